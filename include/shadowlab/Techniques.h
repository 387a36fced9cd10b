#pragma once
/// @file Techniques.h
/// The registered shadow techniques: their names (the values of
/// `lights[i].shadow.technique`), a one-line summary, and the options table
/// of their block `lights[i].shadow.<name>` (Options.h). Each technique is a
/// module of its own (src/techniques/<Name>.cpp) with one registry line.
#include <shadowlab/Options.h>
#include <shadowlab/Scene.h>

#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

struct TechniqueInfo {
    std::string name;          ///< e.g. "none"
    std::string summary;       ///< one line for docs and --help
    const OptionTable* options = nullptr; ///< its block's fields (may have none)
};

/// Every registered technique, in registry order.
std::vector<TechniqueInfo> techniques();
/// The technique named `name`, or nullptr.
const TechniqueInfo* findTechnique(std::string_view name);
/// The Markdown that docs/scene-format.md carries between its "generated"
/// markers: the `technique` values and each technique's options table
/// (`shadowlab techniques --markdown` prints it; a test compares the doc).
std::string techniquesMarkdown();
/// Why `technique` cannot shadow `light` (e.g. a light type it does not
/// handle yet), or an empty string when it can.
std::string unsupportedReason(std::string_view technique, const Light& light);

} // namespace shadowlab
