// The Python module's bench (Module.h): the library's runBench, the one
// `shadowlab bench` runs, with results.json's rows as dicts and their
// images as arrays; files only when `out` names a directory.
#include "Module.h"

#include <shadowlab/Bench.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/Text.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <optional>

namespace shadowlab::python {

namespace fs = std::filesystem;

namespace {

// A scene argument as a file path: a str or os.PathLike, or a Scene loaded
// from a file without overrides (bench's overrides apply to every scene).
std::string scenePath(const py::handle& scene) {
    if (py::isinstance<PyScene>(scene)) {
        const PyScene& s = scene.cast<const PyScene&>();
        if (s.text || s.path.empty() || !s.overrides.empty() || s.camera >= 0)
            throw InputFailure("scenes: bench takes scene files; a Scene from load_scene_json, default_scene, with overrides or a camera= is not one "
                                  "(give the file, and the overrides as bench's overrides=)");
        return s.path;
    }
    // A file that is not there, named as the argument it came in (as the CLI's bench checks them first).
    const std::string path = pathArgument(scene, "scenes");
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw InputFailure("scenes " + text::escapeControl(text::clipMiddle(path, 200)) + ": file not found");
    if (!fs::is_regular_file(status))
        throw InputFailure("scenes " + text::escapeControl(text::clipMiddle(path, 200)) + ": not a regular file (expected a scene file)");
    return path;
}

// `scenes`: None (the built-in default scene), one scene or a list of them.
std::vector<std::string> scenePaths(const py::object& scenes) {
    if (scenes.is_none()) return {};
    if (!(py::isinstance<py::list>(scenes) || py::isinstance<py::tuple>(scenes))) return {scenePath(scenes)};
    std::vector<std::string> paths;
    for (const py::handle& s : scenes) paths.push_back(scenePath(s));
    if (paths.empty()) throw InputFailure("scenes: an empty list (None benches the built-in default scene)");
    return paths;
}

// `out` checked before the run, as the CLI checks -o: not an existing
// file, its parent directory there.
std::string outPath(const py::object& out) {
    if (out.is_none()) return {};
    const std::string path = pathArgument(out, "out");
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (fs::exists(status) && !fs::is_directory(status)) throw InputFailure("out " + text::escapeControl(path) + ": exists and is not a directory");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw InputFailure("out " + text::escapeControl(path) + ": directory " + text::escapeControl(parent.string()) + " does not exist");
    return path;
}

// Ctrl-C during a bench, seen without the GIL: a bench holds the GL lock
// while it runs, and a thread that holds the lock must never wait for the
// GIL (a thread holding the GIL may be waiting for something the bench
// thread's progress would free). Called from the main thread, while
// Python's own SIGINT handler is installed, a handler of ours records the
// signal in a flag the bench's checkpoint reads; at the end Python's
// handler is put back and the signal handed to it (PyErr_SetInterrupt),
// so KeyboardInterrupt, or the handler the program set, follows. Elsewhere
// (another thread, SIGINT ignored) the bench runs to its end, as Python
// code in a thread does.
class InterruptWatch {
public:
    InterruptWatch() {
        const py::object threading = py::module_::import("threading");
        if (!threading.attr("current_thread")().is(threading.attr("main_thread")())) return;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // one that came before the bench
        struct sigaction current {};
        if (sigaction(SIGINT, nullptr, &current) != 0 || current.sa_handler == SIG_IGN || current.sa_handler == SIG_DFL) return;
        struct sigaction ours {};
        ours.sa_handler = [](int) { arrived().store(true); };
        sigemptyset(&ours.sa_mask);
        arrived().store(false);
        installed_ = sigaction(SIGINT, &ours, &python_) == 0;
    }
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;
    ~InterruptWatch() { restore(); }
    /// Whether Ctrl-C came since the bench began (no GIL needed).
    static bool interrupted() { return arrived().load(); }
    /// Python's handler back; a signal that came is handed to it. Call with the GIL.
    void restore() {
        if (!installed_) return;
        sigaction(SIGINT, &python_, nullptr);
        installed_ = false;
        if (arrived().exchange(false)) PyErr_SetInterrupt();
    }

private:
    static std::atomic<bool>& arrived() {
        static std::atomic<bool> flag{false};
        static_assert(std::atomic<bool>::is_always_lock_free, "read from a signal handler");
        return flag;
    }
    struct sigaction python_ {};
    bool installed_ = false;
};

// What a run's images are, kept for the rows.
struct RunImages {
    ImageRGBA8 technique, reference;
    std::vector<ImageRGBA8> errors;
};

// results.json's rows as Python dicts, each with its run's images
// ("images": technique, reference; each light's "images": error).
py::list rowsWithImages(const std::string& results, std::vector<RunImages>& kept) {
    py::dict all = py::module_::import("json").attr("loads")(results);
    py::list rows = all["results"];
    for (std::size_t r = 0; r < kept.size() && r < rows.size(); ++r) {
        py::dict row = rows[r];
        py::dict images;
        images["technique"] = rgba(std::move(kept[r].technique));
        images["reference"] = rgba(std::move(kept[r].reference));
        row["images"] = images;
        py::list lights = row["lights"];
        for (std::size_t l = 0; l < kept[r].errors.size() && l < lights.size(); ++l) {
            py::dict light = lights[l], lightImages;
            lightImages["error"] = rgba(std::move(kept[r].errors[l]));
            light["images"] = lightImages;
        }
    }
    return rows;
}

} // namespace

py::list bench(const py::object& scenes, int width, int height, const py::object& vary, const py::dict& overrides, int frames, int warmup,
               double time, double fps, bool flips, int softSamples, const py::object& out, int rounds, bool skipUnsupported) {
    checkFrame(width, height, time);
    checkSoftSamples(softSamples, width, height);
    BenchOptions options;
    options.scenes = scenePaths(scenes);
    options.overrides = overrideLines(overrides);
    options.vary = varyLines(vary);
    options.frames = frames;
    options.warmup = warmup;
    options.rounds = rounds;
    options.timeSeconds = time;
    options.fps = fps;
    options.flips = flips;
    options.width = width;
    options.height = height;
    options.softSamples = softSamples;
    options.skipUnsupported = skipUnsupported;
    const std::string outDir = outPath(out);

    std::vector<RunImages> kept;
    std::string results, failure;
    bool interrupted = false, input = false, ran = false;
    InterruptWatch watch;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard hold(glLock());
        const Released release;
        Context& context = contextLocked();
        try {
            checkSize(width, height, context.info());  // GL's limits, before the first run
            // Written into OUT.partial-PID and moved into place at the end: a failure leaves nothing.
            std::optional<StagingDirectory> staging;
            if (!outDir.empty()) staging.emplace(outDir, "out");
            BenchHooks hooks;
            // Ctrl-C (KeyboardInterrupt) stops the bench between frames, seen without the GIL.
            hooks.checkpoint = [&] {
                interrupted = interrupted || InterruptWatch::interrupted();
                if (interrupted) throw Error("interrupted");
            };
            hooks.images = [&](std::size_t, const std::string& stem, const Comparison& c) {
                RunImages images{c.technique, c.reference, {}};
                for (const LightComparison& l : c.lights) images.errors.push_back(l.errorImage);
                kept.push_back(std::move(images));
                return staging ? writeBenchImages(staging->path(), stem, c) : BenchImageNames{};  // files as the CLI names them
            };
            results = runBench(context, options, hooks);
            ran = true;  // what fails after this is writing the files: the system's, not the arguments'
            if (staging) {
                writeFileAtomically(staging->path() / "results.json", results);
                writeBenchReport(results, staging->path());
                staging->commit();
            }
        } catch (const Error& e) {
            failure = e.what();
            // Before the first run: the arguments', a scene's or the size's; a run's failure names the run.
            input = (!ran && failure.rfind("bench run ", 0) != 0) || dynamic_cast<const InputError*>(&e) != nullptr;
        }
    }
    watch.restore();
    if (interrupted) {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // KeyboardInterrupt, or what the program's handler raised
        throw std::runtime_error("bench: interrupted");
    }
    if (!failure.empty()) {
        if (input) throw InputFailure(pythonNames(failure, options.overrides));
        throw std::runtime_error(pythonNames(failure, options.overrides));
    }
    return rowsWithImages(results, kept);
}

} // namespace shadowlab::python
