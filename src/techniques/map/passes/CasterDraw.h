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
//
// A cube's or a 2D map's pass draws a closed opaque caster the light sees
// whole from outside, past its near plane, without its far sides: a ray
// from the light meets a near side first, so the nearest depth is a near
// side's, and half of its triangles are not set up and rasterised
// (penumbra-step's pcss cube, whose written distance makes llvmpipe shade
// every fragment, 4.7 -> 3.4 ms; cascades-field's four cascades, 291k
// triangles, about 10 ms). The map changes only at the silhouettes, where
// a far side's slope bias (or polygon offset) put it nearer than the near
// side's. The atlas draws both.
//
// A dense caster whose triangles are far smaller than the map's texels is
// drawn, where the pass allows (CasterDetail: map option lodTexels; a 2D
// map's, a cascade's or a cube's pass, not the atlas's), from a
// coarser level of its mesh (core/MeshLevels.h), the coarsest whose surface
// lies within the allowed world error of the mesh's. Those levels' vertices
// are the mesh's own, so their triangles lie on or within that error of
// its surface, either side; the pass's vertex stage moves them that far
// away from the light (shadow_map_depth.vert: casterPush), so that the
// level is nowhere nearer the light than the surface it stands for, and no
// lit point of it comes out shadowed. cascades-field's bunnies, 70k
// triangles each, are 20-130 texels across in its cascades.
#include "core/Bounds.h"
#include "geometry/LightCamera.h"
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

/// Whether the light's camera sees all of item i from outside it, past its
/// near plane (so that its near sides hide its far ones).
using CasterSeenWhole = std::function<bool(std::size_t i)>;

/// The world-space error a pass accepts in item i's surface (its mesh may
/// be drawn from a coarser level within it, pushed that far from the
/// light); 0: the mesh's own triangles.
using CasterDetail = std::function<float(std::size_t i)>;

/// The detail a 2D map's pass through `camera` allows: `lodTexels` of its
/// texels at each caster, their world size there (an orthographic
/// camera's texelSize; a perspective one's at the caster's nearest point
/// along its axis, not nearer than its near plane; a warped one's
/// smallest); none (an empty function) at 0.
CasterDetail casterDetail(float lodTexels, const LightCamera& camera, const FrameInfo& frame);

/// A cube's: `lodTexels` of its face texels at each caster, at the
/// caster's nearest point to the light over sqrt(3) (a face's texel grows
/// with the distance along its axis, at least that), not nearer than its
/// near plane.
CasterDetail casterDetail(float lodTexels, const CubeCamera& camera, int size, const FrameInfo& frame);

/// The uniform location of the push in the depth programs drawDepthCasters
/// draws levels with (shadow_map_depth.vert and shadow_map_cube.vert:
/// casterPush, world units).
inline constexpr int kCasterPushLocation = 4;

/// Whether a 2D map's `camera` sees `box` whole: an orthographic one
/// always (it clamps depth instead of clipping at its near plane), a
/// perspective one when every corner lies past its near plane.
bool seesWhole(const LightCamera& camera, const Bounds& box);
/// Whether a cube's `camera` sees `box` whole: past every face's near
/// plane, farther than sqrt(3) times it from the light.
bool seesWhole(const CubeCamera& camera, const Bounds& box);

/// The casters `keep` picks: first the opaque ones through program(false),
/// then, when `holes` (the frame has such casters), those with holes
/// through program(true). `state` is the pass's, in effect on entry and on
/// return; where it culls nothing, the opaque closed casters `seenWhole`
/// accepts (none when it is empty) are drawn first with their far sides
/// culled (gl::Cull::Back, or Front where their winding is mirrored:
/// FrameInfo::itemWinding). Where `detail` is given, each opaque caster is
/// drawn from the coarsest level of its mesh within detail(i), its push set
/// at kCasterPushLocation of program(false) (which must have it). Where
/// `state` culls front faces (cullFront) and `openCasters` is given, only
/// closed casters are drawn so (mirrored ones with back faces culled):
/// an open caster (a plane, a ceiling) has no back face where the light
/// sees its front, and is drawn whole with `openCasters` (culling nothing,
/// with the polygon offset a front face takes). Returns the triangles
/// drawn.
std::size_t drawDepthCasters(TechniqueHost& host, const FrameInfo& frame, bool holes, const CasterProgram& program, const CasterFilter& keep,
                             const gl::RenderState& state, const CasterSeenWhole& seenWhole, const CasterDetail& detail = {},
                             const gl::RenderState* openCasters = nullptr);

} // namespace shadowlab::map
