#pragma once
/// @file RayTracer.h
/// Exact (ray-traced) shadow visibility with Embree 3: the ground truth that
/// every shadow technique is measured against. Private to the library; Embree
/// stays out of this header (the handles are forward-declared).
#include <shadowlab/Scene.h>

#include <glm/glm.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

// Embree 3's opaque handle types (RTCDevice = RTCDeviceTy*, RTCScene = RTCSceneTy*).
struct RTCDeviceTy;
struct RTCSceneTy;

namespace shadowlab::reference {

/// One pixel's visible surface point.
struct SurfaceSample {
    glm::vec3 position{0.0f}; ///< world space
    glm::vec3 normal{0.0f};   ///< world space, unit, geometric normal of the visible triangle, facing the camera
    bool valid = false;       ///< false: background pixel, not traced
};

struct VisibilityOptions {
    /// Monte-Carlo samples per pixel for lights with size > 0, >= 1. The first
    /// floor(sqrt(n))^2 are a jittered grid (stratified), any remainder is
    /// uniform random, so the estimate is unbiased for every n.
    int softSamples = 256;
    /// How far the ray origin leaves the surface. < 0 (default): by
    /// offsetRayOrigin(), an amount that depends on the sample's own position
    /// only, so geometry far away (or geometry that casts no shadow) changes
    /// no visibility. >= 0: that many scene units along SurfaceSample::normal
    /// (0: the origin on the surface; for experiments).
    ///
    /// Why an offset along the normal and not tnear: a position interpolated on a
    /// triangle is rounded to float and lies up to an ulp below the surface,
    /// and on a curved mesh the neighbouring facets are tilted towards the
    /// ray. tnear is measured *along the ray*, so for a grazing ray it moves
    /// the start only tnear*sin(angle) off the surface and the ray still
    /// re-enters the own or a neighbouring facet (peers measured 0.01-0.8 %
    /// false hits with tnear alone). Moving the origin by eps along the
    /// geometric normal puts every point of the ray strictly outside the own
    /// facet's plane: n.(o + t*l - p) = eps + t*(n.l) > 0 for n.l > 0, so on
    /// a locally convex surface nothing of it can be hit (0 false hits
    /// measured).
    float normalOffset = -1.0f;
    /// Seed of the stratified jitter; results are deterministic for a given
    /// seed (independent of thread count and scheduling).
    unsigned seed = 1;
    /// When set, the number of samples traced so far is added here as the
    /// work goes on (from the tracing threads), for a progress display.
    std::atomic<std::size_t>* samplesDone = nullptr;
    /// When set and true, tracing stops early and visibility() throws
    /// shadowlab::Error("... cancelled").
    const std::atomic<bool>* cancel = nullptr;
    /// When set, filled with each sample's RGB transmittance: the light
    /// that arrives through translucent casters (alphaMode blend), the
    /// visibility itself per channel; visibility() returns its mean.
    std::vector<glm::vec3>* transmittance = nullptr;
};

/// The origin of a shadow ray from surface point p (world space) with unit
/// geometric normal n: p moved off its surface by an amount that depends on p
/// alone. First the offset of Wachter and Binder (Ray Tracing Gems ch. 6):
/// each coordinate steps 256 * n_i units in its own last place (|p_i| <
/// 1/32: 2^-16 * n_i scene units), which survives float rounding at any
/// magnitude; then a push of 2^-16 * max(|p_x|, |p_y|, |p_z|, 1) along n, for
/// the error of the rasterizer's position (interpolated on the GPU into an
/// RGBA32F target, it can lie slightly below the true surface). Around the
/// origin the offset is ~3e-5 scene units, at 1000 units ~0.03.
glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n);

/// Per sample, 1 where `light` reaches it at all, else 0: the sample is
/// valid, within the light's reach (shaders/light_reach.h: spot cone, range;
/// the definition lighting.frag uses) and its geometric normal faces the
/// light's centre (n . toLight > 0). RayTracer::visibility() is 0 wherever
/// this is 0. Throws shadowlab::Error for a zero or non-finite light direction.
std::vector<std::uint8_t> lightReach(const Light& light, const std::vector<SurfaceSample>& samples);

/// A BVH of every shadow-casting DrawItem, traced with packets of 16
/// occlusion rays (rtcOccluded16) on all hardware threads.
class RayTracer {
public:
    /// Builds the BVH of every DrawItem with castsShadows, in world space.
    /// Throws shadowlab::Error if Embree cannot be started or the build fails,
    /// or a mesh has an index out of range.
    explicit RayTracer(const Scene& scene);
    ~RayTracer();
    RayTracer(RayTracer&&) noexcept;
    RayTracer& operator=(RayTracer&&) noexcept;
    RayTracer(const RayTracer&) = delete;
    RayTracer& operator=(const RayTracer&) = delete;

    /// Visibility in [0,1] per sample (1 = fully lit, 0 = shadowed), in the
    /// order of `samples`; invalid samples get 0.
    ///
    /// Hard (light.size == 0): one ray per sample. Point/spot: towards
    /// light.position, ending just before it; directional: along
    /// -light.direction to infinity. Samples the light does not reach
    /// (lightReach(): outside a spot's outer cone, farther than a nonzero
    /// light.range, facing away from the light) are 0, like shadowed ones.
    ///
    /// Soft (light.size > 0): the fraction of unoccluded rays to points on the
    /// light. Point/spot: the light is a disk of radius `size` centred on
    /// light.position and facing the sample point (the silhouette a sphere
    /// light of that radius shows, up to perspective), sampled uniformly by
    /// area. Directional: directions uniform in solid angle within the cone of
    /// angular diameter `size` degrees around -light.direction (the sun as a
    /// disk in the sky). The cone, range and facing tests use the light's centre.
    ///
    /// Throws shadowlab::Error for softSamples < 1 or a moved-from tracer.
    std::vector<float> visibility(const Light& light, const std::vector<SurfaceSample>& samples,
                                  const VisibilityOptions& options = {}) const;

    /// Triangles in the BVH (shadow casters only).
    std::size_t triangleCount() const;

    /// What an alpha-tested caster's occlusion filter reads: its texture
    /// coordinates per vertex and triangles, its material's alpha factor and
    /// cutoff, and its base-colour texture (or none).
    struct AlphaCaster;

private:
    struct DeviceDeleter { void operator()(RTCDeviceTy* device) const; };
    struct SceneDeleter { void operator()(RTCSceneTy* scene) const; };

    // Declaration order matters: the scene is released before its device,
    // and both before the filters' data they point to.
    std::vector<std::unique_ptr<AlphaCaster>> alphaCasters_;
    std::map<int, std::unique_ptr<ImageRGBA8>> textures_;  ///< by Scene::textures index, the ones the filters read
    std::unique_ptr<RTCDeviceTy, DeviceDeleter> device_;
    std::unique_ptr<RTCSceneTy, SceneDeleter> scene_;
    std::size_t triangleCount_ = 0;
};

} // namespace shadowlab::reference
