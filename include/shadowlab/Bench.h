#pragma once
/// @file Bench.h
/// Time and accuracy for every combination of varied settings over a set of
/// scenes: what `shadowlab bench` runs and the Python module's bench()
/// calls, one implementation. The rows are results.json's (docs/metrics.md);
/// the report is bench's report.html. Needs SHADOWLAB_WITH_EMBREE (the
/// default) for the accuracy columns: without it runBench throws.
#include <shadowlab/Compare.h>
#include <shadowlab/Context.h>
#include <shadowlab/Export.h>
#include <shadowlab/Renderer.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

struct BenchOptions {
    std::vector<std::string> scenes;     ///< scene files; empty = the built-in default scene
    /// `key=value` overrides for every run, as --set takes them (errors name them `--set key=value`).
    std::vector<std::string> overrides;
    int gltfCamera = -1;                 ///< a glTF scene file's camera (SceneFileOptions::gltfCamera, `--camera`); -1: its first
    /// `key=v1,v2,...` (commas inside [] {} "" do not split): every
    /// combination of the values is a run, per scene (errors name them `--vary ...`).
    std::vector<std::string> vary;
    int frames = 10;                     ///< timed frames per run, >= 1; default 10
    /// Seconds since the start of the animation: the lights' and the
    /// camera's paths are evaluated at timeSeconds for the warm-up frames
    /// and the accuracy comparison, and at timeSeconds + k / fps for timed
    /// frame k. Finite; default 0.
    double timeSeconds = 0.0;
    double fps = 30.0;                   ///< frames per second of the timed sequence, > 0; default 30
    /// Temporal stability: compare every timed frame's time with the
    /// reference, and report per light the share of receiver pixels whose
    /// shadow flips between consecutive frames while the reference's does
    /// not (docs/metrics.md). Needs frames >= 2; default off.
    bool flips = false;
    int warmup = 2;                      ///< untimed frames first (shader compilation, caches), >= 0; default 2
    /// Rounds of timing, 1..kMaxBenchRounds: every run is timed once per
    /// round, the runs one after another within a round (interleaved, so a
    /// spell of load on a shared machine falls on every run alike), and each
    /// row keeps its fastest round (the lowest median frame), whole: its
    /// frames, passes and ratios are that round's. The comparison with the
    /// reference is made once, in the last round. Default 1.
    int rounds = 1;
    int width = 960, height = 540;       ///< pixels; default 960 x 540
    int softSamples = 256;               ///< reference rays per pixel for lights with size > 0; default 256
    /// Leave out the runs whose combination a light's technique cannot draw
    /// (UnsupportedError: cascades on a spot light, volume on an
    /// alpha-tested caster), each listed in results.json's "skipped" with
    /// its reason, instead of refusing the whole bench; so one run can vary
    /// techniques over scenes that not every technique suits. Other bad
    /// values still refuse it. Default off.
    bool skipUnsupported = false;
    /// Per-pass clock: Auto = glFinish-bracketed CPU time on a software
    /// rasteriser, timestamp queries on a GPU.
    TimingClock clock = TimingClock::Auto;
};

/// At most this many runs (scenes x combinations) per bench: each run renders
/// warm-up and timed frames and traces a reference, a second or more, so
/// 10,000 runs is already hours; past it is surely a mistake in `vary`.
constexpr std::size_t kMaxBenchRuns = 10000;
/// At most this many rounds (BenchOptions::rounds).
constexpr int kMaxBenchRounds = 100;
/// At most this many timed frames a run (BenchOptions::frames), as the CLI's --frames.
constexpr int kMaxBenchFrames = 100000;
/// At most this many warm-up frames a run (BenchOptions::warmup), as the CLI's --warmup.
constexpr int kMaxBenchWarmup = 1000;

/// The image files a run's row names (paths relative to results.json); an
/// empty name leaves its key out of the row.
struct BenchImageNames {
    std::string technique, reference;  ///< techniqueImage, referenceImage
    std::vector<std::string> errors;   ///< per light: errorImage
};

/// What runBench does around its runs; every member may be left empty.
struct BenchHooks {
    /// Before and after each run's timing in each round: timings done,
    /// timings in all (runs x rounds), the run's label (scene name and
    /// combination, and the round when there are several).
    std::function<void(std::size_t done, std::size_t total, const std::string& label)> progress;
    /// Between timed frames and runs; throw (an Error) to stop the bench.
    std::function<void()> checkpoint;
    /// Traces a comparison's reference (default: job.trace()); a caller may
    /// run it on another thread and cancel it.
    std::function<void(ComparisonJob&)> trace;
    /// A note a technique made in a run's frame (no planar receiver, tiles
    /// shrunk), said as "bench run I/N (LABEL): NOTE"; it is in the row's
    /// `notes` too.
    std::function<void(const std::string& note)> note;
    /// Each run's images, once its comparison is done: the run's index from
    /// 0, a file-name stem made from its label ("3-two-boxes-sun_lights..."),
    /// and the comparison (technique and reference frames, each light's
    /// error image). Returns the names its row gives them.
    std::function<BenchImageNames(std::size_t run, const std::string& stem, const Comparison& comparison)> images;
};

/// Runs every scene with every combination of options.vary: warm-up frames,
/// timed frames (medians and ratios: the frame, the same unshadowed, cached,
/// per pass, per light) and a comparison with the reference; returns
/// results.json's content as JSON text ({"tool", "renderer", ..., "results": [row, ...]}).
/// Every scene and combination is parsed before the first frame: a bad
/// value throws Error naming --set or --vary and the scene; a run that fails
/// later throws Error naming the run ("bench run 2/4 (scene, --vary k=v): ...").
SHADOWLAB_API std::string runBench(Context& context, const BenchOptions& options, const BenchHooks& hooks = {});

/// Writes a run's images where `shadowlab bench -o DIR` puts them:
/// DIR/images/STEM-technique.png, -reference.png and -error-LIGHT.png
/// (`directory`/images made if missing); returns their names relative to
/// `directory`, for BenchHooks::images to return. Throws Error naming a
/// file that cannot be written.
SHADOWLAB_API BenchImageNames writeBenchImages(const std::filesystem::path& directory, const std::string& stem, const Comparison& comparison);

/// Writes report.html into `directory` from results.json's content, with
/// the images the rows name (relative to `directory`) embedded: a plot of
/// error against frame time, the frame against lightGrid.count where
/// varied, a table per run. Throws Error naming the file on failure.
SHADOWLAB_API void writeBenchReport(const std::string& resultsJson, const std::filesystem::path& directory);

} // namespace shadowlab
