// Technique "map", fit "sdsm" on the GPU for cascades: the view depths
// the camera sees, merged from the reduction's blocks (in the view's own
// space, whose z is minus the distance along the view), and the slices
// split over them here, into the light's SdsmFit buffer
// (shadow_map_sdsm_shared.h), which MapBlock copies into the block (MapSdsm:
// SampleBounds::fitOnGpu). The same steps as MapCameras' fitCascades and
// core/LightCamera's cascadeSplits and fitCascade take for the receivers'
// reach (keep them alike): the slices split by cascadeLambda (or
// cascadeSplits) from the camera's near plane to the farthest depth seen,
// the first starting at the nearest. (Placed from the nearest depth seen,
// the logarithmic scheme's splits all moved out with it, and the near
// slices, where a texel covers the most pixels, got fewer texels a metre
// than the tight fit's: docs/techniques/fits.md.)
// SDSM_STABILIZE 1: the depths kept in whole steps of 2^(1/4), and each
// slice's camera fitted here: its bounding sphere, its box snapped to
// whole texels, and its depth range the scene's cut to what the slice's
// lookups reach. Nothing seen: the cameras of the frame before are kept
// (never fitted yet: the slices over the whole reach).
// SDSM_STABILIZE 0: the slices' window depths (sliceWindow), whose pixels a
// second reduction bounds a slice each, and shadow_map_sdsm_fit.comp
// (SDSM_SLICE) fits each slice's camera to its own samples. Nothing seen:
// the frame before's slices are kept (never fitted yet: over the view's reach).
#include "shadowlab_shared.h"
#include "shadow_map_sdsm_shared.h"
#include "shadow_map_sdsm_merge.glsl"

layout(local_size_x = 256) in;

layout(location = 0) uniform mat4 lightView;   // directionalLightView: fixed while the scene is
layout(location = 1) uniform ivec2 blocks;
layout(location = 2) uniform vec3 boxedLo;     // the large meshes' boxes cut to the view, in view space (lo > hi: none)
layout(location = 3) uniform vec3 boxedHi;
layout(location = 4) uniform float diagonal;   // the scene's diagonal
layout(location = 5) uniform float size;       // map texels per side
layout(location = 6) uniform float padding;    // FitInput::paddingTexels
layout(location = 7) uniform int count;        // cascades
layout(location = 8) uniform vec4 camera;      // near plane, far plane, tan(fovY / 2), aspect (width / height)
layout(location = 9) uniform vec3 eye;
layout(location = 10) uniform vec3 forward;    // unit, towards the target
layout(location = 11) uniform vec3 right;      // unit, the view's x
layout(location = 12) uniform vec3 up;         // unit, the view's y
layout(location = 13) uniform float reach;     // where slices end at the farthest (MapCameras: stableReach, or viewReach when not stabilised)
layout(location = 14) uniform float lambda;    // cascadeLambda
layout(location = 15) uniform vec3 sceneLo;    // the scene's box, world space
layout(location = 16) uniform vec3 sceneHi;
layout(location = 17) uniform float given[SL_MAP_MAX_CASCADES - 1];  // cascadeSplits, when givenCount = count - 1
layout(location = 24) uniform int givenCount;
// The far end the slices are split over is clamped to this range: the
// seen far end of a frame before (GpuFit), which the CPU culled the
// casters for, both ends; (0, 3e38) before one is known. The last slice
// still ends at this frame's far end (or past it): only where the other
// slices split follows a frame late.
layout(location = 25) uniform vec2 splitRange;
#if !SDSM_STABILIZE
layout(location = 26) uniform mat4 clipFromView;  // the camera's projection
layout(location = 27) uniform float blend;        // cascadeBlend

// The window depth (0..1) of a point `distance` along the view's axis (map/fit/Sdsm.cpp: windowDepthAt).
float windowDepthAt(float distance) {
    vec4 clip = clipFromView * vec4(0.0, 0.0, -distance, 1.0);
    return 0.5 * clip.z / clip.w + 0.5;
}
#endif
// Stabilised: the receivers' box in lightView (core/LightCamera:
// receiversWindow): half widths, stepped (xy), and centre (zw); the window
// on an axis where it is narrower than a slice's sphere, as fitCascade's.
layout(location = 28) uniform vec4 receiversWindow;

// The view depths seen, [near, far] along the view, within the camera's
// planes. Stabilised: in whole steps of 2^(1/4) with headroom (near two
// steps below the nearest, far one past the farthest), kept from frame to
// frame while the depths seen stay inside and it is at most four steps
// too wide at the near end and three at the far: the splits stay put as
// the camera moves (each change moves every slice's texel grid: a frame of
// flips), and follow a view that changes.
vec2 sampledRange(vec2 seen, vec2 kept) {
    float near = max(seen.x, camera.x), far = min(seen.y, camera.y);
#if SDSM_STABILIZE
    float stepUp = exp2(0.25);
    if (kept.y > kept.x && kept.x <= near && far <= kept.y && near <= kept.x * pow(stepUp, 4.0) && kept.y <= far * pow(stepUp, 3.0)) return kept;
    near = exp2((floor(4.0 * log2(near)) - 2.0) / 4.0);
    far = exp2((ceil(4.0 * log2(far)) + 1.0) / 4.0);
#endif
    near = max(near, camera.x);
    far = clamp(far, near * 1.01, camera.y);
    return vec2(near, far);
}

// The corners of the view's frustum between distances n and f along it: their box, world space.
void frustumBox(float n, float f, out vec3 lo, out vec3 hi) {
    lo = vec3(3.0e38);
    hi = vec3(-3.0e38);
    for (int c = 0; c < 8; ++c) {
        float d = (c & 4) != 0 ? f : n;
        vec3 p = eye + forward * d + right * (((c & 1) != 0 ? 1.0 : -1.0) * d * camera.z * camera.w) + up * (((c & 2) != 0 ? 1.0 : -1.0) * d * camera.z);
        lo = min(lo, p);
        hi = max(hi, p);
    }
}

// cascadeSplits (geometry/Cascades.cpp) over the split range's far end:
// increasing, each slice at least 10^-5 of the range; the last ends at
// the farther of far and the split range's far end.
void placeSplits(float near, float far, out float ends[SL_MAP_MAX_CASCADES]) {
    float splitFar = clamp(far, splitRange.x, splitRange.y);
    float range = 1e-5 * (splitFar - near);
    for (int i = 1; i < count; ++i) {
        float t = float(i) / float(count);
        float scheme = lambda * near * pow(splitFar / near, t) + (1.0 - lambda) * (near + (splitFar - near) * t);
        float split = givenCount == count - 1 ? given[i - 1] : scheme;
        float lowest = (i == 1 ? near : ends[i - 2]) + range;
        ends[i - 1] = clamp(split, lowest, max(lowest, splitFar - range * float(count - i)));
    }
    ends[count - 1] = max(far, splitFar);
}

#if !SDSM_STABILIZE
// Each slice's far end, and the window depths whose pixels its samples
// count: from its near end, or for a slice after the first from where
// the slice before fades into it over its far blend share
// (MapCameras: sliceDistances), each way a step of the 24-bit depth
// wider (a pixel on a split counts for both; map/fit/Sdsm.cpp: depthWindow).
void sliceWindows(float first, float ends[SL_MAP_MAX_CASCADES]) {
    const float depthStep = 1.0 / 16777215.0, below1 = 0.99999994;
    for (int c = 0; c < count; ++c) {
        fit.cascadeFar[c >> 2][c & 3] = ends[c];
        float before = c > 0 ? ends[c - 1] : first, start = c > 1 ? ends[c - 2] : 0.0;
        float from = c == 0 ? first : max(before - blend * (before - start), first);
        vec2 window = vec2(windowDepthAt(from), windowDepthAt(ends[c]));
        fit.sliceWindow[c] = vec4(max(window.x - depthStep, 0.0), min(window.y + depthStep, below1), window);
    }
}
#endif

// Stabilised slice c over view depths [n, f], its lookups reading from
// readFrom: its bounding sphere's box (or the receivers' window where that
// is narrower), snapped to whole texels, its depth the scene's along the
// light cut to what its lookups reach (fitCascade, geometry/Cascades.cpp).
void fitStabilisedSlice(int c, float n, float f, float readFrom, float k2, vec3 sceneLight, vec3 sceneLightHi) {
    // The slice's bounding sphere, radius up to 1/64 of a unit.
    float along = min(0.5 * (f + n) * (1.0 + k2), f);
    float radius = sqrt((f - along) * (f - along) + k2 * f * f);
    radius = ceil(radius * 64.0) / 64.0;
    vec3 sphere = (lightView * vec4(eye + forward * along, 1.0)).xyz;
    float half_ = radius * size / max(size - 2.0 * padding, 1.0);
    vec2 halves = vec2(half_), centre = sphere.xy;
    for (int a = 0; a < 2; ++a)
        if (receiversWindow[a] > 0.0 && receiversWindow[a] < half_) {
            halves[a] = receiversWindow[a];
            centre[a] = receiversWindow[a + 2];
        }
    vec2 texels = 2.0 * halves / size;
    float texel = max(texels.x, texels.y);
    vec2 snapped = floor(centre / texels + 0.5) * texels;
    // Depth: the scene's along the light, cut to what the slice's lookups reach, in steps of 1/32 of the box.
    float from = readFrom > 0.0 ? min(readFrom, n) : n;
    vec3 wlo, whi;
    frustumBox(from, f, wlo, whi);
    wlo = max(wlo, sceneLo);
    whi = min(whi, sceneHi);
    vec3 dlo = sceneLight, dhi = sceneLightHi;
    float depthStep = 0.0625 * half_;
    if (all(lessThanEqual(wlo, whi)) && depthStep > 0.0) {
        sdsmBoxThrough(lightView, wlo, whi);
        dlo.z = max(dlo.z, floor(wlo.z / depthStep) * depthStep);
        dhi.z = min(dhi.z, ceil(whi.z / depthStep) * depthStep);
    }
    float depthPad = 1e-3 * diagonal;
    float nearPlane = -dhi.z - depthPad, farPlane = -dlo.z + depthPad;
    mat4 clip = sdsmOrtho(snapped.x - halves.x, snapped.x + halves.x, snapped.y - halves.y, snapped.y + halves.y, nearPlane, farPlane) * lightView;
    fit.cascadeClip[c] = clip;
    fit.cascadeShadowFromWorld[c] = kSdsmBias * clip;
    fit.cascadeFar[c >> 2][c & 3] = f;
    fit.cascadeTexel[c >> 2][c & 3] = texel;
    fit.cascadeRange[c] = vec4(nearPlane, farPlane, 0.0, 0.0);
    if (c == 0) {
        fit.clipFromWorld = clip;
        fit.shadowFromWorld = kSdsmBias * clip;
        fit.texelWorld = texel;
        fit.nearPlane = nearPlane;
        fit.farPlane = farPlane;
    }
}

void main() {
    vec3 lo, hi;
    mergeBlocks(blocks, lo, hi);
    if (gl_LocalInvocationIndex != 0u) return;
    if (all(lessThanEqual(boxedLo, boxedHi))) {
        lo = min(lo, boxedLo);
        hi = max(hi, boxedHi);
    }
    bool seen = all(lessThanEqual(lo, hi));
    fit.seen = seen ? 1.0 : 0.0;
    vec2 kept = vec2(fit.keptNear, fit.keptFar);
    if (!seen && kept.y > kept.x) return;  // the frame before's cameras stay
    float near = camera.x, far = reach, first = near;
    if (seen) {
        sdsmMargin(lo, hi);
        // The slices end at the farthest depth seen (never past the reach) and
        // the first starts at the nearest; the splits are placed from the near plane.
        vec2 sampled = sampledRange(vec2(-hi.z, -lo.z), kept);
        fit.keptNear = sampled.x;
        fit.keptFar = sampled.y;
        far = max(min(far, sampled.y), near * 1.01);
        first = sampled.x;
    }
    fit.seenFar = far;
    float ends[SL_MAP_MAX_CASCADES];
    placeSplits(near, far, ends);
    if (!(first < ends[0])) first = near;  // nothing seen before the first split: the slice as the tight fit's
    fit.firstNear = first;
#if !SDSM_STABILIZE
    sliceWindows(first, ends);
    return;
#endif
    float k2 = (1.0 + camera.w * camera.w) * camera.z * camera.z;
    vec3 sceneLight = sceneLo, sceneLightHi = sceneHi;
    sdsmBoxThrough(lightView, sceneLight, sceneLightHi);
    for (int c = 0; c < count; ++c) {
        float n = c == 0 ? first : ends[c - 1], f = ends[c];
        float readFrom = c < 2 ? first : ends[c - 2];
        fitStabilisedSlice(c, n, f, readFrom, k2, sceneLight, sceneLightHi);
    }
}
