// Which surface points a light can reach at all: the one definition, shared
// by C++ (the reference ray tracer and compare) and GLSL (lighting.frag), so
// that the boundary cases (exactly on the cone or at the range) agree.
//
// Written in the subset GLSL and C++ share: in C++ it lives in
// shadowlab::shared with glm's vec3, dot and length.
#ifndef SHADOWLAB_LIGHT_REACH_H
#define SHADOWLAB_LIGHT_REACH_H

#include "shadowlab_shared.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
using glm::dot;
using glm::length;
using glm::vec3;
#define SL_INLINE inline
#else
#define SL_INLINE
#endif

// True when point p (world space) lies within the light's reach:
// - directional: everywhere;
// - point: distance to the light <= range (range 0 = unlimited);
// - spot: as point, and strictly inside the outer cone, i.e.
//   dot(axis, p - position) > cosOuter * distance. A point exactly on the
//   cone (or at the light's own position) is out of reach: the smooth
//   falloff of lighting.frag is 0 there too.
// `axis` is the unit direction the light travels; `cosOuter` the cosine of
// the outer half-angle.
SL_INLINE bool slLightReaches(int type, vec3 position, vec3 axis, float range, float cosOuter, vec3 p) {
    if (type == SL_LIGHT_DIRECTIONAL) return true;
    vec3 d = p - position;
    float distance = length(d);
    if (range > 0.0f && distance > range) return false;
    if (type == SL_LIGHT_SPOT) return distance > 0.0f && dot(axis, d) > cosOuter * distance;
    return true;
}

#ifdef __cplusplus
} // namespace shadowlab::shared
#endif
#undef SL_INLINE
#endif
