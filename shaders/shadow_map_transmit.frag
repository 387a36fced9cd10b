// Technique "map", translucent casters (alphaMode blend) after the opaque
// depth: each one's transmittance, multiplied into colour 0 by the blend
// (dst x src), and its depth, the nearest kept in colour 1 (blend MIN),
// where no opaque caster is nearer the light (the depth test, no writes).
in vec2 vUv;
#include "shadow_map_shared.h"
#include "alpha_test.h"
layout(location = 0) out vec4 outTransmit;
layout(location = 1) out vec4 outDepth;

void main() {
    outTransmit = vec4(surfaceTransmittance(vUv), 1.0);
    outDepth = vec4(gl_FragCoord.z);
}
