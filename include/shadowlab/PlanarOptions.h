#pragma once
// Options of technique "planar": projected planar shadows (Wolberg,
// "Projective Shadows"), under lights[i].shadow.planar in a scene file.
#include <shadowlab/Export.h>
#include <shadowlab/Options.h>

#include <string>

namespace shadowlab {

enum class PlanarStyle {
    Stencil, ///< "stencil": each receiver pixel darkened at most once, clipped to the receiver, no z-fighting (default)
    Lecture, ///< "lecture": Wolberg's look, the shadow polygons drawn dark over the lit scene with depth only (double blending, z-fighting)
};

enum class PlanarProjection {
    Vertex,   ///< "vertex": the caster drawn again with the projection in the vertex shader, once per receiver plane (default)
    Geometry, ///< "geometry": a geometry shader emits the projected copy of each triangle (Wolberg's duplication), onto every receiver plane in one draw
};

/// Technique "planar"'s options. What each one does and its default are
/// documented once, in the options table (`shadowlab techniques`,
/// docs/techniques/planar.md); a field's comment here gives its unit and
/// default only.
struct PlanarOptions {
    static constexpr const char* kTechnique = "planar";
    std::string receivers;  ///< node names, comma-separated; default "" (every planar receiver)
    PlanarStyle style = PlanarStyle::Stencil;
    PlanarProjection projection = PlanarProjection::Vertex;
    float darkness = 0.6f;  ///< share of the colour; default 0.6
};

/// The options table of "planar".
SHADOWLAB_API const OptionTable& planarOptionTable();

} // namespace shadowlab
