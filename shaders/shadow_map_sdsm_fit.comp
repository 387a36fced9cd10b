// Technique "map", fit "sdsm" on the GPU (one map of a directional light,
// no warp): the reduction's blocks merged into one box and the light
// camera fitted to it here, into the light's SdsmFit buffer
// (shadow_map_sdsm_shared.h), which MapBlock copies into the light's
// block, so that the CPU never waits for the frame's depth (MapSdsm:
// SampleBounds::fitOnGpu). The same steps as core/LightCamera's
// fitDirectional for visibleSamples (keep the two alike): the samples' box
// and the large meshes' boxes, a relative margin, cut to the casters'
// footprint over it, padded by the filter's footprint, then the
// orthographic camera and its texel.
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

// The casters that matter (LightCamera::casts), their boxes in lightView: lo, hi.
layout(std430, binding = SL_STORAGE_SDSM_CASTERS) readonly buffer Casters { vec4 casterBox[]; };

void main() {
    vec3 lo, hi;
    mergeBlocks(blocks, lo, hi);
    if (gl_LocalInvocationIndex != 0u) return;
    // The large meshes' boxes (SampleBounds::addBoxed), then the margin.
    if (all(lessThanEqual(boxedLo, boxedHi))) {
        lo = min(lo, boxedLo);
        hi = max(hi, boxedHi);
    }
    bool seen = all(lessThanEqual(lo, hi));
    if (seen) {
        sdsmMargin(lo, hi);
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
    // The filter's footprint around it, in texels of the map.
    float extent = max(hi.x - lo.x, hi.y - lo.y);
    float pad = extent * padding / max(size, 1.0);
    lo.xy -= vec2(pad);
    hi.xy += vec2(pad);
    float depthPad = 1e-3 * diagonal;
    float near = -hi.z - depthPad, far = -lo.z + depthPad;
    mat4 clip = sdsmOrtho(lo.x, hi.x, lo.y, hi.y, near, far) * lightView;
    fit.clipFromWorld = clip;
    fit.shadowFromWorld = kSdsmBias * clip;
    fit.texelWorld = max(hi.x - lo.x, hi.y - lo.y) / max(size, 1.0);
    fit.nearPlane = near;
    fit.farPlane = far;
    fit.seen = seen ? 1.0 : 0.0;
}
