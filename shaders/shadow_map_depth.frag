// Technique "map", shadow pass. Variants: MAP_RGBA8 (pack depth into an
// RGBA8 colour, lecture 002 §8.3.1), MAP_MOMENTS (write the moments of
// depth, SL_MAP_MOMENTS_*; MAP_SPOT: of a spot's depth linearised).
// A spot's map is drawn whole, not only the cone inscribed in it (002
// §8.2.1.3 discards outside the cone): a caster outside the cone shadows
// nothing inside it, and the texels just outside the rim keep the depth
// that filters and bilinear compares at the rim read (a discard there left
// them empty, so receivers at the rim came out lit).
in vec2 vUv;
#include "shadow_map_shared.h"
#include "alpha_test.h"
#if MAP_RGBA8
layout(location = 0) out vec4 outPacked;
#elif MAP_MOMENTS > 0
layout(location = 0) out vec4 outMoments;
#endif

void main() {
    if (alphaCutOut(vUv) || translucentSurface()) discard;  // holes; translucent casters go to the transmittance map
#if MAP_RGBA8
    outPacked = packDepth(gl_FragCoord.z);
#elif MAP_MOMENTS > 0
    float z = clamp(gl_FragCoord.z, 0.0, 1.0);  // pancaked casters (depth clamp) at the near plane
#if MAP_SPOT
    // Perspective depth is far from linear: the moments take the distance
    // along the axis between the near and far planes instead.
    float n = map.nearPlane, f = map.farPlane;
    z = (perspectiveDistance(z, n, f) - n) / (f - n);
#endif
    outMoments = momentsOf(z);
#endif
}
