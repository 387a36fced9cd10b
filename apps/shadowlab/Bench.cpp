// shadowlab bench (Bench.h): runBench, which checks its arguments and runs
// bench's parts (BenchParts.h) over every scene and combination, and the
// staging directory main writes its results through.
#include "BenchParts.h"
#include "Interrupt.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/SceneFile.h>

#include <shadowlab/Text.h>

#include <algorithm>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <csignal>
#include <unistd.h>

namespace shadowlab::tool {

namespace fs = std::filesystem;
using nlohmann::json;


StagingDirectory::StagingDirectory(fs::path target) : target_(std::move(target)) {
    removeStaleTemporaries(target_, "partial");  // OUT.partial-PID of benches that were killed
    staging_ = target_;
    staging_ += ".partial-" + std::to_string(getpid());
    std::error_code ec;
    fs::remove_all(staging_, ec);
    fs::create_directories(staging_, ec);
    removeOnForcedEnd(staging_, OnForcedEnd::Everything);  // if a second interrupt ends the run at once
    if (ec) throw Error("-o " + target_.string() + ": cannot create the directory (" + ec.message() + ")");
}

StagingDirectory::~StagingDirectory() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

void StagingDirectory::commit() {
    std::error_code ec;
    if (!fs::exists(target_, ec)) {
        fs::rename(staging_, target_, ec);
        if (ec) throw Error(target_.string() + ": cannot move the results into place (" + ec.message() + ")");
    } else {
        for (const fs::directory_entry& entry : fs::directory_iterator(staging_, ec)) {
            const fs::path destination = target_ / entry.path().filename();
            fs::remove_all(destination, ec);
            fs::rename(entry.path(), destination, ec);
            if (ec) throw Error(destination.string() + ": cannot move into place (" + ec.message() + ")");
        }
        fs::remove_all(staging_, ec);
    }
    committed_ = true;
}

namespace {

// One line per step when stderr is not a terminal, an updating bar when it is.
class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), tty_(isatty(STDERR_FILENO)) {}
    void step(std::size_t done, const std::string& what) {
        const int width = 30;
        const int filled = static_cast<int>(width * done / std::max<std::size_t>(total_, 1));
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.resize(width, '.');
        std::fprintf(stderr, "%s[%s] %zu/%zu %s%s", tty_ ? "\r\033[K" : "", bar.c_str(), done, total_, text::escapeControl(what).c_str(),
                     tty_ ? "" : "\n");
        if (tty_ && done == total_) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    std::size_t total_;
    bool tty_;
};

void checkArgs(const BenchArgs& args) {
    if (args.frames < 1) throw Error("--frames " + std::to_string(args.frames) + ": expected at least 1");
    if (args.warmup < 0) throw Error("--warmup " + std::to_string(args.warmup) + ": expected 0 or more");
    if (!std::isfinite(args.timeSeconds)) throw Error("--time: expected a finite number of seconds");
    if (!std::isfinite(args.fps) || !(args.fps > 0.0)) throw Error("--fps: expected a finite number of frames per second > 0");
    if (!std::isfinite(args.timeSeconds + (args.frames - 1) / args.fps))
        throw Error("--time, --fps: the last timed frame's time is not a finite number of seconds");
    if (args.flips && args.frames < 2)
        throw Error("--flips: needs at least 2 timed frames to compare (got --frames " + std::to_string(args.frames) + ")");
}

} // namespace

json runBench(Context& context, const BenchArgs& args) {
    checkArgs(args);
    std::vector<BenchRun> runs = loadRuns(args);  // every scene and combination checked before the long run starts
    std::fprintf(stderr, "bench: %zu run%s\n", runs.size(), runs.size() == 1 ? "" : "s");
    if (std::error_code ec; !fs::create_directories(args.output / "images", ec) && ec)
        throw Error((args.output / "images").string() + ": cannot create directory (" + ec.message() + ")");
    Progress progress(runs.size());
    json records = json::array();
    for (BenchRun& run : runs) {
        // The scene at --time: the warm-up frames and the comparison.
        Scene scene = sceneAtTime(run.loaded, args.timeSeconds);
        std::string label = scene.name;
        for (const std::string& c : run.combo) label += " " + c;
        progress.step(records.size(), label);
        try {
            Renderer renderer(context);
            renderer.upload(scene);
            // A shadow atlas with an update budget: its frames in sequence on a renderer of their own.
            std::optional<Renderer> budgeted;
            if (scene.shadowAtlas.updateBudget > 0) {
                budgeted.emplace(context);
                budgeted->upload(scene);
            }
            const TimedFrames timed = timeFrames(renderer, scene, run.loaded, args, budgeted ? &*budgeted : nullptr);
            const Accuracy accuracy = measureAccuracy(renderer, scene, run.loaded, args);
            throwIfInterrupted();  // an interrupt during the reference's trace
            // What the techniques noticed (no planar receiver, no disc): said here and kept in the row.
            for (const std::string& note : accuracy.comparison.techniqueFrame.notes)
                std::fprintf(stderr, "shadowlab: note: bench run %zu/%zu (%s): %s\n", records.size() + 1, runs.size(), label.c_str(), note.c_str());
            records.push_back(runRecord(run, scene, timed, accuracy, records.size(), label, args));
        } catch (const Error& e) {
            // Name the run that failed: its scene and the combination of --vary values.
            std::string where = run.file.empty() ? std::string("the default scene") : run.file;
            for (const std::string& c : run.combo) where += ", --vary " + c;
            // A value's source, as render names it: the --set or --vary value
            // applied last to it (from the scene file: the prefix names it).
            std::vector<std::string> applied = args.overrides, labels;
            for (const std::string& o : args.overrides) labels.push_back("--set " + o);
            for (const std::string& c : run.combo) {
                applied.push_back(c);
                labels.push_back("--vary " + c);
            }
            const std::string message = withValueSource(e.what(), "", applied, labels);
            throw Error("bench run " + std::to_string(records.size() + 1) + "/" + std::to_string(runs.size()) + " (" + where +
                        "): " + message);
        }
        progress.step(records.size(), label);
        run.loaded = Scene{};  // its meshes and textures are not needed again
    }
    const GlInfo& info = context.info();
    return json{{"tool", "shadowlab bench"},
                {"renderer", info.renderer},
                {"glVersion", info.version},
                {"width", args.width},
                {"height", args.height},
                {"frames", args.frames},
                {"warmup", args.warmup},
                {"time", args.timeSeconds},
                {"fps", args.fps},
                {"flips", args.flips},
                {"softSamples", args.softSamples},
                {"overrides", args.overrides},
                {"vary", args.vary},
                {"results", records}};
}

} // namespace shadowlab::tool
