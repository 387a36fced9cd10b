#pragma once
// Light cameras for shadow maps (Ganovelli et al. §8.2.1): an orthographic box
// along a directional light, a perspective frustum around a spot's cone,
// fitted to the casters and receivers that matter. GPU-free.
#include "core/Bounds.h"

#include <shadowlab/Scene.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace shadowlab {

/// What a light camera is fitted around.
enum class LightFit {
    Tight, ///< the casters that can shadow what the camera sees
    Scene, ///< the whole scene (directional) or the whole cone (spot)
};

struct LightCamera {
    glm::mat4 viewFromWorld{1.0f};
    glm::mat4 clipFromView{1.0f};
    bool perspective = false;
    float nearPlane = 0.0f, farPlane = 1.0f; ///< along the light, scene units
    /// Orthographic: world size of one texel. Perspective: world size of one
    /// texel per unit of distance along the light's axis.
    float texelSize = 0.0f;
    /// Orthographic: a texel's world size along the light view's x and y,
    /// which differ where a stabilised cascade's window is the receivers'
    /// box on one axis (fitCascade); 0: texelSize both ways. texelSize is
    /// then the larger.
    glm::vec2 texelAxes{0.0f};
    /// Per item: 1 when it may shadow a receiver the camera sees (drawn into
    /// the map), 0 when it cannot; empty: every caster is drawn.
    std::vector<std::uint8_t> casts;
    /// A warped map (LightWarp): clipFromView is projective along the view,
    /// and a texel's world size at a point is max(warpU t, warpV t^2), t =
    /// dot(warpPlane.xyz, point) + warpPlane.w (texelSize: the smallest).
    bool warped = false;
    glm::vec4 warpPlane{0.0f};
    float warpU = 0.0f, warpV = 0.0f;
    /// Light view space: a box around every point whose lookups may read
    /// this map (the receivers the viewer may see where they read it, each
    /// box within that part of the view's frustum), before the filter's
    /// footprint and the offsets widen it; an empty box: none; nothing: not
    /// known, the whole map (fitCascade knows it for stabilised cascades,
    /// whose square is the slice's bounding sphere's).
    std::optional<Bounds> lookups;
    glm::mat4 clipFromWorld() const { return clipFromView * viewFromWorld; }
    /// The unit direction the camera looks along: minus the view matrix's third row.
    glm::vec3 axis() const { return -glm::vec3(viewFromWorld[0][2], viewFromWorld[1][2], viewFromWorld[2][2]); }
};

/// The view a directional light's map is warped for (light space
/// perspective shadow maps, Wimmer, Scherzer and Purgathofer 2004): the
/// camera's position, its unit forward direction, and the view distance the
/// warp's near plane stands for at the least (map option warpNear).
struct LightWarp {
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    float nearDistance = 1.0f;
};

/// The warp's axis: the view direction across the light (unit), and the
/// sine of the angle between view and light (its length before
/// normalising).
struct WarpAxis {
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    float sinGamma = 1.0f;
};
/// A warp's axis for a directional light along `direction` (unit); none
/// without a warp or when the light is within about 1 degree of the view
/// (sine below 0.02: no warp).
std::optional<WarpAxis> warpAxis(const glm::vec3& direction, const LightWarp* warp);

/// What the fit looks at: every item's world bounds, which cast and which
/// receive, and the viewer's clipFromWorld (receivers it cannot see do not
/// need shadows).
struct FitInput {
    const std::vector<Bounds>& itemBounds;
    const std::vector<DrawItem>& items;
    const std::vector<std::optional<glm::vec4>>& itemPlanes; ///< world plane of each planar item
    const std::vector<std::vector<glm::vec4>>& itemConvex;   ///< world planes of each convex item (empty: not known convex)
    glm::mat4 cameraClipFromWorld{1.0f};
    int size = 2048;           ///< map texels per side
    float paddingTexels = 1.0f;///< extra texels around the fitted region (filter footprint)
    /// The filter compares taps against the receiver's plane extended over
    /// a wide region (PCSS's blocker search): a caster farther from the
    /// light than every receiver may still count, so culling keeps it.
    bool planeReachesBeyond = false;
    /// Depth-reduced fits (SDSM, map fit "sdsm"): the bounds of the receiver
    /// points the camera really sees, reduced from the frame's depth, in the
    /// space of directionalLightView(); they replace the visible receivers'
    /// boxes (clipped to the frustum) of the tight fit. Null: not reduced.
    const Bounds* visibleSamples = nullptr;
};

/// A directional light's view for the fits: looking along `direction` from
/// the scene's centre moved back by its diagonal (fixed while the scene
/// is). The space FitInput::visibleSamples are given in.
glm::mat4 directionalLightView(const glm::vec3& direction, const FitInput& in);
/// The scene's diagonal as the directional fits take it (how far back
/// directionalLightView stands, and their depth padding of 10^-3 of it):
/// that of every item's bounds, at least 10^-3; 1 with no items.
float sceneDiagonal(const FitInput& in);

/// The box, in `to` space, of the eight corners of the clip volume of
/// `cameraClipFromWorld` (its NDC cube's corners taken back to the world).
Bounds frustumBounds(const glm::mat4& cameraClipFromWorld, const glm::mat4& to);

/// False when the box lies entirely outside the clip volume of
/// `clipFromWorld` (all eight corners beyond one of its six planes): a
/// conservative test, a box it keeps may still be outside.
bool mayIntersect(const glm::mat4& clipFromWorld, const Bounds& box);
/// Whether a caster's shadow under a directional light shining along
/// `direction` may fall inside a camera's frustum: the caster's box widened
/// by `pad` on every side, swept along the light until it leaves the
/// scene's box (both ways when `bothWays`), crosses the frustum (tested
/// against its planes: it may answer true for a volume that only passes
/// near a corner, never false for one inside).
bool shadowMayReach(const Bounds& caster, const glm::vec3& direction, const Bounds& scene, float pad, bool bothWays,
                    const glm::mat4& clipFromWorld);

/// The light as one homogeneous vector: a point or spot light's position
/// with w = 1, or the unit direction towards a directional light with w = 0
/// (what castersThatMatter, the plane projection and the volumes take).
glm::vec4 towardsLight(const Light& light);

/// Which casters may shadow a receiver the camera sees (LightCamera::casts)
/// for a light `towardsLight` (position, w = 1; or the direction towards a
/// directional light, w = 0), with `lightView` a view along the light for
/// the footprint test of a directional light (ignored for w = 1). A caster
/// counts when some visible receiver overlaps it across the light and is
/// not entirely nearer the light than it; a planar caster (a floor) only
/// when that receiver is another item reaching behind its plane; a convex
/// caster with a point or spot light inside it (a room) only when a visible
/// receiver reaches outside it.
std::vector<std::uint8_t> castersThatMatter(const glm::vec4& towardsLight, const glm::mat4& lightView, const FitInput& in);

/// Directional light travelling along `direction` (unit).
/// Tight: the region of the light's view plane covered by receivers the
/// camera sees, depth from the nearest caster over that region to the
/// farthest receiver; the shadow pass clamps depth (casters nearer than
/// the near plane still occlude). Scene: the lecture's cube around the
/// scene's bounds, sides equal to their diagonal.
/// With `warp` (tight and sdsm fits), the fitted box is warped by a
/// perspective along the view; a light within about 1 degree of the view
/// direction gets none (the warp's axis is undefined there).
LightCamera fitDirectional(const glm::vec3& direction, LightFit fit, const FitInput& in, const LightWarp* warp = nullptr);

/// A point light's cube: six 90-degree cameras from its position with the
/// cube-map convention's directions and up vectors (+X, -X, +Y, -Y, +Z, -Z).
struct CubeCamera {
    glm::vec3 position{0.0f};
    float nearPlane = 0.01f, farPlane = 1.0f;  ///< scene units; stored depth is distance / farPlane
    std::array<glm::mat4, 6> faceClipFromWorld{};
    /// Per item: bit f set when the item may touch face f (and may shadow a
    /// visible receiver); 0 for items that are not drawn.
    std::vector<std::uint8_t> faceMasks;
};

/// The cube-map convention's view of face f (0..5: +X, -X, +Y, -Y, +Z, -Z)
/// from `position`.
glm::mat4 cubeFaceView(const glm::vec3& position, int face);

/// Point light: far at the farthest corner of what must be covered (tight:
/// the receivers the camera sees; scene: everything), within the light's
/// range; near proportional to far (far / 10^4). `nearPlane`/`farPlane` > 0
/// replace the fitted values (the presets' fixed planes).
CubeCamera fitCube(const Light& light, LightFit fit, const FitInput& in, float nearPlane = 0.0f, float farPlane = 0.0f);

/// Spot light: perspective along its axis, field of view just containing
/// the outer cone (plus the padding), far at the farthest projection of the
/// (tight: visible receivers', scene: all) bounds on the axis, near at the
/// nearest caster in the cone (at least far / 10000).
LightCamera fitSpot(const Light& light, LightFit fit, const FitInput& in);

} // namespace shadowlab
