// Technique "map", fit "sdsm" on the GPU: the buffer its compute passes
// fit a light's cameras into (shadow_map_sdsm_fit.comp: one map, or with
// SDSM_SLICE a slice of cascades not stabilised;
// shadow_map_sdsm_cascades.comp: the cascades' splits, and stabilised
// ones' cameras), one per light, kept
// from frame to frame, and copied on the GPU over the cameras' members of
// the light's block (MapBlock). Shared by the C++ (map/fit/Sdsm.h: SdsmFit) and
// the GLSL (std430 at SL_STORAGE_SDSM_FIT); matrices, then vec4s, then
// floats four at a time, so that both lay it out alike.
#ifndef SHADOWLAB_SHADOW_MAP_SDSM_SHARED_H
#define SHADOWLAB_SHADOW_MAP_SDSM_SHARED_H

#include "shadow_map_shared.h"

#define SL_STORAGE_SDSM_CASTERS SL_STORAGE_TECHNIQUE_FIRST      // the casters' boxes in the light's view (shadow_map_sdsm_fit.comp)
#define SL_STORAGE_SDSM_FIT (SL_STORAGE_TECHNIQUE_FIRST + 1)    // and the camera it fits (SdsmFit, below)

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
struct SdsmFit {
#define SL_SDSM_VEC4 glm::vec4
#define SL_SDSM_MAT4 glm::mat4
#else
layout(std430) SL_BINDING(SL_STORAGE_SDSM_FIT) buffer SdsmFit {
#define SL_SDSM_VEC4 vec4
#define SL_SDSM_MAT4 mat4
#endif
    SL_SDSM_MAT4 clipFromWorld;   // the one map's camera, or cascade 0's (the block's lightClipFromWorld) ...
    SL_SDSM_MAT4 shadowFromWorld; // ... and the bias matrix times it (shadowFromWorld)
    SL_SDSM_MAT4 cascadeClip[SL_MAP_MAX_CASCADES]; // cascades: each one's camera (the shadow pass's, per layer)
    // Cascades: these four as the block has them, in its order (one copy).
    SL_SDSM_MAT4 cascadeShadowFromWorld[SL_MAP_MAX_CASCADES];
    SL_SDSM_VEC4 cascadeFar[SL_MAP_MAX_CASCADES / 4];
    SL_SDSM_VEC4 cascadeTexel[SL_MAP_MAX_CASCADES / 4];
    SL_SDSM_VEC4 cascadeRange[SL_MAP_MAX_CASCADES];
    SL_SDSM_VEC4 warpPlane;  // one map, warp lispsm: the block's warpPlane
    // Warped cascades: these two as the block has them (one copy).
    SL_SDSM_VEC4 cascadeWarpPlane[SL_MAP_MAX_CASCADES];
    SL_SDSM_VEC4 cascadeWarp[SL_MAP_MAX_CASCADES];
    // Cascades not stabilised: the window depths whose pixels count for
    // each slice's samples (x, y: a step of the depth buffer wider each way;
    // z, w: not widened, where the large meshes' boxes are cut).
    SL_SDSM_VEC4 sliceWindow[SL_MAP_MAX_CASCADES];
    float texelWorld;  // the one map's texel, or cascade 0's (the block's texelWorld) ...
    float nearPlane;   // ... and its near and far planes
    float farPlane;
    float seen;        // 1 when the camera saw a point this frame
    float keptNear;    // cascades: the view depths the slices split (stabilised: kept while
    float keptFar;     //   the depths seen stay within them; 0, 0: none seen yet)
    float firstNear;   // cascades: where the first slice starts along the view
    float seenFar;     // cascades: where the last slice ends, the farthest depth seen as kept (read back a frame late: GpuFit)
    float warpU;       // one map, warp lispsm: the block's warpU ...
    float warpV;       // ... and warpV
    float padding1, padding2;
#ifdef __cplusplus
};
} // namespace shadowlab::shared
#else
} fit;
#endif
#undef SL_SDSM_VEC4
#undef SL_SDSM_MAT4

#endif
