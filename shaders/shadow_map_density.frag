// Technique "map", debug view: shadow-map texels per screen pixel at each
// visible point, as a colour. Green: about one texel per pixel; towards red:
// one texel covers many pixels (blocky edges, 1/16 at full red); towards
// blue: many texels fall into one pixel (resolution spent for nothing, 16 at
// full blue); grey: outside the map (lit). With cascades (MAP_CASCADES > 1)
// the point's own cascade.
#include "shadow_map_shared.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;
layout(location = 0) out vec4 outColor;

void main() {
#if MAP_CASCADES > 1
    vec4 s = map.cascadeShadowFromWorld[cascadeOf(cascadeDepth(vWorldPosition))] * vec4(vWorldPosition, 1.0);
#else
    vec4 s = map.shadowFromWorld * vec4(vWorldPosition, 1.0);
#endif
    vec2 uv = s.xy / s.w;
    vec2 perPixel = vec2(length(dFdx(uv)), length(dFdy(uv))) / map.texelUv;  // texels a pixel step crosses
    float l = clamp(log2(max(max(perPixel.x, perPixel.y), 1e-6)) / 4.0, -1.0, 1.0);
    vec3 c = l < 0.0 ? mix(vec3(0.1, 0.8, 0.2), vec3(0.9, 0.1, 0.1), -l) : mix(vec3(0.1, 0.8, 0.2), vec3(0.1, 0.2, 0.9), l);
    if (s.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) c = vec3(0.35);
    outColor = vec4(c, 1.0);
}
