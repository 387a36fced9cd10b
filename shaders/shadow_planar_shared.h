// Technique "planar": the uniform block shared by its C++ (src/techniques/
// Planar.cpp) and its GLSL (shadow_planar_project.*).
#ifndef SHADOWLAB_SHADOW_PLANAR_SHARED_H
#define SHADOWLAB_SHADOW_PLANAR_SHARED_H

#include "shadowlab_shared.h"

// Receiver planes one draw may project onto.
#define SL_PLANAR_MAX_PLANES 16

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
struct PlanarUniforms {
#define SL_PLANAR_VEC4 glm::vec4
#define SL_PLANAR_MAT4 glm::mat4
#else
layout(std140) SL_BINDING(SL_BINDING_TECHNIQUE) uniform PlanarUniforms {
#define SL_PLANAR_VEC4 vec4
#define SL_PLANAR_MAT4 mat4
#endif
    // The plane projection matrix (Wolberg's lecture): (n.L) I - L n^T, with L the
    // light (position, w = 1; or the direction towards it, w = 0) and n the
    // plane (a, b, c, d) turned so that n.L > 0.
    SL_PLANAR_MAT4 shadowFromWorld[SL_PLANAR_MAX_PLANES];
    SL_PLANAR_VEC4 plane[SL_PLANAR_MAX_PLANES]; // n, oriented towards the light
    SL_PLANAR_VEC4 params;                      // x planes in this draw, y darkness (style lecture), zw unused
#ifdef __cplusplus
};
} // namespace shadowlab::shared
#else
} planar;
#endif
#undef SL_PLANAR_VEC4
#undef SL_PLANAR_MAT4
#endif
