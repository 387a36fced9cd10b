#pragma once
// Technique "map": the casters of a depth-only shadow pass (a 2D map, a
// cascade, a cube, their floors), drawn by what their surface needs. Opaque
// casters go through a program whose fragment stage tests nothing: one that
// may discard (alpha_test.h) costs llvmpipe its depth-only path, even for
// casters with no holes (learnopengl-shadow-mapping's 1024^2 pass: 1.5
// against 0.9 ms). Casters with holes (alphaMode mask) go through the test
// that cuts them, after the opaque ones: the depth test keeps the nearest
// fragment whatever the order, so the map is the same texel for texel.
// Translucent casters (blend) cast no depth (MapTranslucent colours the
// light through them) and are not drawn here.
#include "techniques/Technique.h"

#include <cstddef>
#include <functional>

namespace shadowlab::map {

/// What a caster's surface asks of a depth pass.
enum class CasterSurface {
    Opaque,      ///< every fragment kept
    Holes,       ///< alphaMode mask: the fragments under the cutoff discarded
    Translucent, ///< alphaMode blend: no depth at all
};

/// Item i's surface (its material's alphaMode; no material: opaque).
CasterSurface casterSurface(const FrameInfo& frame, std::size_t i);
/// Whether some caster of the frame has holes (found once a frame: MapResources::holes).
bool hasCastersWithHoles(const FrameInfo& frame);

/// The program that draws a caster of surface `holes` (true: with the test
/// that cuts holes).
using CasterProgram = std::function<const gl::Program&(bool holes)>;
/// Decides whether item i is drawn, with the program that will draw it (for
/// its per-draw uniforms); false skips it.
using CasterFilter = std::function<bool(std::size_t i, const gl::Program& program)>;

/// The casters `keep` picks: first the opaque ones through program(false),
/// then, when `holes` (the frame has such casters), those with holes
/// through program(true).
void drawDepthCasters(TechniqueHost& host, const FrameInfo& frame, bool holes, const CasterProgram& program, const CasterFilter& keep);

} // namespace shadowlab::map
