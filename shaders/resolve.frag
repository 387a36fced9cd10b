// Resolve: linear radiance -> 8-bit sRGB (IEC 61966-2-1 transfer function),
// clamped to [0,1]. Tone mapping, when it comes, goes here.
#include "shadowlab_shared.h"

in vec2 vUv;
layout(binding = SL_UNIT_RESOLVE_INPUT) uniform sampler2D radiance;
out vec4 outColor;

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    outColor = vec4(linearToSrgb(texelFetch(radiance, ivec2(gl_FragCoord.xy), 0).rgb), 1.0);
}
