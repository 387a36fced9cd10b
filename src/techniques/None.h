#pragma once
// Technique "none": no shadows. Visibility is 1 everywhere (shaders/
// shadow_none.glsl); no shadow pass, shares the base pass. The unshadowed
// baseline every technique's time and error are measured against.
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "none".
TechniqueEntry noneTechnique();

} // namespace shadowlab
