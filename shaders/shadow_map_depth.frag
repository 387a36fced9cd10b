// Technique "map", shadow pass. Variants: MAP_RGBA8 (pack depth into an
// RGBA8 colour, Ganovelli et al. §8.3.1); otherwise depth alone (moment maps
// too: their moments are made from it afterwards, shadow_map_blur.frag);
// MAP_HOLES, casters whose holes are cut here (the others: no test).
// A spot's map is drawn whole, not only the cone inscribed in it (Ganovelli et al.
// §8.2.1.3 discards outside the cone): a caster outside the cone shadows
// nothing inside it, and the texels just outside the rim keep the depth
// that filters and bilinear compares at the rim read (a discard there left
// them empty, so receivers at the rim came out lit).
in vec2 vUv;
#include "shadow_map_shared.h"
#include "alpha_test.h"
#if MAP_RGBA8
layout(location = 0) out vec4 outPacked;
#endif

void main() {
#if MAP_HOLES
    // Casters with holes only (DepthPassVariant::holes): a discard anywhere
    // in the stage costs a software rasteriser its depth-only path.
    if (alphaCutOut(vUv) || translucentSurface()) discard;  // holes; translucent casters go to the transmittance map
#endif
#if MAP_RGBA8
    outPacked = packDepth(gl_FragCoord.z);
#endif
}
