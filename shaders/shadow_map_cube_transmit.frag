// Technique "map", a point light's translucent casters (alphaMode blend)
// into one cube face after its opaque depth: the stored depth's measure
// (distance over far) written as the fragment's depth, tested against the
// opaque casters' (no writes), the transmittance multiplied into colour 0
// and that depth kept, the least, in colour 1 (shadow_map_transmit.frag for 2D).
#include "shadow_map_shared.h"
#include "alpha_test.h"

in vec3 gCubeWorld;
in vec2 gCubeUv;
layout(location = 0) out vec4 outTransmit;
layout(location = 1) out vec4 outDepth;

void main() {
    float depth = clamp(length(gCubeWorld - map.lightPosition) / map.cubeFar, 0.0, 1.0);
    gl_FragDepth = depth;
    outTransmit = vec4(surfaceTransmittance(gCubeUv), 1.0);
    outDepth = vec4(depth);
}
