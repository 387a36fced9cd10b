#pragma once
// Technique "map": shadow maps for directional (orthographic) and spot
// (perspective) lights, cube maps for point lights; options in
// include/shadowlab/MapOptions.h. The module's files, folder by folder,
// are listed in docs/architecture.md ("The map technique's module").
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "map".
TechniqueEntry mapTechnique();

} // namespace shadowlab
