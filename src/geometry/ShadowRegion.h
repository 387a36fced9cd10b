#pragma once
// Where on the screen a light's shadows can fall (RenderOptions::shadowRegions):
// screen rectangles outside of which no receiver is shadowed by the given
// casters. Worked in a light's clip space, where the light travels along
// the depth axis (orthographic: a directional light; perspective: from a
// point): a receiver is shadowed by a caster only where the caster's image
// in that space covers the receiver's own and the receiver lies beyond the
// caster's nearest depth (less a slack the caller gives for its biases).
// So for each caster box (the caller widens it by its filter's reach) and
// each receiver under its image, the rectangle around: a planar receiver's
// plane where the box's corners swept along the light land on it, any other
// receiver's own box, cut to the box's column past its nearest depth.
// GPU-free.
#include "core/Bounds.h"
#include "core/ScreenRect.h"

#include <shadowlab/Scene.h>

#include <glm/glm.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace shadowlab {

/// At most this many rectangles a light (the techniques merge theirs into as few).
inline constexpr std::size_t kMaxShadowRects = 8;

/// The frame's items (as FrameInfo has them) and the view.
struct RegionScene {
    const std::vector<DrawItem>& items;                       ///< DrawItem::receivesShadows says which may be shadowed
    const std::vector<Bounds>& itemBounds;                    ///< world bounds of each
    const std::vector<std::optional<glm::vec4>>& itemPlanes;  ///< world plane of each planar one
    glm::mat4 cameraClipFromWorld{1.0f};
    glm::ivec2 viewport{0};
};

/// The rectangles for `casters` (world boxes) in the light space
/// `lightClipFromWorld` (perspective: what lies nearer than its near plane
/// is left out, as the light's map leaves it), a receiver counting past a
/// caster's nearest clip depth less `depthSlack` (2 or more: the whole
/// depth range). At most `most` rectangles (core/ScreenRect: mergedRects);
/// none when no caster can shadow a receiver; nothing when a point reaches
/// behind the viewer (its image is then not bounded by its corners').
std::optional<std::vector<PixelRect>> shadowRects(const glm::mat4& lightClipFromWorld, bool perspective, const std::vector<Bounds>& casters,
                                                  float depthSlack, const RegionScene& scene, std::size_t most);

/// How far across its ray a receiver's taps reach, as an angle from the
/// light (radians) for a receiver `distance` from it: `angle`, plus `world`
/// scene units at the receiver, plus for pcss (`pcssSize` > 0, the light's
/// radius) its search and penumbra, size (1 / nearest caster - 1 / distance).
/// The world part shrinks with the distance and pcss's grows: over
/// receivers from `nearest` to `farthest`, within(nearest, farthest) bounds
/// it.
struct TapReach {
    float angle = 0.0f;
    float world = 0.0f;
    float pcssSize = 0.0f;
    float pcssNearest = 1.0f;
    float at(float distance) const;
    float within(float nearest, float farthest) const;
};

/// The rectangles for one caster `box` (world) of a point light at
/// `light`, worked in the world: a planar receiver's plane where the rays
/// from the light through the box's corners, each tilted by the taps'
/// reach, meet it (its whole rectangle when one of them does not), any
/// other receiver's whole rectangle when its bounding sphere and the box's,
/// widened by the reach, overlap as seen from the light. For a box too wide
/// for a perspective light space (pointCasterRects); receivers nearer the
/// light than the box included. Nothing when a point lies behind the viewer.
std::optional<std::vector<PixelRect>> centralRects(const glm::vec3& light, const Bounds& box, const TapReach& reach, const RegionScene& scene);

/// `box` cut into pieces whose sides are at most half its distance from
/// `light` (at most `most` along an axis; the whole box when the light is
/// inside it): their shadows together are the box's, and each piece's
/// lies within a narrower range of distances from the light, so the taps'
/// reach there (TapReach) is bounded more tightly.
std::vector<Bounds> piecesSeenFrom(const Bounds& box, const glm::vec3& light, int most = 4);

/// The rectangles for one caster `box` (world) of a point light at
/// `light`: the box widened by `widen` (the taps' reach where it lies
/// farthest) in a perspective light space from the light around it (along
/// the mean direction to its corners), whose near plane `nearPlaneFor`
/// gives from the box's nearest depth along that axis (none above 0:
/// nothing) and every receiver past it counts, out to `farPlane`; or, when
/// the box spreads more than 80 degrees from that axis or reaches the
/// light's side, centralRects of `box` itself with `taps`. Not merged.
std::optional<std::vector<PixelRect>> pointCasterRects(const glm::vec3& light, const Bounds& box, float widen, const TapReach& taps,
                                                       const std::function<float(float)>& nearPlaneFor, float farPlane, const RegionScene& scene);

} // namespace shadowlab
