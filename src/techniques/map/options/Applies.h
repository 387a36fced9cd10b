#pragma once
// Technique "map": which of a light's options take effect, for the panels
// that show them (the viewer's; the catalog's optionUnused and presetKeys,
// include/shadowlab/Techniques.h). GL-free.
#include <shadowlab/Scene.h>

#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::map {

/// Why option `key` has no effect on `light` with its (effective) options,
/// e.g. "directional lights only" or "filter grid only"; "" when it may.
std::string unusedOption(const Light& light, std::string_view key);

/// The keys whose value the light's preset set: the preset gives them a
/// value other than the option's default and the light has that value.
std::vector<std::string> presetKeys(const Light& light);

} // namespace shadowlab::map
