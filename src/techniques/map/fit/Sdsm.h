#pragma once
// Technique "map", fit "sdsm" (Lauritzen et al., "Sample Distribution Shadow
// Maps", 2011): the points the camera sees, from a depth pre-pass of the
// frame (once a frame, shared by the lights that ask, drawn into the
// frame's own depth, which the base pass keeps: TechniqueHost::
// beginDepthPrepass), bounded in a light's view (or, for cascades, the
// camera's) by a fragment reduction of 8x8-pixel blocks
// (shaders/shadow_map_sdsm_reduce.frag), which compute passes merge and fit
// the cameras to on the GPU (fitOnGpu), into a buffer that MapBlock copies
// into the light's block: the frame never waits for its depth. The tight
// fit takes those bounds instead of the boxes of the receivers in view;
// cascades end where the depths they span do, and slices not stabilised
// take their own bounds, a second reduction counting for each slice only
// the pixels at its distances.
#include "core/Bounds.h"
#include "geometry/Cascades.h"
#include "geometry/LightCamera.h"
#include "shadow_map_sdsm_shared.h"
#include "techniques/Technique.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowlab::map {

/// The cameras the fit on the GPU writes (shaders/shadow_map_sdsm_shared.h),
/// one buffer per light: what MapBlock copies over the CPU's cameras.
using SdsmFit = shared::SdsmFit;

/// What the fit on the GPU takes beside the frame's samples
/// (MapCameras: gpuFitInput): the directional light's view (the samples'
/// space for one map), the scene's diagonal and box, the map's size and
/// padding (FitInput's); one map and cascades not stabilised: the boxes in
/// that view of the casters that matter; cascades: their count and splits'
/// settings, the view.
struct GpuFitInput {
    glm::mat4 samplesView{1.0f};  ///< one map: the reduction's space (directionalLightView)
    glm::mat4 lightView{1.0f};    ///< one map, slices: the camera's view (warped: turned), the casters' space
    float diagonal = 1.0f;
    float size = 1024.0f;
    float padding = 1.0f;
    std::vector<Bounds> casters;
    int cascades = 1;
    Bounds scene;
    glm::vec4 camera{0.1f, 100.0f, 1.0f, 1.0f};  ///< near plane, far plane, tan(fovY / 2), aspect
    glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
    bool stabilize = true;  ///< cascades: stabilised (else each slice fitted to its own samples)
    float reach = 100.0f;   ///< where slices end at the farthest (stabilised: MapCameras' stableReach; else viewReach)
    float blend = 0.1f;     ///< cascades not stabilised: cascadeBlend (the slices' windows)
    float lambda = 0.75f;   ///< cascadeLambda
    /// Stabilised cascades: the receivers' window in lightView (core/LightCamera: receiversWindow)
    glm::vec4 receiversWindow{0.0f};
    std::vector<float> given;  ///< cascadeSplits (empty: by lambda)
    /// Cascades: the range the far end the slices are split over is
    /// clamped to (GpuFit::seenFar's both ends; no clamp before it is known).
    glm::vec2 splitRange{0.0f, 3.0e38f};
    /// One map or cascades not stabilised, warp lispsm with the light not
    /// along the view: the warp (core/LightCamera: warpRegion) and its
    /// parameters (each slice's near distance is at least its near end).
    bool warped = false;
    float sinGamma = 1.0f, warpNear = 1.0f;
};

/// A light's fit on the GPU, kept from frame to frame: the buffer the
/// compute passes fit its cameras into (an SdsmFit, made zeroed on first
/// use), and for cascades the far end of the depths seen, read
/// back without waiting (copied after the fit with a fence; taken once the
/// fence has passed, a frame or more later). The next frame splits its
/// slices over that far end, which the CPU then knows, so that it culls
/// each cascade's casters for its own slice (MapCameras:
/// fitCullingCascades); the last slice still ends at that frame's own far
/// end.
class GpuFit {
public:
    GpuFit() = default;
    GpuFit(const GpuFit&) = delete;
    GpuFit& operator=(const GpuFit&) = delete;
    ~GpuFit();
    /// The fit's buffer (made on first use).
    gl::Buffer& buffer();
    /// The far end of the depths seen by the latest fit whose copy has
    /// landed (never waits); 0 before one has.
    float seenFar();
    /// After a fit's dispatch: its far end copied for seenFar(), fenced.
    void readSeenFarLater();

private:
    gl::Buffer fit_{gl::NoCreate};
    gl::Buffer copy_{gl::NoCreate};  ///< persistently mapped for reading
    const float* mapped_ = nullptr;
    GLsync fence_ = nullptr;
    float seenFar_ = 0.0f;
};

/// The cameras (clip from world) the GPU fitted into `fit`, read back: one
/// map's, or each of `cascades` cascades'. For what shows them (the
/// viewer's frustums), never the frame's own path.
std::vector<glm::mat4> readFittedClips(const gl::Buffer& fit, std::size_t cascades);

class SampleBounds {
public:
    /// Draws the frame's depth pre-pass (TechniqueHost::beginDepthPrepass)
    /// unless this frame already has it.
    void prepass(TechniqueHost& host, const FrameInfo& frame);
    /// Cascades not stabilised: the slices a second reduction bounds at once.
    static constexpr int kSlicesAPass = 4;  ///< two targets each: the 8 a framebuffer surely has
    /// The fit, into `out` (an SdsmFit, GpuFit::buffer: cascades keep
    /// their depths in it from frame to frame): the pre-pass reduced, then
    /// for one map shadow_map_sdsm_fit.comp fits the camera as
    /// core/LightCamera's fitDirectional does for visibleSamples; for
    /// cascades (in.cascades > 1) shadow_map_sdsm_cascades.comp splits the
    /// depths seen as MapCameras' fitCascades does and, stabilised, fits
    /// their cameras; not stabilised, a second reduction bounds each
    /// slice's samples (kSlicesAPass at a time) and
    /// shadow_map_sdsm_fit.comp fits each slice to its own.
    void fitOnGpu(TechniqueHost& host, const FrameInfo& frame, const GpuFitInput& in, const gl::Buffer& out);

    /// Meshes of more triangles than this are not drawn in the pre-pass:
    /// their boxes, cut to the view's (a slice's on the GPU), join the bounds instead
    /// (every point of theirs the camera can see lies in both). Bounds that
    /// way are never smaller than the points seen, a little larger where a
    /// large mesh hid what lies behind it; the pre-pass, which the vertex
    /// stage bounds on a large scene, then costs what the small meshes do.
    static constexpr std::size_t kBoxedTriangles = 4096;

private:
    gl::Sampler sampler_{gl::NoCreate};  ///< the frame's depth, nearest, clamped
    static constexpr int kBlock = 8;  ///< pixels per side of a block (shadow_map_sdsm_reduce.frag)
    /// A reduction's targets: each window's lowest and highest corners a block.
    struct Targets {
        std::vector<gl::Texture> lo, hi;
        gl::Framebuffer fbo{gl::NoCreate};
        glm::ivec2 blocks{0};
    };
    Targets one_, slices_;  ///< one window (SDSM_WINDOWS 1), kSlicesAPass windows
    gl::Buffer casters_{gl::NoCreate};  ///< fitOnGpu's caster boxes (and the large meshes')
    GLsizeiptr castersBytes_ = 0;
    /// The windows a reduction counts: `depths`, or (cascades not
    /// stabilised) kSlicesAPass slices from firstSlice on of the ones the
    /// GPU placed in `fit` (SdsmFit::sliceWindow).
    struct Windows {
        std::vector<glm::vec2> depths;
        const gl::Buffer* fit = nullptr;
        int firstSlice = 0, sliceCount = 0;
        int count() const { return fit ? kSlicesAPass : static_cast<int>(depths.size()); }
    };
    /// The reduction pass into `targets` (made or remade for this frame's
    /// size, a window each of `windows`).
    void draw(TechniqueHost& host, const FrameInfo& frame, const glm::mat4& lightFromWorld, const Windows& windows, Targets& targets);
    /// Cascades not stabilised, after their splits: each slice's samples
    /// reduced and its camera fitted to them (shadow_map_sdsm_fit.comp, SDSM_SLICE).
    void fitSlices(TechniqueHost& host, const FrameInfo& frame, const GpuFitInput& in, const gl::Buffer& out);
    /// The casters' boxes (lo, hi each), then the large meshes' world boxes, into casters_.
    void uploadBoxes(const FrameInfo& frame, const std::vector<Bounds>& casters, bool withBoxed);
    /// The large meshes' boxes (boxed_), cut to the view, into `b`
    /// (a slice's: shadow_map_sdsm_fit.comp, SDSM_SLICE).
    void addBoxed(Bounds& b, const FrameInfo& frame, const glm::mat4& lightFromWorld) const;
    glm::ivec2 size_{0};
    std::vector<std::size_t> boxed_;  ///< items in view left out of the pre-pass (kBoxedTriangles)
};

} // namespace shadowlab::map
