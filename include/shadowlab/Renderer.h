#pragma once
/// @file Renderer.h
/// Draws a Scene with each light's shadow technique into an offscreen image.
///
/// Passes per frame: for each light whose technique has one, its shadow
/// pass ("shadow[i]"); the base pass ("base": depth, stencil cleared, the
/// ambient term, and the first light whose technique can share it); for
/// each further light its technique's light pass ("light[i]"), added on the
/// base pass's depth. Colour is written as 8-bit sRGB with lit passes
/// blended in linear light, so there is no separate resolve pass.
#include <shadowlab/Export.h>
#include <shadowlab/Context.h>
#include <shadowlab/DebugImage.h>
#include <shadowlab/Scene.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab {

/// How per-pass times are taken (see docs/metrics.md).
enum class TimingClock {
    Off,          ///< no per-pass times (names only, 0 ms)
    Auto,         ///< CpuFinish on a software rasteriser (llvmpipe ...), GpuTimestamp on a GPU
    CpuFinish,    ///< glFinish around each pass, CPU clock: honest where rasterisation is deferred
    GpuTimestamp, ///< GL_TIMESTAMP queries around each pass: no stalls, for GPUs
};

struct RenderOptions {
    int width = 1280;   ///< pixels, 1 .. GL_MAX_TEXTURE_SIZE; default 1280
    int height = 720;   ///< pixels, 1 .. GL_MAX_TEXTURE_SIZE; default 720
    /// Per-pass times in FrameStats::passes. Default Off: a frame as lean as it gets.
    TimingClock clock = TimingClock::Off;
    /// Also write each pixel's world position and geometric normal, for
    /// readSurfaces() and the ray-traced reference. Default off (it costs
    /// two float targets per frame).
    bool surfaces = false;
    /// Seconds since the start of an animation, handed to techniques
    /// (FrameInfo::timeSeconds). render() draws each Light::position as it
    /// is: move animated lights first with sceneAtTime() / lightAtTime()
    /// (Scene.h) at the same time. Default 0.
    double timeSeconds = 0.0;
    /// Techniques also time the floor of their passes (e.g. a bare
    /// depth-only draw of the same casters into a target of the same size),
    /// as nested "floor" scopes: what a pass cannot beat. Default off (bench turns it on).
    bool measureFloors = false;
    /// Draw this frame through the previous frame's shadow maps: no shadow
    /// pass runs and each map keeps its light camera (its fit to the earlier
    /// view), so the same world points can be read through two frames' maps
    /// (bench --flips). Throws shadowlab::Error when a light's technique has
    /// no such map from the previous frame. Default off.
    bool reuseShadowMaps = false;
    /// Keep a light's shadow map from the previous frame when nothing it is
    /// drawn from changed: the light, its map options, the casters and
    /// receivers (meshes, transforms, shadow flags, alpha materials), the
    /// camera and the frame's size (the fits follow the view), the upload.
    /// Technique "map"; a kept map's pass is not drawn (FrameStats counts
    /// "shadow[i].cached"). Default off: bench's frameMs redraws every map
    /// and reports the cached frame beside it; the viewer turns it on.
    bool cacheShadowMaps = false;
    /// Lights without shadows (technique "none") beyond the one the base
    /// pass shades are shaded together in one pass, "lights", each pixel
    /// looping over the lights whose reach overlaps its 16x16 tile (binned
    /// on the CPU from each light's range), when there are two or more of
    /// them. Off: a pass each, "light[i]", as for shadowed lights. The sums
    /// differ from a pass each only by rounding (one sRGB encoding instead
    /// of one per light). Default on.
    bool groupLights = true;
    /// The base pass runs its light's shadow test only inside the screen
    /// rectangles that the light's technique says its shadows can fall in
    /// this frame (technique "map" with one 2D map or a cube, and "disc":
    /// around the screen image of each caster's box swept away from the
    /// light, widened by the filter's reach); it shades the pixels outside
    /// as lit, without the test, which would find them lit: the same image
    /// for less (FrameStats counts "base.shadowedShare", the rectangles'
    /// share of the frame, when it used them: not over nine tenths of it).
    /// Items that receive no shadows are shaded without the test too. Off:
    /// the test at every pixel. Default on.
    /// Likewise the shadow pass of stabilised cascades (technique "map")
    /// clears and draws only the texels of each cascade that the frame's
    /// lookups can read (around the receivers the view sees in its slice;
    /// FrameStats counts "shadow[i].cascadeN.drawnShare"). Off: every texel.
    bool shadowRegions = true;
};

struct PassTiming {
    std::string name;   ///< "shadow[i]", "base", "light[i]", nested scopes as "shadow[i].blur"
    double ms = 0.0;    ///< milliseconds by FrameStats::clock; 0 when Off
};

struct FrameStats {
    std::vector<PassTiming> passes;
    std::string clock = "off"; ///< "cpu-finish", "gpu-timestamp" or "off"
    int baseLight = -1;        ///< the light shaded inside the base pass (no "light[i]" of its own), -1 none
    /// Numbers the techniques report per pass, e.g. {"shadow[0].triangles", 12}.
    std::vector<std::pair<std::string, double>> counters;
    double cpuMs = 0.0;        ///< wall time of render() including glFinish, milliseconds
    /// What techniques noticed about the scene this frame, one line each
    /// (e.g. a shadow-volume caster that is not a closed mesh); no repeats.
    std::vector<std::string> notes;
};

/// What the base pass saw at each pixel, rows top to bottom.
struct SurfaceBuffer {
    int width = 0, height = 0;
    std::vector<glm::vec4> position; ///< world xyz, w = 1 where geometry was drawn, 0 on background
    std::vector<glm::vec4> normal;   ///< geometric normal facing the camera, w = 1 if the surface receives shadows
};

/// One camera a technique rendered from a light (a shadow map's frustum).
struct LightFrustum {
    int light = 0;                    ///< into Scene::lights
    glm::mat4 clipFromWorld{1.0f};    ///< its volume is clip space's [-1, 1]^3
};

class SHADOWLAB_API Renderer {
public:
    /// Needs `context` current on this thread for the Renderer's lifetime.
    explicit Renderer(Context& context);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Uploads the scene's meshes and textures. Call again when they change;
    /// camera, lights, materials and node transforms are read at each render().
    void upload(const Scene& scene);
    /// Renders a frame of the uploaded scene. Throws shadowlab::Error for a
    /// size beyond the GPU's limits or a scene other than the uploaded one.
    FrameStats render(const Scene& scene, const RenderOptions& options = {});
    /// Renders the frame as render() does, but each light's visibility comes
    /// from `visibility[i]` (width*height values in [0,1], rows top to
    /// bottom) instead of its technique: the exact reference image, lit by
    /// the same shading code. Shadow passes are skipped.
    FrameStats renderWithVisibility(const Scene& scene, const RenderOptions& options,
                                    const std::vector<std::vector<float>>& visibility);
    /// Light `light`'s visibility term (1 lit, 0 shadowed) at each pixel of
    /// the last frame as its technique computes it, rows top to bottom; 0 on
    /// the background. Coloured techniques: the mean of the three channels.
    /// Call after render() with the same scene.
    std::vector<float> readVisibility(const Scene& scene, std::size_t light);
    /// The same per channel (transmittance through coloured casters).
    std::vector<glm::vec3> readVisibilityRgb(const Scene& scene, std::size_t light);
    /// Every technique's debug images for the last frame, named by light;
    /// only those of the kinds in `kinds` (default: every kind), the others
    /// not made at all (compare asks for the texel density alone).
    std::vector<DebugImage> debugImages(const Scene& scene, const DebugImageKinds& kinds = {});
    /// The light cameras the techniques used in the last frame (each 2D
    /// map's frustum, a cube map's six faces), light by light.
    std::vector<LightFrustum> lightFrustums(const Scene& scene) const;
    /// The last frame, 8-bit sRGB, rows top to bottom.
    ImageRGBA8 readColor() const;
    /// Copies the last frame, sRGB-encoded as readColor() has it, into the
    /// current context's default framebuffer at (0, 0), one pixel for one
    /// (a window shows exactly what readColor() would return).
    void blitToDefaultFramebuffer() const;
    /// The last frame's per-pixel surface data (for the ray-traced
    /// reference). Throws unless it was rendered with RenderOptions::surfaces.
    SurfaceBuffer readSurfaces() const;

private:
    struct SHADOWLAB_HIDDEN Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace shadowlab
