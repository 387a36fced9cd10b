// A GLFW window with an OpenGL 4.5 core context, for the interactive viewer.
// The Renderer draws into it exactly as into the headless context.
#include "gl/Debug.h"

#include <shadowlab/Context.h>
#include <shadowlab/Error.h>

#if SHADOWLAB_HAS_GLFW
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
#endif

namespace shadowlab {

#if SHADOWLAB_HAS_GLFW
namespace {

std::string glfwErrorText() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown error";
}

struct GlfwImpl final : Context::Impl {
    GLFWwindow* handle = nullptr;
    void makeCurrent() override { glfwMakeContextCurrent(handle); }
    void releaseCurrent() override { glfwMakeContextCurrent(nullptr); }
    GLFWwindow* window() const override { return handle; }
    ~GlfwImpl() override {
        if (handle) {
            glfwMakeContextCurrent(handle);
            releaseGlObjects();
            glfwDestroyWindow(handle);
        }
        glfwTerminate();
    }
};

} // namespace

Context Context::createWindow(int width, int height, const std::string& title, const ContextOptions& options) {
    if (width < 1 || height < 1) throw Error("window size " + std::to_string(width) + "x" + std::to_string(height) + ": expected at least 1x1");
    if (!glfwInit()) throw Error("glfw: cannot initialise (" + glfwErrorText() + "); is there a display?");
    auto impl = std::make_unique<GlfwImpl>();  // from here on its destructor calls glfwTerminate
    impl->debug.verbose = options.verbose;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    impl->handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!impl->handle) throw Error("glfw: no window with OpenGL 4.5 core (" + glfwErrorText() + ")");
    glfwMakeContextCurrent(impl->handle);
    gl::requireGl45("glfw");
    impl->info = gl::queryGlInfo();
    impl->info.platform = "glfw";
    if (options.debug) gl::installDebugOutput(impl->debug);
    return Context(std::move(impl));
}
#else
Context Context::createWindow(int, int, const std::string&, const ContextOptions&) {
    throw Error("this build has no window support (configure with -DSHADOWLAB_BUILD_VIEWER=ON)");
}
#endif

} // namespace shadowlab
