#pragma once
/// @file Renderer.h
/// Draws a Scene with each light's shadow technique into an offscreen image.
///
/// Passes per frame: for each light its technique's shadow pass (if any);
/// the base pass (depth, ambient term, world position and normal); for each
/// light an additive Blinn-Phong pass scaled by the technique's visibility;
/// the resolve to 8-bit sRGB.
#include <shadowlab/Context.h>
#include <shadowlab/Scene.h>

#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

struct RenderOptions {
    int width = 1280;   ///< pixels, 1 .. GL_MAX_TEXTURE_SIZE; default 1280
    int height = 720;   ///< pixels, 1 .. GL_MAX_TEXTURE_SIZE; default 720
    /// Measure each pass's GPU time with GL_TIME_ELAPSED queries (waits for
    /// the results at the end of the frame). Default off.
    bool measureGpuTime = false;
};

struct PassTiming {
    std::string name;   ///< "shadow[i]", "base", "light[i]", "resolve"
    double gpuMs = 0.0; ///< milliseconds; 0 when not measured
};

struct FrameStats {
    std::vector<PassTiming> passes;
    double cpuMs = 0.0; ///< wall time of render() including glFinish, milliseconds
};

/// What the base pass saw at each pixel, rows top to bottom.
struct SurfaceBuffer {
    int width = 0, height = 0;
    std::vector<glm::vec4> position; ///< world xyz, w = 1 where geometry was drawn, 0 on background
    std::vector<glm::vec4> normal;   ///< geometric normal facing the camera, w = 1 if the surface receives shadows
};

class Renderer {
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
    /// the background. Call after render() with the same scene.
    std::vector<float> readVisibility(const Scene& scene, std::size_t light);
    /// The last frame, 8-bit sRGB, rows top to bottom.
    ImageRGBA8 readColor() const;
    /// The last frame's per-pixel surface data (for the ray-traced reference).
    SurfaceBuffer readSurfaces() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace shadowlab
