// Technique "map", fit "sdsm" on the GPU (one map of a directional light,
// or with SDSM_SLICE one slice of cascades not stabilised): the
// reduction's blocks merged into one box and the light camera fitted
// to it here, into the light's SdsmFit buffer
// (shadow_map_sdsm_shared.h), which MapBlock copies into the light's
// block, so that the CPU never waits for the frame's depth (MapSdsm:
// SampleBounds::fitOnGpu). The same steps as core/LightCamera's
// fitDirectional for visibleSamples (keep the two alike): the samples' box
// and the large meshes' boxes, a relative margin, cut to the casters'
// footprint over it, padded by the filter's footprint, then the
// orthographic camera and its texel; with SDSM_WARP (warp lispsm, the
// light not along the view) the box warped as warpRegion does. A slice
// (as MapCameras' fitCascades fits one not stabilised: fitCascade) takes the
// samples within its window depths (shadow_map_sdsm_cascades.comp placed
// them) and writes cascade `slice`'s members; cascade 0's are the one
// map's too, as the CPU's p.camera is cascade 0.
#include "shadowlab_shared.h"
#include "shadow_map_sdsm_shared.h"
#include "shadow_map_sdsm_merge.glsl"

layout(local_size_x = 256) in;

layout(location = 0) uniform mat4 lightView;   // directionalLightView: the samples' space
layout(location = 1) uniform ivec2 blocks;
layout(location = 2) uniform vec3 boxedLo;     // the large meshes' boxes cut to the view (lo > hi: none)
layout(location = 3) uniform vec3 boxedHi;
layout(location = 4) uniform float diagonal;   // the scene's diagonal
layout(location = 5) uniform float size;       // map texels per side
layout(location = 6) uniform float padding;    // FitInput::paddingTexels
layout(location = 7) uniform int casterCount;

// The casters that matter (LightCamera::casts), their boxes in the
// camera's view (lightView, or the warp's turned view): lo, hi. A slice's:
// those for the whole view (the slice's own are among them); then the
// large meshes' world boxes (boxedCount of them).
layout(std430) SL_BINDING(SL_STORAGE_SDSM_CASTERS) readonly buffer Casters { vec4 casterBox[]; };

#if SDSM_SLICE
layout(location = 14) uniform int slice;
layout(location = 15) uniform mat4 samplesFromClip;  // the samples' space from the camera's clip space
layout(location = 16) uniform int boxedCount;
layout(location = 17) uniform mat4 samplesView;      // the samples' space from the world (directionalLightView)

// SampleBounds::addBoxed for the slice: the large meshes' boxes, cut to
// the box of the view's frustum between the slice's window depths.
void addBoxed(inout vec3 lo, inout vec3 hi) {
    if (boxedCount == 0) return;
    vec2 z = 2.0 * fit.sliceWindow[slice].zw - 1.0;
    vec3 vlo = vec3(3.0e38), vhi = vec3(-3.0e38);
    for (int c = 0; c < 8; ++c) {
        vec4 w = samplesFromClip * vec4((c & 1) != 0 ? 1.0 : -1.0, (c & 2) != 0 ? 1.0 : -1.0, (c & 4) != 0 ? z.y : z.x, 1.0);
        vlo = min(vlo, w.xyz / w.w);
        vhi = max(vhi, w.xyz / w.w);
    }
    for (int k = 0; k < boxedCount; ++k) {
        vec3 a = casterBox[2 * (casterCount + k)].xyz, b = casterBox[2 * (casterCount + k) + 1].xyz;
        sdsmBoxThrough(samplesView, a, b);
        a = max(a, vlo);
        b = min(b, vhi);
        if (all(lessThanEqual(a, b))) {
            lo = min(lo, a);
            hi = max(hi, b);
        }
    }
}
#endif

// The fitted camera into the one map's members, or the slice's (cascade 0's: both).
void store(mat4 clip, float texel, float near, float far) {
#if SDSM_SLICE
    fit.cascadeClip[slice] = clip;
    fit.cascadeShadowFromWorld[slice] = kSdsmBias * clip;
    fit.cascadeTexel[slice >> 2][slice & 3] = texel;
    fit.cascadeRange[slice] = vec4(near, far, 0.0, 0.0);
    if (slice != 0) return;
#endif
    fit.clipFromWorld = clip;
    fit.shadowFromWorld = kSdsmBias * clip;
    fit.texelWorld = texel;
    fit.nearPlane = near;
    fit.farPlane = far;
}

#if SDSM_WARP
// The warp (core/LightCamera: fitDirectional, warpRegion): lightView is the
// camera's view turned so that the view's direction across the light is
// +y; the samples' box is taken into it; the view's eye and forward direction, the
// warp's nearest distance and the sine of the angle between view and light.
layout(location = 8) uniform mat4 worldFromTurned;  // the inverse of lightView, the turned view
layout(location = 9) uniform mat4 turnedFromSamples;
layout(location = 10) uniform vec3 eye;
layout(location = 11) uniform vec3 forward;
layout(location = 12) uniform float warpNear;
layout(location = 13) uniform float sinGamma;

// warpRegion: the region (turned view space) seen through a perspective
// along +y whose centre lies n below it, n from Wimmer et al.'s n_opt;
// near and far, the unwarped planes (the block's).
void warp(vec3 lo, vec3 hi, float nearPlane, float farPlane) {
    float nearest = warpNear;
#if SDSM_SLICE
    // A slice's warp stands for the slice's own near end at the least.
    nearest = max(nearest, slice == 0 ? fit.firstNear : fit.cascadeFar[(slice - 1) >> 2][(slice - 1) & 3]);
#endif
    float z0 = 3.0e38, z1 = 0.0;
    for (int c = 0; c < 8; ++c) {
        vec3 v = vec3((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y, (c & 4) != 0 ? hi.z : lo.z);
        float distance = dot((worldFromTurned * vec4(v, 1.0)).xyz - eye, forward);
        z0 = min(z0, distance);
        z1 = max(z1, distance);
    }
    z0 = max(z0, nearest);
    z1 = max(z1, z0);
    float depth = max(hi.y - lo.y, 1e-6);
    float n = max((z0 + sqrt(z0 * z1)) / sinGamma, 1e-3 * depth);
    float f = n + depth;
    vec3 centre = vec3(0.5 * (lo.x + hi.x), lo.y - n, 0.5 * (lo.z + hi.z));
    float a = (f + n) / (f - n), b = -2.0 * n * f / (f - n);
    mat4 perspective = mat4(0.0);  // [column][row]
    perspective[0][0] = n;
    perspective[1][1] = a;
    perspective[3][1] = b;
    perspective[2][2] = n;
    perspective[1][3] = 1.0;
    mat4 translate = mat4(1.0);
    translate[3] = vec4(-centre, 1.0);
    mat4 warped = perspective * translate;
    vec3 blo = vec3(3.0e38), bhi = vec3(-3.0e38);
    for (int c = 0; c < 8; ++c) {
        vec4 q = warped * vec4((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y, (c & 4) != 0 ? hi.z : lo.z, 1.0);
        blo = min(blo, q.xyz / q.w);
        bhi = max(bhi, q.xyz / q.w);
    }
    // Pad by the filter's footprint, in texels of the warped map.
    vec2 texel = (bhi.xy - blo.xy) / max(size, 1.0);
    blo.xy -= texel * padding;
    bhi.xy += texel * padding;
    float zPad = 1e-4 * (bhi.z - blo.z) + 1e-12;
    blo.z -= zPad;
    bhi.z += zPad;
    mat4 fitted = mat4(1.0);
    fitted[0][0] = 2.0 / (bhi.x - blo.x);
    fitted[1][1] = 2.0 / (bhi.y - blo.y);
    fitted[2][2] = -2.0 / (bhi.z - blo.z);
    fitted[3] = vec4(-(bhi.x + blo.x) / (bhi.x - blo.x), -(bhi.y + blo.y) / (bhi.y - blo.y), (bhi.z + blo.z) / (bhi.z - blo.z), 1.0);
    float u = texel.x / n, w = texel.y / abs(b);
    store(fitted * warped * lightView, max(u * n, w * n * n), nearPlane, farPlane);
    vec4 rowY = vec4(lightView[0][1], lightView[1][1], lightView[2][1], lightView[3][1]);
    vec4 plane = vec4(rowY.xyz, rowY.w - centre.y);
#if SDSM_SLICE
    fit.cascadeWarpPlane[slice] = plane;
    fit.cascadeWarp[slice] = vec4(u, w, 0.0, 0.0);
    if (slice != 0) return;
#endif
    fit.warpPlane = plane;
    fit.warpU = u;
    fit.warpV = w;
}
#endif

void main() {
#if SDSM_SLICE
    // Nothing seen this frame, fitted before: the frame before's cameras stay
    // (shadow_map_sdsm_cascades.comp kept its slices); the same for every invocation.
    if (fit.seen < 0.5 && fit.keptFar > fit.keptNear) return;
#endif
    vec3 lo, hi;
    mergeBlocks(blocks, lo, hi);
    if (gl_LocalInvocationIndex != 0u) return;
    // The large meshes' boxes (SampleBounds::addBoxed), then the margin.
#if SDSM_SLICE
    addBoxed(lo, hi);
#else
    if (all(lessThanEqual(boxedLo, boxedHi))) {
        lo = min(lo, boxedLo);
        hi = max(hi, boxedHi);
    }
#endif
    bool seen = all(lessThanEqual(lo, hi));
    if (seen) {
        sdsmMargin(lo, hi);
#if SDSM_WARP
        sdsmBoxThrough(turnedFromSamples, lo, hi);  // into the turned view
#endif
    } else {
        // Nothing seen: any small valid box.
        lo = vec3(-1.0, -1.0, -diagonal - 1.0);
        hi = vec3(1.0, 1.0, -diagonal + 1.0);
    }
    // Cut to the casters' footprint over it; the casters over it raise its near side.
    vec3 clo = vec3(3.0e38), chi = vec3(-3.0e38);
    for (int c = 0; c < casterCount; ++c) {
        vec3 a = casterBox[2 * c].xyz, b = casterBox[2 * c + 1].xyz;
        if (any(greaterThan(a, b)) || b.x < lo.x || a.x > hi.x || b.y < lo.y || a.y > hi.y) continue;
        clo = min(clo, a);
        chi = max(chi, b);
    }
    if (all(lessThanEqual(clo, chi))) {
        lo.xy = max(lo.xy, clo.xy);
        hi.xy = min(hi.xy, chi.xy);
        hi.z = max(hi.z, chi.z);
    }
#if !SDSM_SLICE
    fit.seen = seen ? 1.0 : 0.0;
#endif
#if SDSM_WARP
    float warpPad = 1e-3 * diagonal;
    warp(lo, hi, -hi.z - warpPad, -lo.z + warpPad);
    return;
#endif
    // The filter's footprint around it, in texels of the map.
    float extent = max(hi.x - lo.x, hi.y - lo.y);
    float pad = extent * padding / max(size, 1.0);
    lo.xy -= vec2(pad);
    hi.xy += vec2(pad);
    float depthPad = 1e-3 * diagonal;
    float near = -hi.z - depthPad, far = -lo.z + depthPad;
    store(sdsmOrtho(lo.x, hi.x, lo.y, hi.y, near, far) * lightView, max(hi.x - lo.x, hi.y - lo.y) / max(size, 1.0), near, far);
}
