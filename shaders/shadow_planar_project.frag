// Technique "planar": the flattened caster. Style stencil: no colour (only
// the stencil is written). Style lecture (PLANAR_DARK): a dark polygon that
// multiplies the colour below by 1 - darkness (blended, so overlapping
// polygons darken twice, as in Wolberg's lecture).
#include "shadow_planar_shared.h"

#if PLANAR_DARK
layout(location = 0) out vec4 outColor;
#endif

void main() {
#if PLANAR_DARK
    outColor = vec4(vec3(1.0 - planar.params.y), 1.0);
#endif
}
