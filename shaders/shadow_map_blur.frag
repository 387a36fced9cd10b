// Technique "map", moment maps: the moments made from the depth the shadow
// pass left, in one direction of a separable Gaussian blur (sigma =
// BLUR_RADIUS / 2 texels, taps -BLUR_RADIUS .. BLUR_RADIUS):
//  - BLUR_FROM_DEPTH 1: across, each tap the moments of one depth texel of
//    the layer map.blurLayer (into the scratch texture, or with radius 0
//    straight into the moment layer: no blur);
//  - BLUR_FROM_DEPTH 0: down, from the scratch into the moment layer.
// Texels past the edge repeat the edge. The radius is a define, so the
// weights fold into constants and the loop unrolls.
#include "shadow_map_shared.h"

#if BLUR_FROM_DEPTH
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2DArray blurSource;  // the depth layers (no compare)
vec4 fetch(ivec2 t) {
    float z = clamp(texelFetch(blurSource, ivec3(t, int(map.blurLayer)), 0).r, 0.0, 1.0);
#if MAP_SPOT
    // Perspective depth is far from linear: the moments take the distance
    // along the axis between the near and far planes instead.
    float n = map.nearPlane, f = map.farPlane;
    z = (perspectiveDistance(z, n, f) - n) / (f - n);
#endif
    return momentsOf(z);
}
ivec2 sourceSize() { return textureSize(blurSource, 0).xy; }
const ivec2 kStep = ivec2(1, 0);
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2D blurSource;  // the scratch: moments blurred across
vec4 fetch(ivec2 t) { return texelFetch(blurSource, t, 0); }
ivec2 sourceSize() { return textureSize(blurSource, 0); }
const ivec2 kStep = ivec2(0, 1);
#endif

layout(location = 0) out vec4 outMoments;

void main() {
    ivec2 centre = ivec2(gl_FragCoord.xy);
#if BLUR_RADIUS == 0
    outMoments = fetch(centre);
#else
    ivec2 last = sourceSize() - 1;
    const float sigma = max(0.5 * float(BLUR_RADIUS), 0.5);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int k = -BLUR_RADIUS; k <= BLUR_RADIUS; ++k) {
        float w = exp(-0.5 * float(k * k) / (sigma * sigma));
        sum += w * fetch(clamp(centre + k * kStep, ivec2(0), last));
        weights += w;
    }
    outMoments = sum / weights;
#endif
}
