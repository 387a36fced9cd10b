// The frame-size limits (include/shadowlab/Limits.h).
#include <shadowlab/Limits.h>

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace shadowlab {

namespace {

// Bytes per output pixel, estimated: the colour, depth and G-buffer targets
// on the GPU (llvmpipe keeps them in system memory), their read-backs and
// CPU images, the reference's per-pixel buffers and the PNG encoder's copy.
constexpr double kBytesPerPixelEstimate = 64.0;
// Share of physical memory a frame may take.
constexpr double kMemoryBudgetShare = 0.5;

// "--width W --height H: the frame needs about N GiB (...), more than the
// budget of B GiB (what)", in GiB or in MiB under one.
[[noreturn]] void refuse(int width, int height, double needed, double budget, const std::string& what) {
    const bool gib = budget >= 1073741824.0;
    const double unit = gib ? 1073741824.0 : 1048576.0;
    char text[320];
    std::snprintf(text, sizeof text,
                  "--width %d --height %d: the frame needs about %.1f %s (estimated %.0f bytes per pixel), more than the budget of "
                  "%.1f %s (%s)",
                  width, height, needed / unit, gib ? "GiB" : "MiB", kBytesPerPixelEstimate, budget / unit, gib ? "GiB" : "MiB", what.c_str());
    throw Error(text);
}

double frameBytes(int width, int height) { return kBytesPerPixelEstimate * static_cast<double>(width) * static_cast<double>(height); }

} // namespace

// A 16384x16384 frame otherwise runs out of memory inside the driver after a minute.
void checkMemory(int width, int height) {
    double budget = 0.0;
    std::string what = "half of this machine's memory";
    if (const char* limit = std::getenv("SHADOWLAB_MEMORY_LIMIT_BYTES"); limit && *limit) {
        char* end = nullptr;
        budget = std::strtod(limit, &end);
        // Decimal digits only (no hex, no inf), at least 1 KiB and finite.
        const bool decimal = std::string(limit).find_first_not_of("0123456789.eE+") == std::string::npos;
        if (*end != '\0' || !decimal || !std::isfinite(budget) || !(budget >= 1024.0))
            throw Error(text::escapeControl(text::clipMiddle(std::string("SHADOWLAB_MEMORY_LIMIT_BYTES=") + limit)) +
                        ": expected a finite decimal number of bytes, at least 1024");
        what = "SHADOWLAB_MEMORY_LIMIT_BYTES";
    } else {
        const double pages = static_cast<double>(sysconf(_SC_PHYS_PAGES)), pageSize = static_cast<double>(sysconf(_SC_PAGE_SIZE));
        if (pages <= 0 || pageSize <= 0) return; // unknown: the GPU limit check still applies
        budget = kMemoryBudgetShare * pages * pageSize;
    }
    const double needed = frameBytes(width, height);
    if (needed > budget) refuse(width, height, needed, budget, what);
}

void checkReferenceRays(int width, int height, int samples) {
    constexpr double kMaxRays = 2147483648.0;  // 2^31: about two minutes of tracing on two cores
    const double rays = static_cast<double>(width) * static_cast<double>(height) * static_cast<double>(samples);
    if (rays > kMaxRays) {
        char text[160];
        std::snprintf(text, sizeof text, "%.3g rays for each soft light's reference, more than the limit of 2^31 (lower --samples, --width or --height)", rays);
        throw Error("--samples " + std::to_string(samples) + " at " + std::to_string(width) + "x" + std::to_string(height) + ": " + text);
    }
}

void checkSceneReferenceRays(int width, int height, int samples, std::size_t softLights) {
    constexpr double kMaxSceneRays = 4294967296.0;  // 2^32: about four minutes of tracing on two cores
    const double rays = static_cast<double>(width) * static_cast<double>(height) * static_cast<double>(samples) * static_cast<double>(softLights);
    if (rays > kMaxSceneRays) {
        char text[200];
        std::snprintf(text, sizeof text, "%.3g rays for the reference of %zu soft lights, more than the limit of 2^32 for a scene (lower --samples, --width or --height)",
                      rays, softLights);
        throw Error("--samples " + std::to_string(samples) + " at " + std::to_string(width) + "x" + std::to_string(height) + ": " + text);
    }
}

void checkSize(int width, int height, const GlInfo& info) {
    const int limit = std::min({info.maxTextureSize, info.maxViewportWidth, info.maxViewportHeight});
    if (width > limit) throw Error("--width " + std::to_string(width) + ": exceeds this GPU's limit of " + std::to_string(limit) + " pixels");
    if (height > limit) throw Error("--height " + std::to_string(height) + ": exceeds this GPU's limit of " + std::to_string(limit) + " pixels");
    // The device's own memory, where the driver reports it (a GPU with less
    // memory than half of the host's would otherwise fail inside the driver).
    const double device = static_cast<double>(info.deviceMemoryBytes);
    if (device > 0.0 && frameBytes(width, height) > device)
        refuse(width, height, frameBytes(width, height), device, "the device's free memory, as " + info.deviceMemorySource + " reports it");
}

} // namespace shadowlab
