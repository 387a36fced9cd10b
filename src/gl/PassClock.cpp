#include "gl/PassClock.h"

#include <shadowlab/Error.h>

#include <algorithm>
#include <cctype>
#include <chrono>

namespace shadowlab::gl {

namespace {
double nowMs() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
} // namespace

const char* toString(ClockKind kind) {
    switch (kind) {
    case ClockKind::Off: return "off";
    case ClockKind::CpuFinish: return "cpu-finish";
    case ClockKind::GpuTimestamp: return "gpu-timestamp";
    }
    return "?";
}

bool isSoftwareRasterizer(const std::string& glRenderer) {
    std::string r = glRenderer;
    std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* software : {"llvmpipe", "softpipe", "swr", "lavapipe", "software rasterizer"})
        if (r.find(software) != std::string::npos) return true;
    return false;
}

ClockKind clockFor(const std::string& glRenderer) {
    return isSoftwareRasterizer(glRenderer) ? ClockKind::CpuFinish : ClockKind::GpuTimestamp;
}

void PassClock::begin(const std::string& name) {
    Scope scope;
    scope.name = open_.empty() ? name : scopes_[open_.back()].name + "." + name;
    if (kind_ == ClockKind::CpuFinish) {
        glFinish();  // the work queued before this scope is not its own
        scope.cpuStartMs = nowMs();
    } else if (kind_ == ClockKind::GpuTimestamp) {
        scope.start = Query(GL_TIMESTAMP);
        scope.stop = Query(GL_TIMESTAMP);
        glQueryCounter(scope.start.id(), GL_TIMESTAMP);
    }
    open_.push_back(scopes_.size());
    scopes_.push_back(std::move(scope));
}

void PassClock::end() {
    if (open_.empty()) throw Error("PassClock::end without begin");
    Scope& scope = scopes_[open_.back()];
    open_.pop_back();
    if (kind_ == ClockKind::CpuFinish) {
        glFinish();  // everything this scope queued has been rasterised
        scope.cpuMs = nowMs() - scope.cpuStartMs;
    } else if (kind_ == ClockKind::GpuTimestamp) {
        glQueryCounter(scope.stop.id(), GL_TIMESTAMP);
    }
}

std::vector<std::pair<std::string, double>> PassClock::results() {
    if (!open_.empty()) throw Error("PassClock: scope '" + scopes_[open_.back()].name + "' was not ended");
    std::vector<std::pair<std::string, double>> out;
    for (Scope& s : scopes_) {
        double ms = s.cpuMs;
        if (kind_ == ClockKind::GpuTimestamp) {
            GLuint64 a = 0, b = 0;
            glGetQueryObjectui64v(s.start.id(), GL_QUERY_RESULT, &a);
            glGetQueryObjectui64v(s.stop.id(), GL_QUERY_RESULT, &b);
            ms = b > a ? static_cast<double>(b - a) * 1e-6 : 0.0;
        }
        out.emplace_back(s.name, ms);
    }
    return out;
}

} // namespace shadowlab::gl
