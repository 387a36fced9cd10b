#pragma once
// Light cameras for shadow maps (lecture 002 §8.2.1): an orthographic box
// along a directional light, a perspective frustum around a spot's cone,
// fitted to the casters and receivers that matter. GPU-free.
#include "core/Bounds.h"

#include <shadowlab/MapOptions.h>
#include <shadowlab/Scene.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace shadowlab {

struct LightCamera {
    glm::mat4 viewFromWorld{1.0f};
    glm::mat4 clipFromView{1.0f};
    bool perspective = false;
    float nearPlane = 0.0f, farPlane = 1.0f; ///< along the light, scene units
    /// Orthographic: world size of one texel. Perspective: world size of one
    /// texel per unit of distance along the light's axis.
    float texelSize = 0.0f;
    /// Per item: 1 when it may shadow a receiver the camera sees (drawn into
    /// the map), 0 when it cannot; empty: every caster is drawn.
    std::vector<std::uint8_t> casts;
    glm::mat4 clipFromWorld() const { return clipFromView * viewFromWorld; }
};

/// What the fit looks at: every item's world bounds, which cast and which
/// receive, and the viewer's clipFromWorld (receivers it cannot see do not
/// need shadows).
struct FitInput {
    const std::vector<Bounds>& itemBounds;
    const std::vector<DrawItem>& items;
    const std::vector<std::optional<glm::vec4>>& itemPlanes; ///< world plane of each planar item
    glm::mat4 cameraClipFromWorld{1.0f};
    int size = 2048;           ///< map texels per side
    float paddingTexels = 1.0f;///< extra texels around the fitted region (filter footprint)
};

/// False when the box lies entirely outside the clip volume of
/// `clipFromWorld` (all eight corners beyond one of its six planes): a
/// conservative test, a box it keeps may still be outside.
bool mayIntersect(const glm::mat4& clipFromWorld, const Bounds& box);

/// Which casters may shadow a receiver the camera sees (LightCamera::casts)
/// for a light `towardsLight` (position, w = 1; or the direction towards a
/// directional light, w = 0), with `lightView` a view along the light for
/// the footprint test of a directional light (ignored for w = 1). A caster
/// counts when some visible receiver overlaps it across the light and is
/// not entirely nearer the light than it; a planar caster (a floor) only
/// when that receiver is another item reaching behind its plane.
std::vector<std::uint8_t> castersThatMatter(const glm::vec4& towardsLight, const glm::mat4& lightView, const FitInput& in);

/// Directional light travelling along `direction` (unit).
/// Tight: the region of the light's view plane covered by receivers the
/// camera sees, depth from the nearest caster over that region to the
/// farthest receiver; the shadow pass clamps depth (casters nearer than
/// the near plane still occlude). Scene: the lecture's cube around the
/// scene's bounds, sides equal to their diagonal.
LightCamera fitDirectional(const glm::vec3& direction, MapFit fit, const FitInput& in);

/// Spot light: perspective along its axis, field of view just containing
/// the outer cone (plus the padding), far at the farthest projection of the
/// (tight: visible receivers', scene: all) bounds on the axis, near at the
/// nearest caster in the cone (at least far / 10000).
LightCamera fitSpot(const Light& light, MapFit fit, const FitInput& in);

} // namespace shadowlab
