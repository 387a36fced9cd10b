#pragma once
/// @file RayTracer.h
/// Exact (ray-traced) shadow visibility with Embree 3: the ground truth that
/// every shadow technique is measured against. Private to the library; Embree
/// stays out of this header (the handles are forward-declared).
#include <shadowlab/Scene.h>

#include <glm/glm.hpp>

#include <cstddef>
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
    /// Scene units the ray origin moves along SurfaceSample::normal; < 0 =
    /// automatic: 1e-4 * diagonal of Scene::worldBounds().
    ///
    /// Why a normal offset and not tnear: a position interpolated on a
    /// triangle is rounded to float and lies up to an ulp below the surface,
    /// and on a curved mesh the neighbouring facets are tilted towards the
    /// ray. tnear is measured *along the ray*, so for a grazing ray it moves
    /// the start only tnear*sin(angle) off the surface and the ray still
    /// re-enters the own or a neighbouring facet (peers measured 0.01-0.8 %
    /// false hits with tnear alone). Moving the origin by eps along the
    /// geometric normal puts every point of the ray strictly outside the own
    /// facet's plane: n.(o + t*l - p) = eps + t*(n.l) > 0 for n.l >= 0, so on
    /// a locally convex surface nothing of it can be hit (0 false hits
    /// measured). The offset is tiny against the scene, so real contact
    /// shadows are not lost.
    float normalOffset = -1.0f;
    /// Seed of the stratified jitter; results are deterministic for a given
    /// seed (independent of thread count and scheduling).
    unsigned seed = 1;
};

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
    /// -light.direction to infinity. Spot: samples outside the outer cone are
    /// 0. Point/spot: samples farther than a nonzero light.range are 0.
    ///
    /// Soft (light.size > 0): the fraction of unoccluded rays to points on the
    /// light. Point/spot: the light is a disk of radius `size` centred on
    /// light.position and facing the sample point (the silhouette a sphere
    /// light of that radius shows, up to perspective), sampled uniformly by
    /// area. Directional: directions uniform in solid angle within the cone of
    /// angular diameter `size` degrees around -light.direction (the sun as a
    /// disk in the sky). The cone and range tests use the light's centre.
    ///
    /// Throws shadowlab::Error for softSamples < 1 or a moved-from tracer.
    std::vector<float> visibility(const Light& light, const std::vector<SurfaceSample>& samples,
                                  const VisibilityOptions& options = {}) const;

    /// Triangles in the BVH (shadow casters only).
    std::size_t triangleCount() const;

    /// The offset used when VisibilityOptions::normalOffset < 0.
    float automaticNormalOffset() const { return autoNormalOffset_; }

private:
    struct DeviceDeleter { void operator()(RTCDeviceTy* device) const; };
    struct SceneDeleter { void operator()(RTCSceneTy* scene) const; };

    // Declaration order matters: the scene is released before its device.
    std::unique_ptr<RTCDeviceTy, DeviceDeleter> device_;
    std::unique_ptr<RTCSceneTy, SceneDeleter> scene_;
    std::size_t triangleCount_ = 0;
    float autoNormalOffset_ = 0.0f;
};

} // namespace shadowlab::reference
