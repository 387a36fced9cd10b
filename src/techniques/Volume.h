#pragma once
// Technique "volume": stencil shadow volumes (Ganovelli et al. §8.5): the
// casters' silhouettes extruded to infinity along the light's rays, capped,
// counted in the stencil; the light is added where the count is zero.
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "volume".
TechniqueEntry volumeTechnique();

} // namespace shadowlab
