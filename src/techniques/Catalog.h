#pragma once
// The technique catalog: what the scene loader, the docs and bench need to
// know about each technique, without OpenGL. One TechniqueKind per
// technique: its name, summary, options table and the functions that judge
// and resolve its options. The GL half (shader files and the factory of the
// Technique that draws) is the registry (techniques/Registry.h), which only
// the renderer reads; a program that loads scenes links this and no GL.
#include <shadowlab/Options.h>
#include <shadowlab/Scene.h>
#include <shadowlab/Techniques.h>

#include <any>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

/// One technique as the scene loader sees it.
struct TechniqueKind {
    std::string name;                      ///< `lights[i].shadow.technique`
    std::string summary;                   ///< one line
    const OptionTable* options = nullptr;  ///< the block `lights[i].shadow.<name>`
    /// Why the technique cannot shadow this light, or "" (default: it can).
    std::function<std::string(const Light&)> unsupported = {};
    /// The light's shadow at the technique's baseline, the plainest form of
    /// it that bench times its variants against (shadowBaseline(),
    /// Techniques.h); default: the light is its own baseline.
    std::function<ShadowBaseline(const Light&)> baseline = {};
    /// Called as a scene is read, after the block `lights[i].shadow.<name>`
    /// (`options`): options that set others' defaults (map's preset) set
    /// every field but those the block wrote (`written`, its keys, `--set`
    /// included), for `light`; default: nothing to resolve.
    std::function<void(std::any& options, const std::vector<std::string>& written, const Light& light)> resolve = {};
    /// Why option `key` of the block has no effect on this light with its
    /// options (optionUnused(), Techniques.h); default: every option does.
    std::function<std::string(const Light& light, std::string_view key)> unused = {};
    /// The keys of the block whose value the light's preset set
    /// (presetKeys(), Techniques.h); default: none.
    std::function<std::vector<std::string>(const Light& light)> presetKeys = {};
};

/// The kind named `name`, or nullptr. Pointers stay valid for the program's life.
const TechniqueKind* findTechniqueKind(std::string_view name);
/// Every kind, in registry order ("none" first).
std::vector<const TechniqueKind*> techniqueKinds();
/// Adds a kind at run time (the registry's registerTechnique). Throws
/// shadowlab::Error when the name is taken or not an identifier, or the
/// options table's block is not the name.
void addTechniqueKind(TechniqueKind kind);

} // namespace shadowlab
