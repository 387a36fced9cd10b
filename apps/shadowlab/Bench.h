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
    /// Seconds since the start of the animation (--time): the lights' and
    /// the camera's paths are evaluated at timeSeconds for the warm-up frames
    /// and the accuracy comparison, and at timeSeconds + k / fps for timed
    /// frame k. Default 0.
    double timeSeconds = 0.0;
    double fps = 30.0;                   ///< frames per second of the timed sequence (--fps), > 0; default 30
    /// Temporal stability (--flips): compare every timed frame's time with
    /// the reference, and report per light the share of receiver pixels
    /// whose shadow flips between consecutive frames while the reference's
    /// does not (docs/metrics.md). Needs frames >= 2; default off.
    bool flips = false;
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

/// At most this many runs (scenes x combinations) per bench: each run renders
/// warm-up and timed frames and traces a reference, a second or more, so
/// 10,000 runs is already hours; past it is surely a mistake in --vary.
constexpr std::size_t kMaxBenchRuns = 10000;

/// Number of runs `sceneCount` scenes and `variations` make (the product of
/// the value counts), computed without building them; throws Error naming
/// --vary and the limit when it exceeds kMaxBenchRuns (without overflowing).
std::size_t countRuns(std::size_t sceneCount, const std::vector<Variation>& variations);

/// A directory beside `target` (`target.partial-PID`) that bench writes into;
/// commit() moves its content into `target` (created if missing, same-named
/// entries replaced). Destroyed without commit(), it is removed with its content.
class StagingDirectory {
public:
    explicit StagingDirectory(std::filesystem::path target);
    ~StagingDirectory();
    StagingDirectory(const StagingDirectory&) = delete;
    StagingDirectory& operator=(const StagingDirectory&) = delete;
    const std::filesystem::path& path() const { return staging_; }
    void commit();

private:
    std::filesystem::path target_, staging_;
    bool committed_ = false;
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
