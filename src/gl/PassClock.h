#pragma once
// Per-pass times that land where the work is.
//
// GL_TIME_ELAPSED is not honest on a renderer that defers rasterisation:
// Mesa's llvmpipe queues a pass's triangles and rasterises them when
// something forces it (the next pass's state change, a flush, a read), so a
// query around one pass can be charged the previous pass's work. Measured
// here: turning off the base pass's extra outputs moved `light[0]` from
// 10-15 ms to 0.3-3 ms while `base` stayed put. So on a software renderer
// each pass is bracketed by glFinish and timed on the CPU (CpuFinish); on a
// GPU, timestamp queries (which, unlike GL_TIME_ELAPSED, may nest) bracket it.
#include "gl/Object.h"

#include <string>
#include <utility>
#include <vector>

namespace shadowlab::gl {

enum class ClockKind {
    Off,          ///< names recorded, times 0
    CpuFinish,    ///< glFinish before and after, steady_clock in between
    GpuTimestamp, ///< glQueryCounter(GL_TIMESTAMP) before and after
};

/// "cpu-finish", "gpu-timestamp" or "off": the name results.json records.
const char* toString(ClockKind kind);
/// Whether GL_RENDERER names a software rasteriser (llvmpipe, softpipe,
/// swr, lavapipe), which rasterises on the CPU and defers the work.
bool isSoftwareRasterizer(const std::string& glRenderer);
/// CpuFinish for a software rasteriser, GpuTimestamp otherwise.
ClockKind clockFor(const std::string& glRenderer);

/// Times nested scopes of a frame: begin("shadow[0]") ... begin("moments") ...
/// end() end() records "shadow[0]" and "shadow[0].moments".
class PassClock {
public:
    explicit PassClock(ClockKind kind) : kind_(kind) {}
    ClockKind kind() const { return kind_; }
    void begin(const std::string& name);
    void end();
    /// (name, milliseconds) in the order the scopes began. Waits for GPU
    /// queries. Throws shadowlab::Error if a scope is still open.
    std::vector<std::pair<std::string, double>> results();

private:
    struct Scope {
        std::string name;
        double cpuStartMs = 0.0, cpuMs = 0.0;
        Query start{NoCreate}, stop{NoCreate};
    };
    ClockKind kind_;
    std::vector<Scope> scopes_;
    std::vector<std::size_t> open_;
};

/// Ends a PassClock scope when it goes out of scope (no-op when empty).
class ScopedPass {
public:
    ScopedPass() = default;
    ScopedPass(PassClock& clock, const std::string& name) : clock_(&clock) { clock.begin(name); }
    ~ScopedPass() { if (clock_) clock_->end(); }
    ScopedPass(ScopedPass&& other) noexcept : clock_(std::exchange(other.clock_, nullptr)) {}
    ScopedPass& operator=(ScopedPass&&) = delete;
    ScopedPass(const ScopedPass&) = delete;
    ScopedPass& operator=(const ScopedPass&) = delete;

private:
    PassClock* clock_ = nullptr;
};

} // namespace shadowlab::gl
