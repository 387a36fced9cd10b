// Technique "map", the floor of its lookups (bench: MapFloors::drawLookup):
// the cheapest lookup there is, one nearest depth a pixel from a map drawn
// just before (the pass floor's, as fresh as the light's own), compared
// (LOOKUP_FETCH 1); its twin without the fetch (0) writes the depth it
// would compare, so that both keep the same divide and the difference is
// the fetch and its compare alone.
#include "shadow_map_shared.h"

in vec4 vLightClip;
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2D floorMap;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 s = vLightClip.xyz / vLightClip.w * 0.5 + 0.5;
#if LOOKUP_FETCH
    float lit = s.z <= textureLod(floorMap, s.xy, 0.0).r ? 1.0 : 0.0;
#else
    float lit = s.z;
#endif
    outColor = vec4(s.xy, 0.0, lit);
}
