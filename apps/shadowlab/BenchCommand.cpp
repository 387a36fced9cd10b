// `shadowlab bench` (BenchCommand.h).
#include "BenchCommand.h"

#include "Commands.h"
#include "Interrupt.h"
#include "OutputFiles.h"

#include <shadowlab/FileWrite.h>
#include <shadowlab/Limits.h>

#include <filesystem>
#include <iostream>
#include <map>

namespace fs = std::filesystem;

namespace shadowlab::tool {

CLI::App* addBench(CLI::App& app, BenchArgs& args, std::string& output) {
    CLI::App* bench = app.add_subcommand("bench", "Time and accuracy of every combination of settings, with results.json and report.html");
    bench->add_option("scenes", args.scenes, "Scene files (JSON); the built-in default scene when omitted");
    bench->add_option("--set", args.overrides, "Override a scene value for every run")->take_all();
    bench->add_option("--camera", args.gltfCamera, "A glTF file's camera: its index among those the file's scene places, from 0 (default: the first)")->check(CLI::Range(0, 65535));
    bench->add_option("--vary", args.vary, "key=v1,v2,...: run once per value (several --vary: every combination)")->take_all();
    bench->add_option("--frames", args.frames, "Timed frames per combination; timed frame k at --time + k / --fps")
        ->check(CLI::Range(1, 100000))->capture_default_str();
    bench->add_option("--time", args.timeSeconds, "Seconds since the start of the animation: the first timed frame's time, and the "
                                                   "time of the warm-up frames and the accuracy comparison")
        ->capture_default_str();
    bench->add_option("--fps", args.fps, "Frames per second of the timed sequence")->capture_default_str();
    bench->add_flag("--flips", args.flips,
                    "Temporal stability: compare every timed frame with the reference and report per light the share of receiver "
                    "pixels whose shadow changes between consecutive frames at the same world point while the truth there does not (needs --frames >= 2)");
    bench->add_flag("--skip-unsupported", args.skipUnsupported,
                    "Leave out the runs whose combination a light's technique cannot draw (cascades on a spot light, a soft filter on an "
                    "atlas tile), each listed with its reason in results.json's \"skipped\", instead of refusing the bench; other bad values still refuse it");
    bench->add_option("--warmup", args.warmup, "Untimed frames before timing")->check(CLI::Range(0, 1000))->capture_default_str();
    bench->add_option("--rounds", args.rounds,
                      "Rounds of timing: each run timed once a round, the runs in turn, and each row keeps its fastest round "
                      "(lowest median frame) whole; for ratios on a shared machine")
        ->check(CLI::Range(1, kMaxBenchRounds))->capture_default_str();
    bench->add_option("--width", args.width, "Image width in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    bench->add_option("--height", args.height, "Image height in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    bench->add_option("--samples", args.softSamples, "Reference rays per pixel for lights with a size")
        ->check(CLI::Range(1, kMaxSoftSamples))->capture_default_str();
    bench->add_option("-o,--output", output, "Output directory")->capture_default_str();
    const std::map<std::string, TimingClock> clocks{{"auto", TimingClock::Auto},
                                                    {"cpu-finish", TimingClock::CpuFinish},
                                                    {"gpu-timestamp", TimingClock::GpuTimestamp}};
    bench->add_option("--clock", args.clock,
                      "Per-pass clock: auto (cpu-finish on a software rasteriser, gpu-timestamp on a GPU), cpu-finish, gpu-timestamp")
        ->transform(CLI::CheckedTransformer(clocks, CLI::ignore_case))
        ->default_str("auto");
    return bench;
}

int runBenchCommand(const BenchArgs& args) {
    removeStaleTemporaries(args.output, "partial");  // what killed benches left, even if this one fails next
    for (const std::string& file : args.scenes) {
        if (file.empty()) throw Error("bench: empty scene path");
        if (text::invalidUtf8At(file) != std::string::npos)
            throw Error(text::escapeControl(file) + ": file name is not valid UTF-8 (results.json is UTF-8)");
        const fs::file_status status = pathStatus(file, file);
        if (!fs::exists(status)) throw Error(file + ": file not found");
        if (!fs::is_regular_file(status)) throw Error(file + ": not a regular file (expected a scene file)");
    }
    checkOutputDirectory(args.output.string());
    checkMemory(args.width, args.height);
    checkReferenceRays(args.width, args.height, args.softSamples);
    Context context = Context::createHeadless();
    checkSize(args.width, args.height, context.info());
    // Everything is written into a staging directory beside the output and
    // moved into place only when the whole run succeeded: a failure half way
    // (a texture past the GPU limit in the third scene) leaves nothing behind.
    StagingDirectory staging(args.output, "-o");
    removeOnForcedEnd(staging.path(), OnForcedEnd::Everything);  // if a second interrupt ends the run at once
    BenchArgs staged = args;
    staged.output = staging.path();
    try {
        runBenchInto(context, staged);
        requireNoGlErrors(context);
    } catch (const Error& e) {  // a file named where it goes, not in the staging directory
        throw Error(naming(e.what(), staged.output.string(), args.output.string()));
    }
    staging.commit();
    std::cout << (args.output / "results.json").string() << "\n" << (args.output / "report.html").string() << "\n";
    return 0;
}

} // namespace shadowlab::tool
