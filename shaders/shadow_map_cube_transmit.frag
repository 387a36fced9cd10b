// Technique "map", a point light's translucent casters (alphaMode blend)
// into one cube face after its opaque depth: the stored depth's measure
// (distance over far, or the reversed window depth as rasterised with
// MAP_CUBE_WINDOW) as the fragment's depth, tested against the
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
#if !MAP_CUBE_WINDOW
    gl_FragDepth = depth;  // else the rasterised window depth is the opaque one's measure
#endif
    outTransmit = vec4(surfaceTransmittance(gCubeUv), 1.0);
    outDepth = vec4(depth);
}
