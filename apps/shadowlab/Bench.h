#pragma once
// shadowlab bench: time and accuracy for every combination of varied
// settings over a set of scenes; results.json and a self-contained report.html.
#include <shadowlab/Context.h>
#include <shadowlab/Renderer.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab::tool {

struct BenchArgs {
    std::vector<std::string> scenes;     ///< scene files; empty = the built-in default scene
    std::vector<std::string> overrides;  ///< --set, for every combination
    std::vector<std::string> vary;       ///< --vary key=v1,v2,...
    int frames = 10;                     ///< timed frames per combination
    int warmup = 2;                      ///< untimed frames first (shader compilation, caches)
    int width = 960, height = 540;
    int softSamples = 256;
    /// Per-pass clock (--clock): Auto = glFinish-bracketed CPU time on a
    /// software rasteriser, timestamp queries on a GPU.
    TimingClock clock = TimingClock::Auto;
    std::filesystem::path output = "bench";
};

/// One --vary: a JSON path and its values (JSON text, split at top-level commas).
struct Variation {
    std::string key;
    std::vector<std::string> values;
};

/// Parses `key=v1,v2` (commas inside [] {} "" do not split). Throws Error naming the flag.
Variation parseVariation(const std::string& text);
/// Every combination of the variations' values as `key=value` overrides (cartesian product).
std::vector<std::vector<std::string>> combinations(const std::vector<Variation>& variations);

/// Runs the benchmark; returns results.json's content.
nlohmann::json runBench(Context& context, const BenchArgs& args);

/// Writes report.html from results.json's content into `directory`.
void writeReport(const nlohmann::json& results, const std::filesystem::path& directory);

} // namespace shadowlab::tool
