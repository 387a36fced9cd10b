// Technique "map", fit "sdsm" on the GPU (one map of a directional light,
// no warp): the reduction's blocks (shadow_map_sdsm_reduce.frag) merged
// into one box and the light camera fitted to it here, written where the
// light's map block takes it (MapSdsm: SampleBounds::fitOnGpu; MapBlock
// copies it), so that the CPU never waits for the frame's depth. The same
// steps as core/LightCamera's fitDirectional for visibleSamples (keep the
// two alike): the samples' box and the large meshes' boxes (SDSM_BOXED),
// a relative margin, cut to the casters' footprint over it, padded by the
// filter's footprint, then the orthographic camera and its texel.
#include "shadowlab_shared.h"

layout(local_size_x = 256) in;

// The reduction's lowest and highest corner a block (w = 1: covered).
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2D blockLo;
layout(binding = SL_UNIT_SHADOW_FIRST + 1) uniform sampler2D blockHi;
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
// What MapBlock copies into the block (MapSdsm.h: SdsmFit).
layout(std430, binding = SL_STORAGE_SDSM_FIT) writeonly buffer Fit {
    mat4 clipFromWorld;
    mat4 shadowFromWorld;
    float texelWorld;
    float nearPlane;
    float farPlane;
    float seen;  // 1 when the camera sees a point
    vec4 box;    // the camera's box across the light: left, right, bottom, top (light view)
} fit;

shared vec3 lows[256], highs[256];

void main() {
    // 1. Every block's corners, merged: each invocation its share, then halves.
    uint i = gl_LocalInvocationIndex;
    vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
    int n = blocks.x * blocks.y;
    for (int k = int(i); k < n; k += 256) {
        ivec2 at = ivec2(k % blocks.x, k / blocks.x);
        vec4 a = texelFetch(blockLo, at, 0), b = texelFetch(blockHi, at, 0);
        if (a.w > 0.5) {
            lo = min(lo, a.xyz);
            hi = max(hi, b.xyz);
        }
    }
    lows[i] = lo;
    highs[i] = hi;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (i < stride) {
            lows[i] = min(lows[i], lows[i + stride]);
            highs[i] = max(highs[i], highs[i + stride]);
        }
        barrier();
    }
    if (i != 0u) return;
    lo = lows[0];
    hi = highs[0];
    // 2. The large meshes' boxes (SampleBounds::addBoxed), then the margin
    // for the rounding of points taken back from depth.
    if (all(lessThanEqual(boxedLo, boxedHi))) {
        lo = min(lo, boxedLo);
        hi = max(hi, boxedHi);
    }
    bool seen = all(lessThanEqual(lo, hi));
    if (seen) {
        vec3 margin = vec3(1e-4 * length(hi - lo));
        lo -= margin;
        hi += margin;
    } else {
        // Nothing seen: any small valid box.
        lo = vec3(-1.0, -1.0, -diagonal - 1.0);
        hi = vec3(1.0, 1.0, -diagonal + 1.0);
    }
    // 3. Cut to the casters' footprint over it; the casters over it raise its near side.
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
    // 4. The filter's footprint around it, in texels of the map.
    float extent = max(hi.x - lo.x, hi.y - lo.y);
    float pad = extent * padding / max(size, 1.0);
    lo.xy -= vec2(pad);
    hi.xy += vec2(pad);
    float depthPad = 1e-3 * diagonal;
    float near = -hi.z - depthPad, far = -lo.z + depthPad;
    // glm::ortho(lo.x, hi.x, lo.y, hi.y, near, far), column by column.
    mat4 ortho = mat4(vec4(2.0 / (hi.x - lo.x), 0.0, 0.0, 0.0), vec4(0.0, 2.0 / (hi.y - lo.y), 0.0, 0.0),
                      vec4(0.0, 0.0, -2.0 / (far - near), 0.0),
                      vec4(-(hi.x + lo.x) / (hi.x - lo.x), -(hi.y + lo.y) / (hi.y - lo.y), -(far + near) / (far - near), 1.0));
    mat4 clip = ortho * lightView;
    fit.clipFromWorld = clip;
    // Texture space: the bias matrix (scale and offset by 0.5) times the camera.
    mat4 bias = mat4(vec4(0.5, 0.0, 0.0, 0.0), vec4(0.0, 0.5, 0.0, 0.0), vec4(0.0, 0.0, 0.5, 0.0), vec4(0.5, 0.5, 0.5, 1.0));
    fit.shadowFromWorld = bias * clip;
    fit.texelWorld = max(hi.x - lo.x, hi.y - lo.y) / max(size, 1.0);
    fit.nearPlane = near;
    fit.farPlane = far;
    fit.seen = seen ? 1.0 : 0.0;
    fit.box = vec4(lo.x, hi.x, lo.y, hi.y);
}
