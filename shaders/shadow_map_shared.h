// Technique "map": constants and the uniform block shared by its C++
// (src/techniques/Map.cpp) and its GLSL (shadow_map*.glsl/vert/frag).
#ifndef SHADOWLAB_SHADOW_MAP_SHARED_H
#define SHADOWLAB_SHADOW_MAP_SHARED_H

#include "shadowlab_shared.h"

// MAP_FILTER's values, SL_MAP_FILTER_<NAME>, come with the light pass's
// variant (src/techniques/map/MapFilters.cpp: the filters' table).

// MAP_MOMENTS variant values (MapRepresentation's order): 0 a depth map.
#define SL_MAP_MOMENTS_VSM 1
#define SL_MAP_MOMENTS_EVSM2 2
#define SL_MAP_MOMENTS_EVSM4 3
#define SL_MAP_MOMENTS_MSM 4

// Cascaded maps of a directional light, at most.
#define SL_MAP_MAX_CASCADES 8

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
    SL_MAP_MAT4 faceClipFromWorld[6]; // cube maps: each face's camera (+X, -X, +Y, -Y, +Z, -Z)
    SL_MAP_VEC4 params;  // x array layer, y the filter's reach (texels from the centre to its farthest tap), z world size of a texel (spot: per unit of distance along the axis), w 1 perspective / 0 ortho
    SL_MAP_VEC4 bias;    // map depth units: x constant, y times (1 - N.L), z the least of the two (max(y (1 - N.L), z) + x); w normal bias, texels
    SL_MAP_VEC4 taps;    // x one texel in uv (1 / size), y poisson radius (texels), z poisson taps, w dither spread (texels)
    SL_MAP_VEC4 light;   // xyz: spot position or -direction (towards the light), w the light a shadowed point keeps (shadowedLight)
    SL_MAP_VEC4 axis;    // xyz: perspective light camera's unit view direction (texels grow along it), w unused
    SL_MAP_VEC4 cube;    // cube maps: x far (stored depth = distance / far), y slope bias (shadow pass), z world size of a texel per unit of distance (2 / size), w filter radius (world units)
    SL_MAP_VEC4 cubeMore;// cube maps: x radius growth per (viewer distance / far), y constant offset (stored depth units, shadow pass), z 1 when the bias is the presets' constant only, w unused
    SL_MAP_MAT4 cascadeShadowFromWorld[SL_MAP_MAX_CASCADES]; // cascades: the bias matrix times each cascade's light camera
    SL_MAP_VEC4 cascadeFar[SL_MAP_MAX_CASCADES / 4];   // cascades: each slice's far end, scene units along the view
    SL_MAP_VEC4 cascadeTexel[SL_MAP_MAX_CASCADES / 4]; // cascades: world size of one texel of each cascade
    SL_MAP_VEC4 cascade;  // cascades: xyz the view's forward direction (unit), w the blend share of a slice
    SL_MAP_VEC4 cascadeRange[SL_MAP_MAX_CASCADES]; // cascades: x near, y far plane of each cascade's light camera, scene units
    SL_MAP_VEC4 pcss;     // x the light's size for filter pcss (directional: tan of half its angular diameter; spot, point: its radius, scene units), y near, z far plane of the light camera, w pcss's blocker-search taps
    SL_MAP_VEC4 blur;     // moment maps' blur passes: x radius (texels), y axis (0 across, 1 down), z the layer blurred, w unused
    SL_MAP_VEC4 moments;  // moment maps: x light-bleeding reduction, yzw unused
    SL_MAP_VEC4 transmit; // x 1 when the transmittance layers hold translucent casters (2D maps), yzw unused
#ifdef __cplusplus
};
} // namespace shadowlab::shared
#else
} map;
#endif
#undef SL_MAP_VEC4
#undef SL_MAP_MAT4

#ifndef __cplusplus
// d in [0, 1) as four base-255 digits (lecture 002 §8.3.1, Listing 8.2).
// The lecture uses base 256, but an 8-bit UNORM channel stores x as
// round(255 x) / 255, so a digit k / 256 comes back as about k / 255: up to
// 0.4 % of the depth range wrong. With base 255 every digit is an exact
// UNORM step and the four channels give 32 bits of depth.
vec4 packDepth(float d) {
    if (d >= 1.0) return vec4(1.0);
#if defined(MAP_R8) && MAP_R8
    // r8: one byte, rounded up, so a caster never shadows its own surface
    // (lecture 002 exercise 8.6.2-1, variation 2: casters nearer the light
    // than anything they shadow need no more).
    return vec4(ceil(d * 255.0) / 255.0, 0.0, 0.0, 1.0);
#endif
    const vec4 shift = vec4(1.0, 255.0, 255.0 * 255.0, 255.0 * 255.0 * 255.0);
    const vec4 mask = vec4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
    vec4 res = fract(d * shift);
    res -= res.yzww * mask;
    return res;
}
// Its inverse.
float unpackDepth(vec4 v) {
#if defined(MAP_R8) && MAP_R8
    return v.r;
#else
    return dot(v, vec4(1.0, 1.0 / 255.0, 1.0 / 65025.0, 1.0 / 16581375.0));
#endif
}

// A perspective camera's window depth in [0, 1] as the distance along its
// axis, between its near and far planes n and f.
float perspectiveDistance(float depth, float n, float f) {
    float z = 2.0 * depth - 1.0;
    return 2.0 * n * f / (f + n - z * (f - n));
}

#if defined(MAP_MOMENTS) && MAP_MOMENTS > 0
// The moments a map stores for depth z in [0, 1] (a spot's: linear between
// its near and far planes): VSM (z, z^2); EVSM the warps e^(c+ z') and
// -e^(-c- z') of z' = 2z - 1 with their squares; MSM (z, z^2, z^3, z^4).
vec4 momentsOf(float z) {
#if MAP_MOMENTS == SL_MAP_MOMENTS_VSM
    return vec4(z, z * z, 0.0, 0.0);
#elif MAP_MOMENTS == SL_MAP_MOMENTS_MSM
    float z2 = z * z;
    return vec4(z, z2, z2 * z, z2 * z2);
#else
    float w = 2.0 * z - 1.0;
    float p = exp(MAP_EVSM_POSITIVE * w), n = -exp(-MAP_EVSM_NEGATIVE * w);
    return vec4(p, p * p, n, n * n);
#endif
}
#endif

// Cascades (MAP_CASCADES > 1, defined by every program that includes this
// with the map block): the view depth of a world point, the slice it lies
// in (the first whose far end is beyond it), and how far it is into the
// band at the slice's far end where it fades into the next cascade (0
// before the band, 1 at its end).
#ifdef MAP_CASCADES
float cascadeDepth(vec3 worldPosition) { return dot(worldPosition - frame.cameraPosition.xyz, map.cascade.xyz); }
float cascadeFarOf(int c) { return map.cascadeFar[c >> 2][c & 3]; }
int cascadeOf(float depth) {
    int c = 0;
    while (c < MAP_CASCADES - 1 && depth > cascadeFarOf(c)) ++c;
    return c;
}
float cascadeBlend(float depth, int c) {
    float far = cascadeFarOf(c);
    float band = map.cascade.w * (far - (c > 0 ? cascadeFarOf(c - 1) : 0.0));
    return band > 0.0 ? (depth - (far - band)) / band : 0.0;
}
#endif
#endif
#endif
