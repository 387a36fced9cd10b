// Technique "map", the floor of its lookups (bench: MapFloors::drawLookup):
// the cheapest lookup there is, one nearest depth a pixel from a map drawn
// just before (the pass floor's, as fresh as the light's own), compared
// (LOOKUP_FETCH 1); its twin without the fetch (0) writes the value it
// would compare, so that both keep the same arithmetic and the difference
// is the fetch and its compare alone. LOOKUP_CUBE: a cube's face along
// the direction from the light, compared with a depth of the distance
// along its major axis.
#include "shadow_map_shared.h"

#if LOOKUP_CUBE
in vec3 vFromLight;
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform samplerCube floorMap;
#else
in vec4 vLightClip;
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2D floorMap;
#endif
layout(location = 0) out vec4 outColor;

void main() {
#if LOOKUP_CUBE
    vec3 v = vFromLight;
    float ref = 1.0 - 1.0 / max(max(abs(v.x), abs(v.y)), abs(v.z));
#if LOOKUP_FETCH
    float lit = ref <= textureLod(floorMap, v, 0.0).r ? 1.0 : 0.0;
#else
    float lit = ref;
#endif
    outColor = vec4(v, lit);
#else
    vec3 s = vLightClip.xyz / vLightClip.w * 0.5 + 0.5;
#if LOOKUP_FETCH
    float lit = s.z <= textureLod(floorMap, s.xy, 0.0).r ? 1.0 : 0.0;
#else
    float lit = s.z;
#endif
    outColor = vec4(s.xy, 0.0, lit);
#endif
}
