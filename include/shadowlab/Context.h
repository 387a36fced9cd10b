#pragma once
/// @file Context.h
/// An OpenGL 4.5 core context. Everything shadowlab draws needs one current
/// on the calling thread.
#include <shadowlab/Export.h>
#include <cstddef>
#include <memory>
#include <string>

struct GLFWwindow;

namespace shadowlab {

struct ContextOptions {
    /// Request a debug context and route KHR_debug messages to stderr
    /// (errors always, other messages when `verbose`). Default on.
    bool debug = true;
    /// Also print KHR_debug messages of low/notification severity. Default off.
    bool verbose = false;
};

/// What the driver reports, and the limits techniques must respect.
struct GlInfo {
    std::string vendor, renderer, version, glslVersion;
    std::string platform;       ///< "egl-surfaceless", "egl-device" or "glfw"
    int maxTextureSize = 0;     ///< GL_MAX_TEXTURE_SIZE, texels
    int maxCubeMapSize = 0;     ///< GL_MAX_CUBE_MAP_TEXTURE_SIZE, texels
    int maxArrayLayers = 0;     ///< GL_MAX_ARRAY_TEXTURE_LAYERS
    int maxRenderbufferSize = 0;///< GL_MAX_RENDERBUFFER_SIZE
    int maxViewportWidth = 0, maxViewportHeight = 0;
    /// Device memory free when the context was made, bytes, as the driver
    /// reports it (GL_NVX_gpu_memory_info's current available video memory,
    /// else GL_ATI_meminfo's free texture memory); 0 when it reports none
    /// (llvmpipe, which uses host memory).
    long long deviceMemoryBytes = 0;
    std::string deviceMemorySource; ///< the extension deviceMemoryBytes came from (or SHADOWLAB_DEVICE_MEMORY_KIB when that stands in for it), or ""
};

/// A headless context: EGL on Mesa's surfaceless platform (llvmpipe where
/// there is no GPU), else the EGL device platform (NVIDIA headless). The
/// environment variable SHADOWLAB_EGL_PLATFORM=surfaceless|device forces one.
/// Throws shadowlab::Error when no OpenGL 4.5 core context can be made,
/// naming the version that was found.
/// GL objects (buffers, textures, framebuffers, programs ...) the library
/// holds right now, over all contexts: for leak checks (a scene reloaded a
/// hundred times must not grow it).
SHADOWLAB_API long liveGlObjects();

class SHADOWLAB_API Context {
public:
    static Context createHeadless(const ContextOptions& options = {});
    /// A window of `width` x `height` screen coordinates with an OpenGL 4.5
    /// core context (GLFW), for the interactive viewer; all rendering code is
    /// the same as headless. Throws shadowlab::Error when there is no display,
    /// no OpenGL 4.5 core, or the build has SHADOWLAB_BUILD_VIEWER off.
    static Context createWindow(int width, int height, const std::string& title, const ContextOptions& options = {});
    /// The OpenGL 4.5 core context current on the calling thread, made by
    /// the caller (GLFW, SDL, Qt, its own EGL or GLX): shadowlab draws into
    /// it and owns nothing of it. Every Renderer call on an adopted context
    /// puts back the GL state it changes (bindings of framebuffers, program,
    /// vertex array and buffers, textures and samplers on units 0-31, the
    /// active unit, viewport and scissor, depth, stencil, blend, cull and
    /// polygon-offset state and masks, clip distances, depth clamp,
    /// seamless cube maps, clip control, sRGB writes, pixel-store
    /// alignment, clear values), so the caller's next draw is unaffected.
    /// With options.debug, shadowlab's KHR_debug callback replaces the
    /// caller's until the Context is destroyed, which puts the caller's
    /// back. makeCurrent() checks that the context is still current (it
    /// cannot make it so); releaseCurrent() does nothing; destroying the
    /// Context leaves the GL context to the caller. Throws shadowlab::Error
    /// when no context is current or it is not OpenGL 4.5 core.
    static Context adoptCurrent(const ContextOptions& options = {});

    Context(Context&&) noexcept;
    Context& operator=(Context&&) noexcept;
    ~Context();

    const GlInfo& info() const;
    void makeCurrent();
    /// Makes no context current on this thread, so that another thread
    /// may make this one current (a context is current on one thread at a
    /// time); drop everything made with it (Renderer) first.
    void releaseCurrent();
    /// GL errors reported through KHR_debug since creation or the last reset.
    std::size_t debugErrorCount() const;
    /// The most recent KHR_debug error message, empty if none.
    std::string lastDebugError() const;
    void resetDebugErrors();
    /// The window of a createWindow context, nullptr when headless.
    GLFWwindow* window() const;

    struct SHADOWLAB_HIDDEN Impl;
    explicit Context(std::unique_ptr<Impl> impl);
    /// The implementation (library-internal: program cache, debug state).
    Impl& impl() { return *impl_; }

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace shadowlab
