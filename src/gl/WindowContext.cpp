#include "gl/WindowContext.h"

#include <shadowlab/Error.h>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

namespace shadowlab::gl {

WindowContext::WindowContext(int width, int height, const std::string& title, const ContextOptions& options) {
    debug_->verbose = options.verbose;
    if (!glfwInit()) {
        const char* description = nullptr;
        glfwGetError(&description);
        throw Error(std::string("glfw: cannot initialise (") + (description ? description : "no display?") + ")");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const char* description = nullptr;
        glfwGetError(&description);
        glfwTerminate();
        throw Error(std::string("glfw: no OpenGL 4.5 core window (") + (description ? description : "unknown") + ")");
    }
    glfwMakeContextCurrent(window_);
    try {
        requireGl45("glfw");
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
    info_ = queryGlInfo();
    info_.platform = "glfw";
    if (options.debug) installDebugOutput(*debug_);
}

WindowContext::~WindowContext() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_); }
void WindowContext::swapBuffers() { glfwSwapBuffers(window_); }

} // namespace shadowlab::gl
