// Headless OpenGL 4.5 core context through EGL: Mesa's surfaceless platform
// (llvmpipe without a GPU) or the EGL device platform (NVIDIA headless).
// No surface: all rendering goes to framebuffer objects.
#include "gl/Debug.h"

#include <shadowlab/Context.h>
#include <shadowlab/Error.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <string>
#include <vector>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

namespace shadowlab {

namespace {
std::string eglErrorText();
}

struct EglImpl final : Context::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;

    void makeCurrent() override {
        if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
            throw Error("eglMakeCurrent failed (" + eglErrorText() + ")");
    }
    void releaseCurrent() override { eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
    ~EglImpl() override {
        if (display != EGL_NO_DISPLAY && context != EGL_NO_CONTEXT &&
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
            releaseGlObjects();
        if (display != EGL_NO_DISPLAY) {
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
            eglTerminate(display);
        }
    }
};

namespace {

std::string eglErrorText() {
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04X", eglGetError());
    return buf;
}

EGLDisplay openSurfaceless() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
    return eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

EGLDisplay openDevice() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") ||
        !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device"))
        return EGL_NO_DISPLAY;
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (count <= 0 || !eglQueryDevicesEXT(count, devices.data(), &count)) return EGL_NO_DISPLAY;
    for (EGLDeviceEXT device : devices) {
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (display != EGL_NO_DISPLAY) return display;
    }
    return EGL_NO_DISPLAY;
}

// Creates a context on an initialised display; returns EGL_NO_CONTEXT on failure.
EGLContext createContext(EGLDisplay display, bool debug, EGLint major, EGLint minor, bool core) {
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint numConfigs = 0;
    EGLConfig* configPtr = &config;
    // Surfaceless contexts may use EGL_NO_CONFIG_KHR; prefer a real config when one exists.
    if (!eglChooseConfig(display, configAttribs, configPtr, 1, &numConfigs) || numConfigs == 0) config = nullptr;
    std::vector<EGLint> attribs;
    if (major > 0) {
        attribs.insert(attribs.end(), {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor});
        attribs.insert(attribs.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       core ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT});
        if (debug) attribs.insert(attribs.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
    }
    attribs.push_back(EGL_NONE);
    return eglCreateContext(display, config, EGL_NO_CONTEXT, attribs.data());
}

} // namespace

Context Context::createHeadless(const ContextOptions& options) {
    auto impl = std::make_unique<EglImpl>();
    impl->debug.verbose = options.verbose;
    const char* forced = std::getenv("SHADOWLAB_EGL_PLATFORM");
    const std::string want = forced ? forced : "";
    if (!want.empty() && want != "surfaceless" && want != "device")
        throw Error("SHADOWLAB_EGL_PLATFORM: expected 'surfaceless' or 'device', got '" + want + "'");

    std::string platform;
    std::string tried;
    for (const std::string candidate : {"surfaceless", "device"}) {
        if (!want.empty() && candidate != want) continue;
        EGLDisplay display = candidate == "surfaceless" ? openSurfaceless() : openDevice();
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
            tried += (tried.empty() ? "" : ", ") + candidate + " (no display)";
            continue;
        }
        impl->display = display;
        platform = "egl-" + candidate;
        break;
    }
    if (impl->display == EGL_NO_DISPLAY)
        throw Error("EGL: no headless display could be opened (tried " + (tried.empty() ? std::string("none") : tried) +
                    "); install Mesa's EGL (libegl-mesa0) or a GPU driver with EGL");
    if (!eglBindAPI(EGL_OPENGL_API)) throw Error("EGL: desktop OpenGL not supported (" + eglErrorText() + ")");

    impl->context = createContext(impl->display, options.debug, 4, 5, true);
    if (impl->context == EGL_NO_CONTEXT) {
        // Report what the driver does offer.
        std::string found = "no OpenGL context at all";
        EGLContext fallback = createContext(impl->display, false, 0, 0, false);
        if (fallback != EGL_NO_CONTEXT && eglMakeCurrent(impl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, fallback)) {
            const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
            found = "'" + std::string(v ? v : "?") + "'";
            eglMakeCurrent(impl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        if (fallback != EGL_NO_CONTEXT) eglDestroyContext(impl->display, fallback);
        throw Error(platform + ": OpenGL 4.5 core is required, found " + found);
    }
    if (!eglMakeCurrent(impl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl->context))
        throw Error(platform + ": eglMakeCurrent without a surface failed (" + eglErrorText() + ")");
    gl::requireGl45(platform.c_str());
    impl->info = gl::queryGlInfo();
    impl->info.platform = platform;
    if (options.debug) gl::installDebugOutput(impl->debug);
    return Context(std::move(impl));
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&&) noexcept = default;
Context::~Context() = default;

const GlInfo& Context::info() const { return impl_->info; }
void Context::makeCurrent() { impl_->makeCurrent(); }
void Context::releaseCurrent() { impl_->releaseCurrent(); }
GLFWwindow* Context::window() const { return impl_->window(); }
std::size_t Context::debugErrorCount() const { return impl_->debug.errors.load(); }
std::string Context::lastDebugError() const {
    std::lock_guard lock(impl_->debug.mutex);
    return impl_->debug.lastError;
}
void Context::resetDebugErrors() {
    impl_->debug.errors = 0;
    std::lock_guard lock(impl_->debug.mutex);
    impl_->debug.lastError.clear();
}

} // namespace shadowlab
