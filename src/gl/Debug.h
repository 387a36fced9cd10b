#pragma once
// KHR_debug output: messages to stderr, errors counted so tests can fail on them.
#include "gl/Program.h"

#include <shadowlab/Context.h>

#include <atomic>
#include <mutex>
#include <string>

namespace shadowlab::gl {

struct DebugState {
    bool verbose = false;
    std::atomic<std::size_t> errors{0};
    std::mutex mutex;
    std::string lastError;
};

} // namespace shadowlab::gl

namespace shadowlab {
/// What every kind of context holds; EGL and GLFW derive from it.
struct Context::Impl {
    GlInfo info;
    gl::DebugState debug;
    /// Programs live as long as the context; derived destructors call
    /// releaseGlObjects() while the context still exists.
    std::unique_ptr<gl::ProgramCache> programs = std::make_unique<gl::ProgramCache>();
    void releaseGlObjects() { programs.reset(); }
    virtual ~Impl() = default;
    virtual void makeCurrent() = 0;
    virtual GLFWwindow* window() const { return nullptr; }
};
} // namespace shadowlab

namespace shadowlab::gl {

/// Installs the debug callback on the current context (synchronous output).
void installDebugOutput(DebugState& state);
/// Fills GlInfo from the current context (platform left to the caller).
GlInfo queryGlInfo();
/// Throws shadowlab::Error unless the current context is 4.5 core or newer.
void requireGl45(const char* platform);

} // namespace shadowlab::gl
