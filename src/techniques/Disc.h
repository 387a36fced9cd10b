#pragma once
// Technique "disc": exact shadows of flat discs in the light pass, with no
// shadow pass (Ganovelli et al. exercise 8.6.2-1 and its variation 1). Options:
// include/shadowlab/DiscOptions.h; GLSL: shaders/shadow_disc.glsl.
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "disc".
TechniqueEntry discTechnique();

} // namespace shadowlab
