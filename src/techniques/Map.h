#pragma once
// Technique "map": shadow maps for directional (orthographic) and spot
// (perspective) lights; options in include/shadowlab/MapOptions.h.
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "map".
TechniqueEntry mapTechnique();

} // namespace shadowlab
