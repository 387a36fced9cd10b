#pragma once
// KHR_debug output: messages to stderr, errors counted so tests can fail on them.
#include "gl/Program.h"

#include <shadowlab/Context.h>

#include <atomic>
#include <functional>
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
    /// The caller's context (Context::adoptCurrent): calls put its GL state back.
    bool adopted = false;
    void releaseGlObjects() { programs.reset(); }
    virtual ~Impl() = default;
    virtual void makeCurrent() = 0;
    virtual void releaseCurrent() = 0;
    virtual GLFWwindow* window() const { return nullptr; }
};
} // namespace shadowlab

namespace shadowlab::gl {

/// Installs the debug callback on the current context (synchronous output).
void installDebugOutput(DebugState& state);
/// Free device memory as the driver reports it: GL_NVX_gpu_memory_info's
/// current available video memory, else GL_ATI_meminfo's free texture
/// memory (both in KiB); {0, ""} when neither extension is there. The
/// queries are parameters so that tests can feed a driver that has them.
struct DeviceMemory {
    long long bytes = 0;
    std::string source;
};
DeviceMemory queryDeviceMemory(const std::function<bool(const char*)>& hasExtension,
                               const std::function<void(unsigned pname, int* values)>& getIntegerv);

/// Throws shadowlab::Error naming `where` if GL recorded GL_OUT_OF_MEMORY
/// since the last call (other errors are left to the debug output); clears
/// GL's error flags. The debug output does not print GL_OUT_OF_MEMORY: this
/// check, or the run's final count of GL errors, says it in one line.
void throwIfOutOfMemory(const char* where);

/// While one lives on this thread, the debug callback prints nothing (it
/// still counts errors): around a call whose outcome the caller reports in
/// its own words, such as a framebuffer's completeness.
class QuietDebugOutput {
public:
    QuietDebugOutput();
    ~QuietDebugOutput();
    QuietDebugOutput(const QuietDebugOutput&) = delete;
    QuietDebugOutput& operator=(const QuietDebugOutput&) = delete;

private:
    bool wasQuiet_;
};

/// Fills GlInfo from the current context (platform left to the caller).
GlInfo queryGlInfo();
/// Throws shadowlab::Error unless the current context is 4.5 core or newer.
void requireGl45(const char* platform);

} // namespace shadowlab::gl
