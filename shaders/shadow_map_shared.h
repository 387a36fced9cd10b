// Technique "map": constants and the uniform block shared by its C++
// (src/techniques/Map.cpp) and its GLSL (shadow_map*.glsl/vert/frag).
#ifndef SHADOWLAB_SHADOW_MAP_SHARED_H
#define SHADOWLAB_SHADOW_MAP_SHARED_H

#include "shadowlab_shared.h"

// MAP_FILTER variant values (MapFilter's order).
#define SL_MAP_FILTER_NONE 0
#define SL_MAP_FILTER_HARDWARE 1
#define SL_MAP_FILTER_GRID 2
#define SL_MAP_FILTER_DITHER4 3
#define SL_MAP_FILTER_POISSON 4

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
struct MapUniforms {
#define SL_MAP_VEC4 glm::vec4
#define SL_MAP_MAT4 glm::mat4
#else
layout(std140, binding = SL_BINDING_TECHNIQUE) uniform MapUniforms {
#define SL_MAP_VEC4 vec4
#define SL_MAP_MAT4 mat4
#endif
    SL_MAP_MAT4 lightClipFromWorld; // the light camera (shadow pass)
    SL_MAP_MAT4 shadowFromWorld;    // bias matrix * lightClipFromWorld: map uv in xy, depth in z (after /w)
    SL_MAP_VEC4 params;  // x array layer, y the filter's reach (texels from the centre to its farthest tap), z world size of a texel (spot: per unit of distance along the axis), w 1 perspective / 0 ortho
    SL_MAP_VEC4 bias;    // map depth units: x constant, y times (1 - N.L), z the least of the two (max(y (1 - N.L), z) + x); w normal bias, texels
    SL_MAP_VEC4 taps;    // x one texel in uv (1 / size), y poisson radius (texels), z poisson taps, w dither spread (texels)
    SL_MAP_VEC4 light;   // xyz: spot position or -direction (towards the light), w the light a shadowed point keeps (shadowedLight)
    SL_MAP_VEC4 axis;    // xyz: perspective light camera's unit view direction (texels grow along it), w unused
#ifdef __cplusplus
};
} // namespace shadowlab::shared
#else
} map;
#endif
#undef SL_MAP_VEC4
#undef SL_MAP_MAT4
#endif
