#pragma once
// Technique "map": what the registry and the scene loader ask of its
// options (options/OptionTable.cpp; the table itself is mapOptionTable(),
// include/shadowlab/MapOptions.h): the combinations refused, the options as
// the scene is read, and the plainest map bench times the others against.
// These, and ShadowMap::prepare, are the only readers of a light's options
// from the light; everything else reads MapLight::options.
#include <shadowlab/MapOptions.h>
#include <shadowlab/Techniques.h>

#include <any>
#include <string>
#include <vector>

namespace shadowlab::map {

/// Why "map" cannot shadow this light with its options, or "" (the registry's unsupported()).
std::string unsupported(const Light& light);

/// The light's options as the scene is read (TechniqueKind::resolve):
/// `written`, the keys its block gave; the preset's values under them
/// (withPreset), and filter "pcf" on a point light's cube a 4x4x4 grid.
void resolveOptions(std::any& options, const std::vector<std::string>& written, const Light& light);

/// The registry's baseline: the plainest map of the same size (one 2D map,
/// depth, the default filter: the lecture's technique), which cascades,
/// PCSS and moment maps are timed against.
ShadowBaseline plainestMap(const Light& light);

} // namespace shadowlab::map
