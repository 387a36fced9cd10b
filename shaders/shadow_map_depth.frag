// Technique "map", shadow pass. Variants: MAP_RGBA8 (pack depth into an
// RGBA8 colour, lecture 002 §8.3.1), MAP_SPOT (discard outside the cone:
// the cone is the circle inscribed in the square map, 002 §8.2.1.3).
in vec2 vLightNdc;
#include "shadow_map_shared.h"
#if MAP_RGBA8
layout(location = 0) out vec4 outPacked;
#endif

void main() {
#if MAP_SPOT
    if (dot(vLightNdc, vLightNdc) > 1.0) discard;
#endif
#if MAP_RGBA8
    outPacked = packDepth(gl_FragCoord.z);
#endif
}
