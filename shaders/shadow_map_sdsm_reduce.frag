// Technique "map", fit "sdsm": the bounds, in a directional light's view,
// of the points the camera sees (Lauritzen et al., "Sample Distribution
// Shadow Maps", 2011), reduced by blocks: each fragment of a target
// kBlock x kBlock times smaller than the frame bounds its block of the
// depth pre-pass (MapSdsm), each covered pixel taken from window depth back
// to the world and into the light's view, and writes the block's lowest
// (location 0) and highest (location 1) corner, w = 1 if any pixel was
// covered. (Surfaces that receive no shadow count too: their points only
// widen the bounds.) MapSdsm merges the blocks.
#include "shadowlab_shared.h"
const int kBlock = 4;  // MapSdsm::kBlock

layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2D sdsmDepth;
// Light view from (pixel x, pixel y, window depth, 1): the light's view
// times the camera's inverse projection times the viewport's inverse, one
// matrix (MapSdsm); the light's view is affine, so w divides alone.
layout(location = 0) uniform mat4 lightFromWindow;
layout(location = 2) uniform ivec2 viewport;

layout(location = 0) out vec4 outLo;
layout(location = 1) out vec4 outHi;

void main() {
    ivec2 origin = ivec2(gl_FragCoord.xy) * kBlock;
    vec3 lo = vec3(3.0e38), hi = vec3(-3.0e38);
    float any = 0.0;
    for (int j = 0; j < kBlock; ++j)
        for (int i = 0; i < kBlock; ++i) {
            ivec2 p = min(origin + ivec2(i, j), viewport - 1);
            float d = texelFetch(sdsmDepth, p, 0).r;
            vec4 h = lightFromWindow * vec4(vec2(p) + 0.5, d, 1.0);
            vec3 light = h.xyz / h.w;
            bool covered = d < 1.0;
            lo = covered ? min(lo, light) : lo;
            hi = covered ? max(hi, light) : hi;
            any = covered ? 1.0 : any;
        }
    outLo = vec4(lo, any);
    outHi = vec4(hi, any);
}
