// Technique "map", moment maps: one direction of the separable Gaussian
// blur (sigma = radius / 2 texels, taps -radius .. radius): across from a
// layer of the moment array into the scratch texture (BLUR_FROM_ARRAY 1),
// then down from the scratch back into the layer (0). Texels past the edge
// repeat the edge.
#include "shadow_map_shared.h"

#if BLUR_FROM_ARRAY
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2DArray blurSource;
vec4 fetch(ivec2 t) { return texelFetch(blurSource, ivec3(t, int(map.blurLayer)), 0); }
ivec2 sourceSize() { return textureSize(blurSource, 0).xy; }
#else
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2D blurSource;
vec4 fetch(ivec2 t) { return texelFetch(blurSource, t, 0); }
ivec2 sourceSize() { return textureSize(blurSource, 0); }
#endif

layout(location = 0) out vec4 outMoments;

void main() {
    int radius = int(map.blurRadius);
    ivec2 step = map.blurAxis < 0.5 ? ivec2(1, 0) : ivec2(0, 1);
    ivec2 centre = ivec2(gl_FragCoord.xy), last = sourceSize() - 1;
    float sigma = max(0.5 * float(radius), 0.5);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int k = -radius; k <= radius; ++k) {
        float w = exp(-0.5 * float(k * k) / (sigma * sigma));
        sum += w * fetch(clamp(centre + k * step, ivec2(0), last));
        weights += w;
    }
    outMoments = sum / weights;
}
