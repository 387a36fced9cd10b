// Fuzz target: a scene file with --set overrides. The input is the JSON
// text, optionally followed by a NUL byte and NUL-separated overrides.
// Relative mesh and texture paths resolve in fuzz/corpus/files/, so the
// scene loader reaches the OBJ and glTF loaders with real files.
// Expected failures throw shadowlab::Error; anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding.
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    std::vector<std::string> overrides;
    for (std::size_t at = nul; at != std::string::npos;) {
        const std::size_t next = input.find('\0', at + 1);
        overrides.push_back(input.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
        at = next;
    }
    try {
        const shadowlab::Scene scene = shadowlab::parseScene(input.substr(0, nul), "fuzz.json", SHADOWLAB_FUZZ_FILES_DIR, overrides);
        // Animated lights and camera: a parsed path evaluates at any finite
        // time without an error, every position it reaches is finite, and the
        // camera has a view (a finite view matrix) everywhere on its path.
        constexpr double kTimes[] = {-1e9, -1.5, 0.0, 0.25, 0.5, 1.0 / 3.0, 7.0, 1e9};
        for (const shadowlab::Light& light : scene.lights)
            for (const double t : kTimes) {
                const glm::vec3 p = shadowlab::lightAtTime(light, t).position;
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
            }
        for (const double t : kTimes) {
            const glm::mat4 view = shadowlab::cameraAtTime(scene.camera, t).viewFromWorld();
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    if (!std::isfinite(view[c][r])) __builtin_trap();
        }
    } catch (const shadowlab::Error&) {
    }
    return 0;
}
