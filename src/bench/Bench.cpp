// bench (include/shadowlab/Bench.h): runBench, which checks its options
// and runs bench's parts (BenchParts.h) over every scene and combination.
#include "BenchParts.h"

#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace shadowlab::bench {

using nlohmann::json;

namespace {

void checkArgs(const BenchOptions& args) {
    if (args.width < 1 || args.height < 1)
        throw Error("--width, --height: expected at least 1 pixel, got " + std::to_string(args.width) + "x" + std::to_string(args.height));
    if (args.softSamples < 1 || args.softSamples > kMaxSoftSamples)
        throw Error("--samples " + std::to_string(args.softSamples) + ": expected 1.." + std::to_string(kMaxSoftSamples));
    // Bounded as the CLI's flags are (Python's bench ran 10^6 frames or 10^7 warm-ups for ever).
    if (args.frames < 1 || args.frames > kMaxBenchFrames)
        throw Error("--frames " + std::to_string(args.frames) + ": expected 1.." + std::to_string(kMaxBenchFrames));
    if (args.warmup < 0 || args.warmup > kMaxBenchWarmup)
        throw Error("--warmup " + std::to_string(args.warmup) + ": expected 0.." + std::to_string(kMaxBenchWarmup));
    if (args.rounds < 1 || args.rounds > kMaxBenchRounds)
        throw Error("--rounds " + std::to_string(args.rounds) + ": expected 1.." + std::to_string(kMaxBenchRounds));
    if (!std::isfinite(args.timeSeconds)) throw Error("--time: expected a finite number of seconds");
    if (!std::isfinite(args.fps) || !(args.fps > 0.0)) throw Error("--fps: expected a finite number of frames per second > 0");
    if (!std::isfinite(args.timeSeconds + (args.frames - 1) / args.fps))
        throw Error("--time, --fps: the last timed frame's time is not a finite number of seconds");
    if (args.flips && args.frames < 2)
        throw Error("--flips: needs at least 2 timed frames to compare (got --frames " + std::to_string(args.frames) + ")");
}

// The runs --skip-unsupported left out while loading: the first ten said.
// What each scene file's loading chose (a glTF with no light or camera), once a file.
void noteSceneChoices(const BenchHooks& hooks, const std::vector<BenchRun>& runs) {
    if (!hooks.note) return;
    for (std::size_t r = 0; r < runs.size(); ++r)
        if (r == 0 || runs[r].file != runs[r - 1].file)
            for (const std::string& note : runs[r].loaded.notes) hooks.note(note);
}

void noteSkipped(const BenchHooks& hooks, const json& skipped) {
    if (!hooks.note) return;
    for (std::size_t i = 0; i < skipped.size(); ++i) {
        if (i == 10) {
            hooks.note("--skip-unsupported: " + std::to_string(skipped.size() - 10) + " more run(s) left out (results.json's \"skipped\")");
            break;
        }
        const std::string file = skipped[i]["sceneFile"].get<std::string>();
        hooks.note("--skip-unsupported: left out " + (file.empty() ? std::string("the default scene") : file) + ": " + skipped[i]["reason"].get<std::string>());
    }
}

// A value's source, as render names it: the --set or --vary value applied
// last to it (from the scene file: the prefix names it). The values in
// the order applied, and their labels.
std::pair<std::vector<std::string>, std::vector<std::string>> valueSources(const BenchOptions& args, const BenchRun& run) {
    std::vector<std::string> applied = args.overrides, labels;
    for (const std::string& o : args.overrides) labels.push_back("--set " + o);
    for (const std::string& c : run.combo) {
        applied.push_back(c);
        labels.push_back("--vary " + c);
    }
    return {applied, labels};
}

// Which run a row is: its number (from 0) of how many, and its label.
struct RunName {
    std::size_t index, count;
    const std::string& label;
};

// A run's row after its last round: its accuracy against the reference,
// the notes of its technique frame said, its fastest round's frames.
json lastRecord(Renderer& renderer, Scene& scene, const BenchRun& run, const TimedFrames& fastest, const RunName& name,
                const BenchOptions& args, const BenchHooks& hooks) {
    const Accuracy accuracy = measureAccuracy(renderer, scene, run.loaded, args, hooks);
    if (hooks.checkpoint) hooks.checkpoint();  // a stop asked for during the reference's trace
    // What the techniques noticed (no planar receiver, no disc): said here and kept in the row.
    if (hooks.note)
        for (const std::string& note : accuracy.comparison.techniqueFrame.notes)
            hooks.note("bench run " + std::to_string(name.index + 1) + "/" + std::to_string(name.count) + " (" + name.label + "): " + note);
    return runRecord(run, scene, fastest, accuracy, name.index, name.label, args, hooks);
}

// results.json: the bench's settings, the runs left out and a row per run.
json resultsJson(const GlInfo& info, const BenchOptions& args, const json& skipped, const json& records);

json run(Context& context, const BenchOptions& args, const BenchHooks& hooks) {
    checkArgs(args);
    json skipped = json::array();
    std::vector<BenchRun> runs = loadRuns(args, &skipped);  // every scene and combination checked before the long run starts
    if (runs.empty()) throw Error("--skip-unsupported: every run was left out (" + skipped.front()["reason"].get<std::string>() + ")");
    noteSkipped(hooks, skipped);
    noteSceneChoices(hooks, runs);
    json records = json::array();
    // Rounds (BenchOptions::rounds): every run timed once a round, the
    // runs in turn; a run keeps its fastest round's frames whole.
    const std::size_t total = runs.size() * static_cast<std::size_t>(args.rounds);
    std::vector<TimedFrames> fastest(runs.size());
    std::vector<std::vector<double>> roundMedians(runs.size());
    std::vector<int> chosen(runs.size(), 0);
    std::size_t done = 0;
    for (int round = 0; round < args.rounds; ++round) {
        const bool last = round + 1 == args.rounds;
        for (std::size_t r = 0; r < runs.size(); ++r) {
            BenchRun& run = runs[r];
            if (run.skipped) {  // found unsupported while drawing (--skip-unsupported), in an earlier round
                done += 1;
                continue;
            }
            // The scene at --time: the warm-up frames and the comparison.
            Scene scene = sceneAtTime(run.loaded, args.timeSeconds);
            std::string label = scene.name;
            for (const std::string& c : run.combo) label += " " + c;
            const std::string shown =
                args.rounds > 1 ? label + " (round " + std::to_string(round + 1) + "/" + std::to_string(args.rounds) + ")" : label;
            if (hooks.progress) hooks.progress(done, total, shown);
            try {
                Renderer renderer(context);
                renderer.upload(scene);
                // A shadow atlas with an update budget: its frames in sequence on a renderer of their own.
                std::optional<Renderer> budgeted;
                if (scene.shadowAtlas.updateBudget > 0) {
                    budgeted.emplace(context);
                    budgeted->upload(scene);
                }
                TimedFrames timed = timeFrames(renderer, scene, run.loaded, args, hooks, budgeted ? &*budgeted : nullptr);
                roundMedians[r].push_back(median(timed.frameTimes));
                if (round == 0 || roundMedians[r].back() < roundMedians[r][static_cast<std::size_t>(chosen[r])]) {
                    fastest[r] = std::move(timed);
                    chosen[r] = round;
                }
                if (last) {
                    json record = lastRecord(renderer, scene, run, fastest[r], {r, runs.size(), label}, args, hooks);
                    if (args.rounds > 1) {
                        record["round"] = chosen[r];
                        record["frameMsByRound"] = roundMedians[r];
                    }
                    records.push_back(std::move(record));
                }
            } catch (const Error& e) {
                // Name the run that failed: its scene and the combination of --vary values.
                std::string where = run.file.empty() ? std::string("the default scene") : run.file;
                for (const std::string& c : run.combo) where += ", --vary " + c;
                const auto [applied, labels] = valueSources(args, run);
                const std::string message = "bench run " + std::to_string(r + 1) + "/" + std::to_string(runs.size()) + " (" + where +
                                            "): " + withValueSource(e.what(), "", applied, labels);
                // Found only while drawing (an alpha-tested caster under shadow volumes): left out as a load-time one is.
                if (args.skipUnsupported && dynamic_cast<const UnsupportedError*>(&e)) {
                    run.skipped = true;
                    const std::string reason = withValueSource(e.what(), run.file, applied, labels);
                    skipped.push_back({{"sceneFile", run.file}, {"vary", run.combo}, {"reason", reason}});
                    if (hooks.note) hooks.note("--skip-unsupported: left out " + where + ": " + reason);
                    if (hooks.progress) hooks.progress(++done, total, shown);
                    continue;
                }
                if (dynamic_cast<const InputError*>(&e)) throw InputError(message);  // still the input's fault
                throw Error(message);
            }
            if (hooks.progress) hooks.progress(++done, total, shown);
            if (last) run.loaded = Scene{};  // its meshes and textures are not needed again
        }
    }
    if (records.empty()) throw Error("--skip-unsupported: every run was left out (" + skipped.front()["reason"].get<std::string>() + ")");
    return resultsJson(context.info(), args, skipped, records);
}

json resultsJson(const GlInfo& info, const BenchOptions& args, const json& skipped, const json& records) {
    return json{{"tool", "shadowlab bench"},
                {"renderer", info.renderer},
                {"glVersion", info.version},
                {"width", args.width},
                {"height", args.height},
                {"frames", args.frames},
                {"warmup", args.warmup},
                {"rounds", args.rounds},
                {"time", args.timeSeconds},
                {"fps", args.fps},
                {"flips", args.flips},
                {"softSamples", args.softSamples},
                {"overrides", args.overrides},
                {"vary", args.vary},
                {"skipUnsupported", args.skipUnsupported},
                {"skipped", skipped},
                {"results", records}};
}

} // namespace

} // namespace shadowlab::bench

namespace shadowlab {

std::string runBench(Context& context, const BenchOptions& options, const BenchHooks& hooks) {
    // Invalid UTF-8 in a scene's name or a value is replaced, not an exception (results.json is UTF-8).
    return bench::run(context, options, hooks).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

} // namespace shadowlab
