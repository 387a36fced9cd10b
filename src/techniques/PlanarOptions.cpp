// Technique "planar": its options table and catalog row (no OpenGL; the
// technique itself is techniques/Planar.cpp).
#include "techniques/Kinds.h"

#include <shadowlab/PlanarOptions.h>

namespace shadowlab {

const OptionTable& planarOptionTable() {
    static const OptionTable table =
        OptionTableFor<PlanarOptions>("planar")
            .nodeNames(&PlanarOptions::receivers, "receivers",
                       "the receiver planes; empty: every node whose mesh is planar and receives shadows")
            .choice(&PlanarOptions::style, "style", {"stencil", "lecture"},
                    "stencil: each receiver pixel darkened once, clipped to the receiver; lecture: Wolberg's dark polygons with depth only (double blending, z-fighting)")
            .choice(&PlanarOptions::projection, "projection", {"vertex", "geometry"},
                    "the caster flattened in the vertex shader once per plane, or by a geometry shader onto every plane of a draw (Wolberg's duplication)")
            .number(&PlanarOptions::darkness, "darkness", 0.0, 1.0, "share of the colour", "style lecture: what each shadow polygon takes away")
            .build();
    return table;
}

namespace {

// Which options take effect: darkness only in style "lecture".
std::string planarUnused(const Light& light, std::string_view key) {
    const auto it = light.shadow.options.find(PlanarOptions::kTechnique);
    const PlanarOptions* o = it == light.shadow.options.end() ? nullptr : std::any_cast<PlanarOptions>(&it->second);
    const bool lecture = o && o->style == PlanarStyle::Lecture;
    return key == "darkness" && !lecture ? "style lecture only" : "";
}

} // namespace

TechniqueKind planarKind() {
    return {.name = "planar",
            .summary = "projected planar shadows: casters flattened onto receiver planes, kept to the receiver by the stencil",
            .options = &planarOptionTable(),
            .unused = &planarUnused};
}

} // namespace shadowlab
