// Constants and uniform-block layouts shared by C++ and GLSL: the one place
// they are written. Included by src/render/*.cpp and by the shaders.
// Blocks use std140 with vec4/mat4 members only, so the C++ structs (glm)
// have the same layout without padding rules to remember.
#ifndef SHADOWLAB_SHARED_H
#define SHADOWLAB_SHARED_H

// Light types (LightUniforms.params.w and the LIGHT_TYPE variant define).
#define SL_LIGHT_DIRECTIONAL 0
#define SL_LIGHT_SPOT 1
#define SL_LIGHT_POINT 2

// Uniform-block binding points.
#define SL_BINDING_FRAME 0
#define SL_BINDING_LIGHT 1
#define SL_BINDING_DRAW 2
#define SL_BINDING_TECHNIQUE 3     // a technique's own block (light-space matrices, bias, ...)

// Shader-storage binding points (their own namespace): the clustered light
// list of the pass that shades many lights at once (lighting.frag's
// LIGHT_LIST variant, src/render/LightList.cpp).
#define SL_STORAGE_LIGHT_LIST 0    // ListedLight[]: each light's terms, as LightUniforms without the projector
#define SL_STORAGE_LIGHT_TILES 1   // uvec4 (tile size px, tiles across, tiles down, slices), vec4 (slices' near, scale), then per cluster (first, count), then light indices
#define SL_LIGHT_TILE_SIZE 16      // pixels per side of a tile
#define SL_LIGHT_SLICES 32         // depth slices a tile (geometry/LightTiles.h)
#define SL_STORAGE_LIST_SHADOW 2   // the light list's shadow lookup's own buffer (its technique's: map's atlas tiles, shadow_atlas_shared.h)
#define SL_STORAGE_TECHNIQUE_FIRST 3  // storage a technique's own passes use, from here up (map's fit sdsm: shadow_map_sdsm_shared.h)

// Texture units.
#define SL_UNIT_BASE_COLOR 0
#define SL_UNIT_SCREEN_VISIBILITY 2   // per-pixel visibility from the ray-traced reference (R32F)
#define SL_UNIT_PROJECTOR 3           // a spot light's projected image (slide projector)
#define SL_UNIT_SHADOW_FIRST 4        // units a technique's textures use, from here up

// Colour attachments of the frame's framebuffer.
#define SL_TARGET_COLOR 0     // radiance, SRGB8_ALPHA8 (linear values, encoded on write)
#define SL_TARGET_POSITION 1  // only when surfaces are asked for: world position xyz, w = 1 on geometry (RGBA32F)
#define SL_TARGET_NORMAL 2    // only when surfaces are asked for: geometric normal facing the camera, w = receives shadows (RGBA16F)

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
#define SL_VEC4 glm::vec4
#define SL_MAT4 glm::mat4
#define SL_BLOCK(name, bindingPoint, instance) struct name
#define SL_END_BLOCK(instance) ;
#else
#define SL_VEC4 vec4
#define SL_MAT4 mat4
#define SL_BLOCK(name, bindingPoint, instance) layout(std140) SL_BINDING(bindingPoint) uniform name
#define SL_END_BLOCK(instance) instance;
#endif

SL_BLOCK(FrameUniforms, SL_BINDING_FRAME, frame) {
    SL_MAT4 clipFromWorld;
    SL_VEC4 cameraPosition;   // world space, w unused
    SL_VEC4 ambient;          // global ambient, linear RGB
} SL_END_BLOCK(frame)

SL_BLOCK(LightUniforms, SL_BINDING_LIGHT, light) {
    SL_VEC4 radiance;         // colour * intensity, linear RGB
    SL_VEC4 position;         // world space (spot, point)
    SL_VEC4 direction;        // world space unit vector the light travels (directional, spot)
    SL_VEC4 params;           // x range (0 = unlimited), y cos(inner), z cos(outer), w type
    SL_MAT4 projectorFromWorld; // spot with a projected image: world -> the image's clip space (HAS_PROJECTOR)
} SL_END_BLOCK(light)

// One light of the clustered light list (std430; vec4 members only): a
// LightUniforms without the projector, and its shadow in the atlas.
struct ListedLight {
    SL_VEC4 radiance;
    SL_VEC4 position;
    SL_VEC4 direction;
    SL_VEC4 params;
    SL_VEC4 shadow;  // the light's shadow as its technique's list lookup reads it (Technique::listedShadow; y 0: none)
};

SL_BLOCK(DrawUniforms, SL_BINDING_DRAW, draw) {
    SL_MAT4 worldFromObject;
    SL_MAT4 normalFromObject; // inverse transpose of worldFromObject's 3x3
    SL_VEC4 baseColor;        // rgb, w = receives shadows (1/0)
    SL_VEC4 ambient;          // rgb
    SL_VEC4 diffuse;          // rgb
    SL_VEC4 specular;         // rgb, w = shininess
    SL_VEC4 alpha;            // x the base colour's alpha factor, y cutoff, z the AlphaMode (0 opaque, 1 mask, 2 blend), w 1 with a base-colour texture
} SL_END_BLOCK(draw)

#ifdef __cplusplus
} // namespace shadowlab::shared
#endif
#undef SL_BLOCK
#undef SL_END_BLOCK
#endif
