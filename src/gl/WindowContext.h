#pragma once
// A GLFW window with an OpenGL 4.5 core context, for the interactive viewer.
// Draws with the same renderer code as the headless context.
#include "gl/Debug.h"

#include <shadowlab/Context.h>

#include <memory>
#include <string>

struct GLFWwindow;

namespace shadowlab::gl {

class WindowContext {
public:
    /// Opens a window of `width` x `height` screen coordinates. Throws
    /// shadowlab::Error when there is no display or no OpenGL 4.5 core.
    WindowContext(int width, int height, const std::string& title, const ContextOptions& options = {});
    ~WindowContext();
    WindowContext(const WindowContext&) = delete;
    WindowContext& operator=(const WindowContext&) = delete;

    GLFWwindow* window() const { return window_; }
    const GlInfo& info() const { return info_; }
    bool shouldClose() const;
    void swapBuffers();
    std::size_t debugErrorCount() const { return debug_->errors.load(); }

private:
    GLFWwindow* window_ = nullptr;
    GlInfo info_;
    std::unique_ptr<DebugState> debug_ = std::make_unique<DebugState>();
};

} // namespace shadowlab::gl
