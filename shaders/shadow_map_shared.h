// Technique "map": constants and the uniform block shared by its C++
// (src/techniques/map/) and its GLSL (shadow_map*.glsl/vert/frag).
#ifndef SHADOWLAB_SHADOW_MAP_SHARED_H
#define SHADOWLAB_SHADOW_MAP_SHARED_H

#include "shadowlab_shared.h"

// MAP_FILTER's values, SL_MAP_FILTER_<NAME>, come with the light pass's
// variant (src/techniques/map/options/Filters.cpp: the filters' table).

// MAP_MOMENTS variant values (MapRepresentation's order): 0 a depth map.
#define SL_MAP_MOMENTS_VSM 1
#define SL_MAP_MOMENTS_EVSM2 2
#define SL_MAP_MOMENTS_EVSM4 3
#define SL_MAP_MOMENTS_MSM 4

// Cascaded maps of a directional light, at most.
#define SL_MAP_MAX_CASCADES 8

// The golden angle, radians: the turn between a Vogel disk's taps
// (shadow_map_sampling.glsl; MapSettings: vogelHullInradius).
#define SL_MAP_GOLDEN_ANGLE 2.3999632

// The block: matrices, then vec4 arrays, then each vec3 with a float, then
// floats four at a time, so std140 lays it out as C++ does (a vec3 starts
// on 16 bytes, a float packs after it; map/lookup/Block.cpp checks the offsets).
// Every member has one meaning, in the units it says.
#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
struct MapUniforms {
#define SL_MAP_VEC3 glm::vec3
#define SL_MAP_VEC4 glm::vec4
#define SL_MAP_MAT4 glm::mat4
#else
layout(std140) SL_BINDING(SL_BINDING_TECHNIQUE) uniform MapUniforms {
#define SL_MAP_VEC3 vec3
#define SL_MAP_VEC4 vec4
#define SL_MAP_MAT4 mat4
#endif
    SL_MAP_MAT4 lightClipFromWorld; // the light camera (shadow pass)
    SL_MAP_MAT4 shadowFromWorld;    // bias matrix * lightClipFromWorld: map uv in xy, depth in z (after /w)
    SL_MAP_MAT4 faceClipFromWorld[6]; // cube maps: each face's camera (+X, -X, +Y, -Y, +Z, -Z)
    SL_MAP_MAT4 cascadeShadowFromWorld[SL_MAP_MAX_CASCADES]; // cascades: the bias matrix times each cascade's light camera
    SL_MAP_VEC4 cascadeFar[SL_MAP_MAX_CASCADES / 4];   // cascades: each slice's far end, scene units along the view
    SL_MAP_VEC4 cascadeTexel[SL_MAP_MAX_CASCADES / 4]; // cascades: world size of one texel of each cascade
    SL_MAP_VEC4 cascadeRange[SL_MAP_MAX_CASCADES]; // cascades: x near, y far plane of each cascade's light camera, scene units
    SL_MAP_VEC4 warpPlane;  // warp lispsm: t, the distance from the warp's centre along the view across the light (LightCamera::warpPlane); xyz: the map's y in the world
    SL_MAP_VEC4 warpAcross; // warp lispsm: the map's x in the world (xyz)
    SL_MAP_VEC4 cascadeWarpPlane[SL_MAP_MAX_CASCADES]; // warp lispsm, cascades: each one's warpPlane
    SL_MAP_VEC4 cascadeWarp[SL_MAP_MAX_CASCADES];      // warp lispsm, cascades: each one's warpU (x) and warpV (y)
    SL_MAP_VEC4 cascadeScale[SL_MAP_MAX_CASCADES];     // cascades sharing one light view (MAP_CASCADE_AXES): each one's texture space from the first's, a scale (xyz), w: the cascade's texel along the light view's y, world units ...
    SL_MAP_VEC4 cascadeOffset[SL_MAP_MAX_CASCADES];    // ... and an offset (xyz); w: the cascade's texel along x
    SL_MAP_VEC4 lightTexture;  // a perspective 2D map: the light's own position times shadowFromWorld (w 0), where rays towards it meet
    SL_MAP_VEC3 lightPosition; float shadowedLight; // spot and point lights: world position; the light a shadowed point keeps (share, shadowedLight)
    SL_MAP_VEC3 towardsLight; float reachTexels;    // directional lights: unit vector towards the light; the filter's reach (texels from the centre to its farthest tap)
    SL_MAP_VEC3 lightAxis; float cascadeBlend;      // a perspective light camera's unit view direction (texels grow along it); cascades: the blend share of a slice
    SL_MAP_VEC3 viewForward; float layer;           // cascades: the view's unit forward direction; the light's array layer (a cube's: its index among the cubes)
    float texelWorld;       // world size of a map texel (perspective: per unit of distance along the axis)
    float perspective;      // 1 for a perspective light camera, 0 orthographic
    float constantBias;     // stored depth units, subtracted from the receiver's depth
    float slopeDepthBias;   // stored depth units times (1 - N.L) (preset learnopengl, MAP_PRESET_BIAS) ...
    float minDepthBias;     // ... and the least of it: max(slopeDepthBias (1 - N.L), minDepthBias) + constantBias
    float normalBiasTexels; // the receiver moved along its normal by this many texels times 1 - N.L
    float texelUv;          // one texel in uv (1 / size)
    float poissonRadius;    // poisson: disk radius, texels
    float filterTaps;       // poisson and pcss: taps
    float ditherSpread;     // dither4: the taps' spread, texels
    float cubeFar;          // cube maps: far plane, world units (stored depth = distance / far)
    float cubeSlopeBias;    // cube maps, shadow pass: times the distance's largest change to a neighbouring texel
    float cubeTexelPerDistance; // cube maps: world size of a texel per unit of distance (2 / size)
    float diskRadius;       // cube maps: filter radius at the fragment, world units
    float diskGrowth;       // cube maps: the radius's growth per (viewer distance / far)
    float cubeOffset;       // cube maps, shadow pass: constant offset, stored depth units
    float lightSize;        // pcss: directional, tan of half its angular diameter; spot, point: its radius, scene units
    float nearPlane;        // the light camera's near plane, scene units
    float farPlane;         // and far plane
    float blockerTaps;      // pcss: blocker-search taps
    float blurRadius;       // moment blur pass: radius, texels
    float blurAxis;         // unused (the moment passes' variants say their direction)
    float blurLayer;        // moment blur pass: the layer blurred
    float bleedReduction;   // moment maps: light-bleeding reduction (share of the bound)
    float transmittance;    // 1 when the transmittance layers hold translucent casters (the shaders test MAP_TRANSMIT)
    float kernelRounds;     // grid and pcf20 with MAP_EARLY_OUT: rounds of four taps after the first (a loop bound the compiler cannot unroll)
    float cascadeRounds;    // cascades: 2, the slice's test and the next one's where it fades into it (a loop bound the compiler cannot unroll)
    float blockerHull;      // pcss with MAP_EARLY_OUT: the blocker taps' convex hull's inradius, a share of the search radius
    float warpU;            // warp lispsm: a texel's world size across the view per unit of t (0: no warp; cascades: cascade 0's, > 0 when warped) ...
    float warpV;            // ... and along it per t^2, t = dot(warpPlane.xyz, point) + warpPlane.w
    float atlasTiles;       // atlas: the light's tiles in the shadow atlas (1 a spot's, 6 a point light's; 0 none this frame); `layer` is its first
    float atlasBilinear;    // atlas: 1 for a bilinear compare (filter hardware), 0 the nearest texel
    float blockerNear;      // pcss, spot and point lights: no caster is nearer the light than this, scene units (a spot: along its axis; 0: unknown)
    float padding3, padding4, padding5; // to a whole 16 bytes (std140 rounds the block up)
#ifdef __cplusplus
};
} // namespace shadowlab::shared
#else
} map;
#endif
#undef SL_MAP_VEC3
#undef SL_MAP_VEC4
#undef SL_MAP_MAT4

#ifndef __cplusplus
#if MAP_CUBE_WINDOW
// A cube face's reversed window depth in clip space (MapSettings:
// cubeWindowDepth; 0..w with glClipControl 0..1): n (f - w) / (f - n) for
// w the distance along the face's axis, near 1 and far 0 once divided by
// w. From w itself: the standard matrix's (w - z) / 2 would subtract two
// nearly equal numbers and keep a thousandth of the depth's precision.
float cubeWindowClipZ(float w) { return map.nearPlane * (map.farPlane - w) / (map.farPlane - map.nearPlane); }
#endif
#endif

#ifndef __cplusplus
// d in [0, 1) as four base-255 digits (Ganovelli et al. §8.3.1, Listing 8.2).
// The lecture uses base 256, but an 8-bit UNORM channel stores x as
// round(255 x) / 255, so a digit k / 256 comes back as about k / 255: up to
// 0.4 % of the depth range wrong. With base 255 every digit is an exact
// UNORM step and the four channels give 32 bits of depth.
vec4 packDepth(float d) {
    if (d >= 1.0) return vec4(1.0);
#if defined(MAP_R8) && MAP_R8
    // r8: one byte, rounded up, so a caster never shadows its own surface
    // (Ganovelli et al. exercise 8.6.2-1, variation 2: casters nearer the light
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
float cascadeDepth(vec3 worldPosition) { return dot(worldPosition - frame.cameraPosition.xyz, map.viewForward); }
float cascadeFarOf(int c) { return map.cascadeFar[c >> 2][c & 3]; }
int cascadeOf(float depth) {
    int c = 0;
    while (c < MAP_CASCADES - 1 && depth > cascadeFarOf(c)) ++c;
    return c;
}
float cascadeBlend(float depth, int c) {
    float far = cascadeFarOf(c);
    float band = map.cascadeBlend * (far - (c > 0 ? cascadeFarOf(c - 1) : 0.0));
    return band > 0.0 ? (depth - (far - band)) / band : 0.0;
}
#endif
#endif
#endif
