#pragma once
// Technique "planar": projected planar shadows (Wolberg's lecture). Each caster is
// drawn again flattened onto each receiver plane by the plane projection
// matrix; the stencil keeps the shadow on the receiver's own pixels, marks
// each at most once, and the light is added where it is not marked.
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "planar".
TechniqueEntry planarTechnique();

} // namespace shadowlab
