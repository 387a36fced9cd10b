#pragma once
/// @file Techniques.h
/// The registered shadow techniques: their names (the values of
/// `lights[i].shadow.technique`), a one-line summary, and the options table
/// of their block `lights[i].shadow.<name>` (Options.h). Each technique is a
/// module of its own (src/techniques/<Name>.cpp) with one registry line.
#include <shadowlab/Export.h>
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
SHADOWLAB_API std::vector<TechniqueInfo> techniques();
/// The technique named `name`, or nullptr.
SHADOWLAB_API const TechniqueInfo* findTechnique(std::string_view name);
/// The Markdown that docs/scene-format.md carries between its "generated"
/// markers: the `technique` values and each technique's options table
/// (`shadowlab techniques --markdown` prints it; a test compares the doc).
SHADOWLAB_API std::string techniquesMarkdown();
/// Why `technique` cannot shadow `light` (e.g. a light type it does not
/// handle yet), or an empty string when it can.
SHADOWLAB_API std::string unsupportedReason(std::string_view technique, const Light& light);

/// Why option `key` of `light`'s technique block (`lights[i].shadow.<technique>.<key>`)
/// has no effect on this light with its other options, in a few words
/// ("directional lights only", "filter grid only"), or "" when it may: for
/// panels that grey out what does not apply (the viewer's).
SHADOWLAB_API std::string optionUnused(const Light& light, std::string_view key);
/// The keys of `light`'s technique block whose values its preset set (map's
/// `preset`: a value other than the option's default that the light has),
/// for panels that mark them; none without a preset.
SHADOWLAB_API std::vector<std::string> presetKeys(const Light& light);

/// A light's shadow at its technique's baseline: the plainest form of the
/// technique, which bench times a frame against (results.json's
/// `frameOverHardMap`; for `map`, one 2D map of the same size with the
/// default filter and representation).
struct ShadowBaseline {
    ShadowSettings shadow;  ///< the light's shadow settings at the baseline
    /// Whether the light's own settings are a variant worth timing against
    /// the baseline (a map's cascades, filter or representation).
    bool differs = false;
};
/// `light`'s baseline, from its technique's registry entry; a technique
/// without one (or an unknown one): the light's own settings, not differing.
SHADOWLAB_API ShadowBaseline shadowBaseline(const Light& light);

} // namespace shadowlab
