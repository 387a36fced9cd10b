// Technique "map", fit "sdsm": the bounds, in a directional light's view,
// of the points the camera sees (Lauritzen et al., "Sample Distribution
// Shadow Maps", 2011), reduced by blocks: each fragment of a target
// kBlock x kBlock times smaller than the frame bounds its block of the
// depth pre-pass (MapSdsm): for each depth window, the covered pixels'
// depth range within it, its box in window space taken back to the world
// and into the light's view, and writes the block's lowest and highest
// corner, w = 1 if any pixel within the window was covered. (Surfaces
// that receive no shadow count too: their points only widen the bounds.)
// MapSdsm merges the blocks.
#include "shadowlab_shared.h"
const int kBlock = 8;  // MapSdsm::kBlock

SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2D sdsmDepth;
// Light view from (pixel x, pixel y, window depth, 1): the light's view
// times the camera's inverse projection times the viewport's inverse, one
// matrix (MapSdsm); the light's view is affine, so w divides alone.
layout(location = 0) uniform mat4 lightFromWindow;
layout(location = 2) uniform ivec2 viewport;
// SDSM_WINDOWS (1, or MapSdsm::kSlicesAPass): the window depths whose
// pixels count, [lo, hi], each its own bounds: one slice of cascades each
// (its distances along the view as window depths, from the fit's buffer
// with SDSM_WINDOWS_FROM_FIT), else [0, 1) (uncovered pixels, at depth 1,
// never count); lo > hi: none.
#if SDSM_WINDOWS_FROM_FIT
// Cascades not stabilised: the windows the GPU placed
// (shadow_map_sdsm_cascades.comp: sliceWindow), slices firstSlice on, of sliceCount.
#include "shadow_map_sdsm_shared.h"
layout(location = 3) uniform int firstSlice;
layout(location = 4) uniform int sliceCount;
vec2 windowOf(int w) { return firstSlice + w < sliceCount ? fit.sliceWindow[firstSlice + w].xy : vec2(1.0, 0.0); }
#else
layout(location = 3) uniform vec2 depthWindow[SDSM_WINDOWS];
vec2 windowOf(int w) { return depthWindow[w]; }
#endif

// Window w's lowest corner at location 2w, its highest at 2w + 1.
layout(location = 0) out vec4 outBounds[2 * SDSM_WINDOWS];

void main() {
    // Each window's nearest and farthest window depth in the block (four
    // gathers of 2x2 texels; clamped at the frame's edge), then the
    // light-view box of the eight corners of its window-space box: the map
    // from window to light is projective, so the box of those corners holds
    // every point of the block within the window (a little more, where the
    // block's depths differ).
    ivec2 origin = ivec2(gl_FragCoord.xy) * kBlock;
    vec2 texel = 1.0 / vec2(viewport);
    float dmin[SDSM_WINDOWS], dmax[SDSM_WINDOWS];
    vec2 window[SDSM_WINDOWS];
    for (int w = 0; w < SDSM_WINDOWS; ++w) {
        window[w] = windowOf(w);
        dmin[w] = 1.0;
        dmax[w] = 0.0;
    }
    for (int j = 0; j < kBlock; j += 2)
        for (int i = 0; i < kBlock; i += 2) {
            vec4 d = textureGather(sdsmDepth, (vec2(origin + ivec2(i, j)) + 1.0) * texel, 0);
            for (int w = 0; w < SDSM_WINDOWS; ++w) {
                // Pixels outside the window (uncovered ones at depth 1
                // among them) count for neither end.
                vec4 inside = step(vec4(window[w].x), d) * step(d, vec4(window[w].y));
                vec4 near = mix(vec4(1.0), d, inside);
                dmin[w] = min(dmin[w], min(min(near.x, near.y), min(near.z, near.w)));
                vec4 far = d * inside;
                dmax[w] = max(dmax[w], max(max(far.x, far.y), max(far.z, far.w)));
            }
        }
    vec2 first = vec2(origin) + 0.5, last = min(vec2(origin + (kBlock - 1)), vec2(viewport - 1)) + 0.5;
    for (int w = 0; w < SDSM_WINDOWS; ++w) {
        if (dmin[w] >= 1.0) {
            outBounds[2 * w] = vec4(0.0);
            outBounds[2 * w + 1] = vec4(0.0);
            continue;
        }
        vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
        for (int c = 0; c < 8; ++c) {
            vec3 p = vec3((c & 1) != 0 ? last.x : first.x, (c & 2) != 0 ? last.y : first.y, (c & 4) != 0 ? dmax[w] : dmin[w]);
            vec4 h = lightFromWindow * vec4(p, 1.0);
            vec3 light = h.xyz / h.w;
            lo = min(lo, light);
            hi = max(hi, light);
        }
        outBounds[2 * w] = vec4(lo, 1.0);
        outBounds[2 * w + 1] = vec4(hi, 1.0);
    }
}
