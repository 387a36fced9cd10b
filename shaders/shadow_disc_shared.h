// Technique "disc": the uniform block shared by its C++ (src/techniques/
// Disc.cpp) and its GLSL (shadow_disc.glsl).
#ifndef SHADOWLAB_SHADOW_DISC_SHARED_H
#define SHADOWLAB_SHADOW_DISC_SHARED_H

#include "shadowlab_shared.h"

// Discs one light's pass tests against.
#define SL_DISC_MAX 64

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
struct DiscUniforms {
#define SL_DISC_VEC4 glm::vec4
#else
layout(std140) SL_BINDING(SL_BINDING_TECHNIQUE) uniform DiscUniforms {
#define SL_DISC_VEC4 vec4
#endif
    // Disc k: centre c (xyz) and its two semi-axes a, b (xyz, world units,
    // perpendicular): the points c + s a + t b with s^2 + t^2 <= 1.
    SL_DISC_VEC4 centre[SL_DISC_MAX];
    SL_DISC_VEC4 axisA[SL_DISC_MAX];
    SL_DISC_VEC4 axisB[SL_DISC_MAX];
    SL_DISC_VEC4 light;   // xyz the light's position (w = 1) or the direction towards it (w = 0)
    SL_DISC_VEC4 params;  // y the shortest ray length that counts (scene units); x, z, w unused (the disc count is the variant's DISC_COUNT)
#ifdef __cplusplus
};
} // namespace shadowlab::shared
#else
} disc;
#endif
#undef SL_DISC_VEC4
#endif
