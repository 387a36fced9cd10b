#pragma once
// Options of technique "planar": projected planar shadows (Wolberg,
// "Projective Shadows"), under lights[i].shadow.planar in a scene file.
#include <shadowlab/Export.h>
#include <shadowlab/Options.h>

#include <string>

namespace shadowlab {

enum class PlanarStyle {
    Stencil, ///< "stencil": each receiver pixel darkened at most once, clipped to the receiver, no z-fighting (default)
    Lecture, ///< "lecture": 000's look, the shadow polygons drawn dark over the lit scene with depth only (double blending, z-fighting)
};

enum class PlanarProjection {
    Vertex,   ///< "vertex": the caster drawn again with the projection in the vertex shader, once per receiver plane (default)
    Geometry, ///< "geometry": a geometry shader emits the projected copy of each triangle (000's duplication), onto every receiver plane in one draw
};

struct PlanarOptions {
    static constexpr const char* kTechnique = "planar";
    /// Comma-separated node names of the receiver planes; empty (default):
    /// every node whose mesh is planar and receives shadows.
    std::string receivers;
    PlanarStyle style = PlanarStyle::Stencil;
    PlanarProjection projection = PlanarProjection::Vertex;
    float darkness = 0.6f; ///< style lecture: the share of the colour a shadow polygon takes away, per polygon; default 0.6
};

/// The options table of "planar".
SHADOWLAB_API const OptionTable& planarOptionTable();

} // namespace shadowlab
