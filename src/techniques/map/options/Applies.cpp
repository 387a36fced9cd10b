// Technique "map": which options take effect for a light (Applies.h). Each
// rule follows the option's own doc line in the options table
// (OptionTable.cpp): what it says the option is for.
#include "techniques/map/options/Applies.h"

#include "techniques/map/options/Settings.h"

#include <shadowlab/MapOptions.h>

#include <any>
#include <functional>
#include <utility>

namespace shadowlab::map {

namespace {

struct Facts {
    const MapOptions& o;
    bool directional, cube, cascades, moments, atlas;
    bool filter(MapFilter f) const { return o.filter == f; }
};

// Per option, when it is unused and the reason; an option not listed is always used.
using Rule = std::pair<std::function<bool(const Facts&)>, const char*>;

const std::vector<std::pair<std::string_view, Rule>>& rules() {
    static const std::vector<std::pair<std::string_view, Rule>> table = {
        {"warp", {[](const Facts& f) { return !f.directional; }, "directional lights only"}},
        {"warpNear", {[](const Facts& f) { return !f.directional || f.o.warp != MapWarp::Lispsm; }, "warp lispsm only"}},
        {"kernel", {[](const Facts& f) { return !f.filter(MapFilter::Grid); }, "filter grid only"}},
        {"gridTaps", {[](const Facts& f) { return !f.filter(MapFilter::Grid) || f.cube; }, "filter grid on a 2D map only"}},
        {"earlyOut", {[](const Facts& f) { return !f.filter(MapFilter::Grid) && !f.filter(MapFilter::Pcf20) && !f.filter(MapFilter::Pcss); },
                      "filters grid, pcf20 and pcss only"}},
        {"samples", {[](const Facts& f) { return !f.filter(MapFilter::Poisson) && !f.filter(MapFilter::Pcss); }, "filters poisson and pcss only"}},
        {"blockerSamples", {[](const Facts& f) { return !f.filter(MapFilter::Pcss); }, "filter pcss only"}},
        {"radius", {[](const Facts& f) { return !f.filter(MapFilter::Poisson) || f.cube; }, "filter poisson on a 2D map only (a cube: diskRadius)"}},
        {"mipmaps", {[](const Facts& f) { return f.cube || f.atlas; }, "not on a cube or in the atlas"}},
        {"outside", {[](const Facts& f) { return f.cube || f.atlas || f.cascades; }, "one 2D map only (not a cube, cascades or the atlas)"}},
        {"cascades", {[](const Facts& f) { return !f.directional; }, "directional lights only"}},
        {"cascadeLambda", {[](const Facts& f) { return !f.cascades; }, "cascades only (cascades 2 or more, a directional light)"}},
        {"cascadeSplits", {[](const Facts& f) { return !f.cascades; }, "cascades only (cascades 2 or more, a directional light)"}},
        {"stabilize", {[](const Facts& f) { return !f.cascades; }, "cascades only (cascades 2 or more, a directional light)"}},
        {"cascadeBlend", {[](const Facts& f) { return !f.cascades; }, "cascades only (cascades 2 or more, a directional light)"}},
        {"representation", {[](const Facts& f) { return f.cube; }, "directional and spot lights only"}},
        {"momentFormat", {[](const Facts& f) { return !f.moments; }, "representation vsm, evsm2, evsm4 or msm only"}},
        {"blur", {[](const Facts& f) { return !f.moments; }, "representation vsm, evsm2, evsm4 or msm only"}},
        {"bleedReduction", {[](const Facts& f) { return !f.moments; }, "representation vsm, evsm2, evsm4 or msm only"}},
        {"cubePasses", {[](const Facts& f) { return !f.cube || f.atlas; }, "point lights' cubes only (not in the atlas)"}},
        {"faceCulling", {[](const Facts& f) { return !f.cube; }, "point lights only"}},
        {"diskRadius", {[](const Facts& f) { return !f.cube || !(f.filter(MapFilter::Grid) || f.filter(MapFilter::Pcf20) || f.filter(MapFilter::Poisson)); },
                        "point lights with filter grid, pcf20 or poisson only"}},
        {"diskGrowth", {[](const Facts& f) { return !f.cube || !(f.filter(MapFilter::Grid) || f.filter(MapFilter::Pcf20) || f.filter(MapFilter::Poisson)); },
                        "point lights with filter grid, pcf20 or poisson only"}},
        {"atlas", {[](const Facts& f) { return f.directional; }, "spot and point lights only"}},
    };
    return table;
}

const MapOptions* optionsOf(const Light& light) {
    const auto it = light.shadow.options.find(MapOptions::kTechnique);
    return it == light.shadow.options.end() ? nullptr : std::any_cast<MapOptions>(&it->second);
}

} // namespace

std::string unusedOption(const Light& light, std::string_view key) {
    const MapOptions defaults;
    const MapOptions* stored = optionsOf(light);
    const MapOptions& o = stored ? *stored : defaults;
    const bool directional = light.type == LightType::Directional;
    const bool cube = isCube(o, light);
    const Facts facts{o, directional, cube, directional && o.cascades > 1,
                      !cube && o.representation != MapRepresentation::Depth, o.atlas && !directional};
    for (const auto& [name, rule] : rules())
        if (name == key && rule.first(facts)) return rule.second;
    return std::string();
}

std::vector<std::string> presetKeys(const Light& light) {
    const MapOptions* stored = optionsOf(light);
    if (!stored || stored->preset == MapPreset::Default) return {};
    const OptionTable& table = mapOptionTable();
    const std::any effective = *stored;
    const std::any preset = presetValues(*stored, light.type == LightType::Point);
    const std::any defaults = MapOptions{};
    std::vector<std::string> keys;
    for (const OptionField& f : table.fields) {
        if (f.key == "preset") continue;
        const std::string value = table.valueText(f, preset);
        if (value != table.valueText(f, defaults) && value == table.valueText(f, effective)) keys.push_back(f.key);
    }
    return keys;
}

} // namespace shadowlab::map
