// shadowlab: the command-line tool. Subcommands:
//   render [SCENE.json] -o out.png [--width W --height H] [--set key=value ...]
//          [--time T] [--frames N --fps F -o frame_%03d.png]
//   compare [SCENE.json] [-o DIR] [--set ...] [--time T]  technique vs ray-traced reference
//   bench [SCENES...] [--set ...] [--vary key=v1,v2] [--frames N] [--rounds R] [--time T --fps F] [--flips] [-o DIR]
//   info
// Every failure prints one line `shadowlab: error: ...` and exits non-zero;
// no output file is written unless the whole render succeeded.
#include "Bench.h"
#if SHADOWLAB_VIEWER
#include "Viewer.h"
#endif
#include "Interrupt.h"
#include "OutputFiles.h"

#include <shadowlab/Limits.h>
#include <shadowlab/Compare.h>
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include <shadowlab/Text.h>

#include <CLI/CLI.hpp>


#include <algorithm>
#include <new>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include <unistd.h>  // isatty
#if defined(__GLIBC__)
#include <malloc.h>  // mallopt
#endif

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

// What the techniques noticed about the scene (FrameStats::notes), each once per run.
void printNotes(const std::vector<std::string>& notes) {
    static std::set<std::string> printed;
    for (const std::string& note : notes)
        if (printed.insert(note).second) std::cerr << "shadowlab: note: " << note << "\n";
}


struct RenderArgs {
    std::string scene;
    std::string output;
    int width = 1280;
    int height = 720;
    std::vector<std::string> overrides;
    std::string debugImages;  ///< directory for the techniques' debug images; empty = none
    std::vector<std::string> debug; ///< --debug: which debug images to write beside the output (shadow-maps, texel-density, all)
    int viewFromLight = -1;   ///< --view-from-light: the light whose view replaces the camera; -1 none
    double timeSeconds = 0.0; ///< --time: seconds since the start of the animation, of the first frame
    int frames = 1;           ///< --frames: how many frames, each 1/fps seconds after the previous
    double fps = 30.0;        ///< --fps: frames per second of the sequence, > 0
};

// --time and --fps: finite (CLI11 reads "nan" and "inf" as numbers).
using text::numberText;
void checkTime(double seconds, const std::string& flag) {
    if (!std::isfinite(seconds)) throw Error(flag + " " + numberText(seconds) + ": expected a finite number of seconds");
}
void checkFps(double fps) {
    if (!std::isfinite(fps) || !(fps > 0.0)) throw Error("--fps " + numberText(fps) + ": expected a finite number of frames per second > 0");
}

// --view-from-light I: the scene seen from light I (Ganovelli et al. exercise 8.6.1-1).
void applyViewFromLight(Scene& scene, int light) {
    if (light < 0) return;
    if (static_cast<std::size_t>(light) >= scene.lights.size())
        throw Error("--view-from-light " + std::to_string(light) + ": the scene has " + std::to_string(scene.lights.size()) + " light(s)");
    try {
        scene.camera = cameraFromLight(scene, scene.lights[static_cast<std::size_t>(light)]);
    } catch (const Error& e) {
        throw Error("--view-from-light " + std::to_string(light) + ": " + e.what());
    }
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
    return path.empty() ? defaultScene(overrides) : loadSceneFile(path, overrides);
}

void requireNoGlErrors(const Context& context) {
    if (context.debugErrorCount() > 0)
        throw Error("OpenGL reported " + std::to_string(context.debugErrorCount()) + " error(s); last: " + context.lastDebugError());
}

// Whether --debug's list asks for images of `kind`: shadow-maps (2D maps and
// cube crosses), texel-density, cascades, atlas, or all (every image).
bool debugWanted(DebugImageKind kind, const std::vector<std::string>& wanted) {
    for (const std::string& w : wanted)
        if (w == "all" || (w == "shadow-maps" && (kind == DebugImageKind::ShadowMap || kind == DebugImageKind::CubeCross)) ||
            (w == "texel-density" && kind == DebugImageKind::TexelDensity) || (w == "cascades" && kind == DebugImageKind::Cascades) ||
            (w == "atlas" && kind == DebugImageKind::Atlas))
            return true;
    return false;
}

// --debug texel-density: a light drawn with a light camera whose technique
// makes no texel-density image of it (a tile of the shadow atlas) is said,
// not left out silently.
void noteLightsWithoutDensity(const Renderer& renderer, const Scene& scene, const std::vector<DebugImage>& images, std::ostream& out) {
    std::vector<bool> hasCamera(scene.lights.size(), false), hasDensity(scene.lights.size(), false);
    for (const LightFrustum& f : renderer.lightFrustums(scene))
        if (f.light >= 0 && static_cast<std::size_t>(f.light) < hasCamera.size()) hasCamera[static_cast<std::size_t>(f.light)] = true;
    for (const DebugImage& d : images)
        if (d.kind == DebugImageKind::TexelDensity && d.light >= 0 && static_cast<std::size_t>(d.light) < hasDensity.size())
            hasDensity[static_cast<std::size_t>(d.light)] = true;
    std::string missing;
    std::size_t count = 0;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (hasCamera[i] && !hasDensity[i]) {
            if (count < 8) missing += (missing.empty() ? "" : ", ") + std::to_string(i) + " '" + text::escapeControl(scene.lights[i].name) + "'";
            ++count;
        }
    if (count == 0) return;
    if (count > 8) missing += " and " + std::to_string(count - 8) + " more";
    out << "shadowlab: note: --debug texel-density: no texel-density image of light" << (count > 1 ? "s " : " ") << missing
        << ": the technique makes none of its map (a tile of the shadow atlas)\n";
}

int runRender(const RenderArgs& args) {
    checkTime(args.timeSeconds, "--time");
    checkFps(args.fps);
    const Scene loaded = loadScene(args.scene, args.overrides);
    // Without -o: <scene>.png, or <scene>-%03d.png for a sequence.
    std::string stem = args.scene.empty() ? std::string("default") : fs::path(args.scene).stem().string();
    for (std::size_t at = stem.find('%'); at != std::string::npos; at = stem.find('%', at + 2)) stem.insert(at, "%");
    const std::string defaultName = stem + (args.frames > 1 ? "-%03d" : "") + ".png";
    const std::string outputName = args.output.empty() ? defaultName : args.output;
    const tool::FramePattern pattern = tool::parseFramePattern(outputName);
    if (args.frames > 1 && !pattern.hasField())
        throw Error("-o " + outputName + ": --frames " + std::to_string(args.frames) +
                    " needs a frame number field in the name, e.g. frame_%03d.png");
    // Every name is checked before anything is rendered.
    std::vector<fs::path> outputs;
    for (int k = 0; k < args.frames; ++k) outputs.push_back(tool::checkOutput(pattern.name(k), "-o"));
    // --debug-images DIR: a directory, or a name free for one, checked before anything is rendered.
    if (!args.debugImages.empty()) {
        std::error_code ec;
        if (fs::exists(args.debugImages, ec) && !fs::is_directory(args.debugImages, ec))
            throw Error("--debug-images " + args.debugImages + ": exists and is not a directory");
    }
    // Frame k at --time + k / --fps: the times are checked before the first frame too.
    std::vector<double> times;
    for (int k = 0; k < args.frames; ++k) {
        times.push_back(args.timeSeconds + k / args.fps);
        if (!std::isfinite(times.back()))
            throw Error("--time " + numberText(args.timeSeconds) + " --fps " + numberText(args.fps) + ": frame " + std::to_string(k) +
                        "'s time is not a finite number of seconds");
    }
    if (args.viewFromLight >= 0) {  // a missing light or a point light fails here, not after the first frame
        Scene first = sceneAtTime(loaded, times[0]);
        applyViewFromLight(first, args.viewFromLight);
    }
    checkMemory(args.width, args.height);
    Context context = Context::createHeadless();
    checkSize(args.width, args.height, context.info());
    Renderer renderer(context);
    renderer.upload(loaded);
    tool::MadeDirectories made;  // --debug-images DIR, if this run makes it (before the files in it)
    tool::PendingFiles pending;
    Scene scene = loaded;
    for (int k = 0; k < args.frames; ++k) {
        tool::throwIfInterrupted();
        const fs::path& output = outputs[static_cast<std::size_t>(k)];
        // The lights and the camera where their paths put them at this
        // frame's time, the camera from a light's view after it moved.
        const double t = times[static_cast<std::size_t>(k)];
        for (std::size_t l = 0; l < scene.lights.size(); ++l) scene.lights[l] = lightAtTime(loaded.lights[l], t);
        scene.camera = cameraAtTime(loaded.camera, t);
        applyViewFromLight(scene, args.viewFromLight);
        RenderOptions options;
        options.width = args.width;
        options.height = args.height;
        options.timeSeconds = t;
        printNotes(renderer.render(scene, options).notes);
        const ImageRGBA8 image = renderer.readColor();
        std::vector<DebugImage> debug;
        if (!args.debugImages.empty() || !args.debug.empty()) debug = renderer.debugImages(scene);
        requireNoGlErrors(context);  // before writing: no image from a failed frame
        pending.write(output, image);
        // --debug KIND: the images of that kind beside the output, <stem>-<image>.png.
        for (const DebugImage& d : debug)
            if (debugWanted(d.kind, args.debug)) pending.write(output.parent_path() / (output.stem().string() + "-" + d.name + ".png"), d.image);
        if (debugWanted(DebugImageKind::TexelDensity, args.debug)) noteLightsWithoutDensity(renderer, scene, debug, std::cerr);
        // --debug-images DIR: <image>.png, or <frame stem>-<image>.png for a sequence.
        if (!args.debugImages.empty()) {
            const fs::path dir(args.debugImages);
            if (k == 0) made.make(dir, "--debug-images " + args.debugImages);
            for (const DebugImage& d : debug)
                pending.write(dir / ((args.frames > 1 ? output.stem().string() + "-" : std::string()) + d.name + ".png"), d.image);
        }
    }
    const std::vector<fs::path> written = pending.commit();
    made.keep();
    for (const fs::path& path : written) std::cout << path.string() << "\n";
    return 0;
}

struct CompareArgs {
    std::string scene;
    std::string output = "compare";
    int width = 960;
    int height = 540;
    int softSamples = 256;
    std::vector<std::string> overrides;
    double timeSeconds = 0.0; ///< --time: the lights and the camera where their paths put them at this time, seconds
};

std::string pct(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f%%", 100.0 * share);
    return buf;
}

int runCompare(const CompareArgs& args) {
    checkTime(args.timeSeconds, "--time");
    // Both sides, technique and reference, see the lights and the camera at --time.
    const Scene scene = sceneAtTime(loadScene(args.scene, args.overrides), args.timeSeconds);
    const fs::path dir = tool::checkOutputDirectory(args.output);
    checkMemory(args.width, args.height);
    checkReferenceRays(args.width, args.height, args.softSamples);
    checkSceneReferenceRays(args.width, args.height, args.softSamples,
                            static_cast<std::size_t>(std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.size > 0.0f; })));
    Context context = Context::createHeadless();
    checkSize(args.width, args.height, context.info());
    Renderer renderer(context);
    renderer.upload(scene);
    CompareOptions options;
    options.width = args.width;
    options.height = args.height;
    options.softSamples = args.softSamples;
    options.timeSeconds = args.timeSeconds;
    // compareWithReference's three steps, so that an interrupt stops the trace.
    ComparisonJob job(renderer, scene, options);
    // On a terminal, a trace of seconds or more says that it has begun (a
    // soft light's rays per pixel, every light's pixels); a log or a pipe
    // gets the error line alone when it fails.
    double rays = 0.0;
    for (const Light& light : scene.lights)
        rays += static_cast<double>(args.width) * args.height * (light.size > 0.0f ? args.softSamples : 1);
    if (rays >= 1e8 && isatty(STDERR_FILENO)) std::fprintf(stderr, "compare: tracing the reference, %.3g rays\n", rays);
    tool::traceInterruptibly(job);
    const Comparison c = job.finish(renderer);
    // The lights whose technique drew them a light camera (a map): each
    // should have a texel footprint, and one that has none is said to have none.
    std::vector<bool> hasCamera(scene.lights.size(), false);
    for (const LightFrustum& f : renderer.lightFrustums(scene))
        if (f.light >= 0 && static_cast<std::size_t>(f.light) < hasCamera.size()) hasCamera[static_cast<std::size_t>(f.light)] = true;
    printNotes(c.techniqueFrame.notes);
    requireNoGlErrors(context);

    // Every file staged, then all renamed into place or none (OutputFiles.h).
    // Made here and the run fails: removed again once the files are (declared first, destroyed last).
    tool::MadeDirectories made;
    made.make(dir, "-o " + args.output);
    tool::PendingFiles pending;
    pending.write(dir / "technique.png", c.technique);
    pending.write(dir / "reference.png", c.reference);
    std::cout << "scene " << scene.name << ", " << args.width << "x" << args.height << ", reference traced in "
              << static_cast<long>(c.referenceMs) << " ms\n";
    for (std::size_t i = 0; i < c.lights.size(); ++i) {
        const LightComparison& l = c.lights[i];
        const Light& light = scene.lights[i];
        std::cout << "light " << i << " '" << l.name << "' (" << toString(light.type) << ", " << (l.soft ? "soft" : "hard")
                  << ", technique " << light.shadow.technique << "): " << l.receiverPixels << " receiver pixels, "
                  << pct(l.receiverPixels ? double(l.referenceShadowedPixels) / double(l.receiverPixels) : 0.0)
                  << " shadowed in truth\n"
                  << "  misclassified, all receivers:      false shadow " << pct(l.falseShadow) << ", false lit " << pct(l.falseLit) << "\n"
                  << "  misclassified, away from edges:    false shadow " << pct(l.falseShadowAwayFromEdges) << ", false lit "
                  << pct(l.falseLitAwayFromEdges) << " (" << l.edgePixels << " pixels in the 1-pixel edge band)\n"
                  << "  visibility error:                  MAE " << l.meanAbsError << ", RMSE " << l.rmse << "\n";
        if (l.coloured)
            std::cout << "  coloured light, RMSE per channel:  red " << l.rmseRgb[0] << ", green " << l.rmseRgb[1] << ", blue " << l.rmseRgb[2] << "\n";
        if (l.umbraPixels > 0) std::cout << "  light leaked into the umbra:       " << pct(l.leakedInUmbra) << " of the light (" << l.umbraPixels << " umbra pixels)\n";
        if (l.texelFootprintP50 >= 0.0)
            std::cout << "  texel footprint (pixels a texel):  median " << l.texelFootprintP50 << ", p95 " << l.texelFootprintP95 << ", max "
                      << l.texelFootprintMax << "\n";
        else if (hasCamera[i])  // a map with no texel-density image (the shadow atlas's tiles): said, not left out silently
            std::cout << "  texel footprint (pixels a texel):  not measured (the technique makes no texel-density image of this light's map)\n";
        if (l.soft)
            std::cout << "  penumbra:                          " << l.techniquePenumbraPixels << " pixels against " << l.referencePenumbraPixels
                      << " in truth (ratio " << l.penumbraRatio() << ")\n";
        const std::string index = std::to_string(i);
        pending.write(dir / ("error-" + index + ".png"), l.errorImage);
        pending.write(dir / ("visibility-" + index + ".png"), l.referenceVisibility);
        pending.write(dir / ("technique-visibility-" + index + ".png"), l.techniqueVisibility);
        pending.write(dir / ("reach-" + index + ".png"), l.reach);
    }
    const std::string metrics = comparisonMetricsJson(scene, args.scene, options, c, true);
    pending.write(dir / "metrics.json", [&](const fs::path& p) { writeFileAtomically(p, metrics); });
    const std::vector<fs::path> written = pending.commit();
    made.keep();
    std::cout << "wrote";
    for (const fs::path& p : written) std::cout << " " << p.string();
    std::cout << "\n";
    if (!c.lights.empty())
        std::cout << "error-<i>.png: red = lit where truth is shadowed (false lit), blue = shadowed where truth is lit (false shadow), "
                     "paler in the 1-pixel edge band; grey = agrees, darker grey = not a receiver\n";
    return 0;
}

int runBenchCommand(const tool::BenchArgs& args) {
    removeStaleTemporaries(args.output, "partial");  // what killed benches left, even if this one fails next
    for (const std::string& file : args.scenes) {
        if (file.empty()) throw Error("bench: empty scene path");
        if (text::invalidUtf8At(file) != std::string::npos)
            throw Error(text::escapeControl(file) + ": file name is not valid UTF-8 (results.json is UTF-8)");
        const fs::file_status status = tool::pathStatus(file, file);
        if (!fs::exists(status)) throw Error(file + ": file not found");
        if (!fs::is_regular_file(status)) throw Error(file + ": not a regular file (expected a scene file)");
    }
    tool::checkOutputDirectory(args.output.string());
    checkMemory(args.width, args.height);
    checkReferenceRays(args.width, args.height, args.softSamples);
    Context context = Context::createHeadless();
    checkSize(args.width, args.height, context.info());
    // Everything is written into a staging directory beside the output and
    // moved into place only when the whole run succeeded: a failure half way
    // (a texture past the GPU limit in the third scene) leaves nothing behind.
    StagingDirectory staging(args.output, "-o");
    tool::removeOnForcedEnd(staging.path(), tool::OnForcedEnd::Everything);  // if a second interrupt ends the run at once
    tool::BenchArgs staged = args;
    staged.output = staging.path();
    try {
        tool::runBenchInto(context, staged);
        requireNoGlErrors(context);
    } catch (const Error& e) {  // a file named where it goes, not in the staging directory
        throw Error(tool::naming(e.what(), staged.output.string(), args.output.string()));
    }
    staging.commit();
    std::cout << (args.output / "results.json").string() << "\n" << (args.output / "report.html").string() << "\n";
    return 0;
}

// The registered techniques and their options tables (the same tables the
// scene parser, --set, bench --vary and docs/scene-format.md use).
int runTechniques(bool markdown) {
    if (markdown) {
        std::cout << techniquesMarkdown();
        return 0;
    }
    for (const TechniqueInfo& t : techniques()) {
        // A light whose scene names no technique gets the default one.
        std::cout << t.name << (t.name == ShadowSettings{}.technique ? " (the default)" : "") << ": " << t.summary << "\n";
        for (const OptionField& f : t.options->fields)
            std::cout << "  lights[i].shadow." << t.name << "." << f.key << " = " << t.options->defaultText(f) << "  ("
                      << OptionTable::rangeText(f) << (f.unit.empty() ? "" : " " + f.unit) << ") " << f.doc << "\n";
    }
    return 0;
}

// Two --set of one path: the later would replace the earlier unchecked, so
// a bad earlier value would pass without a word; refused, as bench refuses
// a --vary of a path a --set sets.
void requireDistinctSets(const std::vector<std::string>& overrides) {
    const auto clash = overrideDiscarding(overrides);
    if (!clash) return;
    const std::string& later = overrides[clash->first];
    const std::string& earlier = overrides[clash->second];
    const std::string a = earlier.substr(0, earlier.find('=')), b = later.substr(0, later.find('='));
    if (overridePathsEqual(a, b)) throw Error("--set " + later + ": " + b + " is already set by --set " + earlier + " (give each path once)");
    throw Error("--set " + later + ": replaces " + a + ", set by --set " + earlier + " before it (set the inner path after the outer one, or within it)");
}

// An empty path given on purpose is an error, not "use the default".
void requireNonEmpty(const CLI::App* command, const char* option, const std::string& value, const std::string& what) {
    if (command->get_option(option)->count() > 0 && value.empty()) throw Error(what + ": empty path");
}

int runInfo() {
    Context context = Context::createHeadless();
    const GlInfo& i = context.info();
    std::cout << "shadowlab " << SHADOWLAB_VERSION << "\n"
              << "platform:           " << i.platform << "\n"
              << "GL vendor:          " << i.vendor << "\n"
              << "GL renderer:        " << i.renderer << "\n"
              << "GL version:         " << i.version << "\n"
              << "GLSL version:       " << i.glslVersion << "\n"
              << "max texture size:   " << i.maxTextureSize << "\n"
              << "max cube map size:  " << i.maxCubeMapSize << "\n"
              << "max array layers:   " << i.maxArrayLayers << "\n"
              << "max viewport:       " << i.maxViewportWidth << "x" << i.maxViewportHeight << "\n"
              << "device memory free: "
              << (i.deviceMemoryBytes > 0 ? std::to_string(i.deviceMemoryBytes / 1048576) + " MiB (" + i.deviceMemorySource + ")"
                                          : std::string("not reported by the driver"))
              << "\n"
              << "build: viewer " << (SHADOWLAB_VIEWER ? "on" : "off")
#ifdef SHADOWLAB_WITH_EMBREE
              << ", embree reference on"
#else
              << ", embree reference off"
#endif
              << "\n";
    return 0;
}

// Each subcommand's options, into the arguments its run function takes.
CLI::App* addRender(CLI::App& app, RenderArgs& args) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to a PNG image");
    render->add_option("scene", args.scene, "Scene file (JSON); the built-in default scene when omitted");
    render->add_option("-o,--output", args.output, "Output PNG (default: <scene name>.png)");
    render->add_option("--width", args.width, "Image width in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    render->add_option("--height", args.height, "Image height in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    render->add_option("--set", args.overrides, "Override a scene value by JSON path, e.g. lights[0].intensity=2")->take_all();
    render->add_option("--view-from-light", args.viewFromLight, "See the scene from light I's camera (spot: along its cone; directional: along its direction)")
        ->check(CLI::Range(0, static_cast<int>(kMaxLights) - 1));
    render->add_option("--debug", args.debug,
                       "Also write debug images beside the output as <name>-<image>.png: shadow-maps (each light's map, "
                       "perspective depth linearised; a point light's cube as a cross), texel-density (the texel footprint: screen pixels a map texel covers), cascades (the frame coloured by cascade), atlas (the shadow atlas's tiles, each light's outlined), all")
        ->check(CLI::IsMember({"shadow-maps", "texel-density", "cascades", "atlas", "all"}))
        ->delimiter(',');
    render->add_option("--debug-images", args.debugImages, "Also write the techniques' debug images (shadow maps, ...) into this directory");
    render->add_option("--time", args.timeSeconds, "Seconds since the start of the animation: where the light and camera paths are (the first frame's time)")
        ->capture_default_str();
    render->add_option("--frames", args.frames, "Render this many frames, frame k at --time + k / --fps; -o then needs a field such as %03d")
        ->check(CLI::Range(1, 100000))->capture_default_str();
    render->add_option("--fps", args.fps, "Frames per second of the sequence")->capture_default_str();
    return render;
}

CLI::App* addCompare(CLI::App& app, CompareArgs& args) {
    CLI::App* compare = app.add_subcommand("compare", "Compare a scene's shadow techniques with exact ray-traced shadows");
    compare->add_option("scene", args.scene, "Scene file (JSON); the built-in default scene when omitted");
    compare->add_option("-o,--output", args.output, "Output directory")->capture_default_str();
    compare->add_option("--width", args.width, "Image width in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    compare->add_option("--height", args.height, "Image height in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    compare->add_option("--samples", args.softSamples, "Reference rays per pixel for lights with a size")
        ->check(CLI::Range(1, kMaxSoftSamples))->capture_default_str();
    compare->add_option("--set", args.overrides, "Override a scene value by JSON path")->take_all();
    compare->add_option("--time", args.timeSeconds, "Seconds since the start of the animation: where the light and camera paths are")
        ->capture_default_str();
    return compare;
}

// -o into `output`, checked in main before it becomes args.output.
CLI::App* addBench(CLI::App& app, tool::BenchArgs& args, std::string& output) {
    CLI::App* bench = app.add_subcommand("bench", "Time and accuracy of every combination of settings, with results.json and report.html");
    bench->add_option("scenes", args.scenes, "Scene files (JSON); the built-in default scene when omitted");
    bench->add_option("--set", args.overrides, "Override a scene value for every run")->take_all();
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

#if SHADOWLAB_VIEWER
CLI::App* addView(CLI::App& app, ViewArgs& args) {
    CLI::App* view = app.add_subcommand("view", "Open a window on a scene with a panel of every light's technique and options (needs a display)");
    view->add_option("scene", args.scene, "Scene file (JSON); the built-in default scene when omitted");
    view->add_option("--set", args.overrides, "Override a scene value by JSON path, as for render")->take_all();
    view->add_option("--width", args.width, "Window width")->check(CLI::Range(64, 16384))->capture_default_str();
    view->add_option("--height", args.height, "Window height")->check(CLI::Range(64, 16384))->capture_default_str();
    view->add_option("--frames", args.frames, "Quit after this many frames (0: run until closed)")->check(CLI::Range(0, 1000000))->capture_default_str();
    view->add_option("--screenshot", args.screenshot, "With --frames: write the window's last frame (panel included) as this PNG");
    view->add_option("--script", args.script, "Run a file of actions, one per frame: set KEY=VALUE, wait N, screenshot FILE, quit");
    return view;
}
#endif

// Every option that takes a value refuses an empty one (`--time ''` was
// read as 0, `--debug-images ''` wrote nothing and exited 0).
void refuseEmptyValues(CLI::App& app) {
    const CLI::Validator nonEmpty([](std::string& value) { return value.empty() ? std::string("expected a value, got an empty string") : std::string(); },
                                  "", "non-empty");
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
        for (CLI::Option* option : command->get_options())
            // Positional scene paths and -o keep their own messages (requireNonEmpty, "empty path").
            if (option->get_type_size() != 0 && !option->get_positional() && option->get_name() != "--help" && option->get_name() != "--output")
                option->check(nonEmpty);
}

bool isCommand(CLI::App& app, const std::string& name) {
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
        if (command->get_name() == name) return true;
    return false;
}

std::string commandList(CLI::App& app) {
    std::string list;
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) list += " " + command->get_name();
    return list;
}

} // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // Keep the heap glibc would hand back to the system after every frame:
    // Mesa's software rasteriser frees its per-frame memory at the heap's
    // top, and taking those pages again the next frame costs page faults
    // (docs/history.md, "The heap"). Setting the trim
    // threshold fixes glibc's mmap threshold too, which would then map and
    // unmap every block over 128 KiB each frame: keep blocks up to the
    // largest threshold glibc takes (32 MiB) in the heap as well.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
    CLI::App app{"shadowlab: real-time shadows on OpenGL 4.5, measured against exact ray-traced shadows"};
    app.require_subcommand(1);
    app.failure_message([](const CLI::App*, const CLI::Error& e) { return "shadowlab: error: " + text::escapeControl(text::clipMiddle(e.what())) + "\n"; });

    RenderArgs renderArgs;
    CLI::App* render = addRender(app, renderArgs);
    CompareArgs compareArgs;
    CLI::App* compare = addCompare(app, compareArgs);
    tool::BenchArgs benchArgs;
    std::string benchOutput = "bench";
    CLI::App* bench = addBench(app, benchArgs, benchOutput);

    bool techniquesMarkdown = false;
    CLI::App* techniquesCommand = app.add_subcommand("techniques", "List the shadow techniques and their options");
    techniquesCommand->add_flag("--markdown", techniquesMarkdown, "Print the options tables as docs/scene-format.md carries them");

    CLI::App* info = app.add_subcommand("info", "Print the OpenGL implementation, its limits and the build options");

#if SHADOWLAB_VIEWER
    ViewArgs viewArgs;
    CLI::App* view = addView(app, viewArgs);
#endif

    refuseEmptyValues(app);
    tool::ignoreFileSizeSignal();
    if (argc > 1 && argv[1][0] != '-' && !isCommand(app, argv[1])) {
        std::cerr << "shadowlab: error: " << text::escapeControl(argv[1]) << ": not a command (expected one of" << commandList(app) << ")\n";
        return 1;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        requireNonEmpty(render, "scene", renderArgs.scene, "render: scene");
        requireNonEmpty(render, "--output", renderArgs.output, "-o");
        requireNonEmpty(compare, "scene", compareArgs.scene, "compare: scene");
        requireNonEmpty(compare, "--output", compareArgs.output, "-o");
        requireNonEmpty(bench, "--output", benchOutput, "-o");
        for (const std::vector<std::string>* sets : {&renderArgs.overrides, &compareArgs.overrides, &benchArgs.overrides}) requireDistinctSets(*sets);
#if SHADOWLAB_VIEWER
        requireDistinctSets(viewArgs.overrides);
#endif
        if (*render || *compare || *bench) tool::installInterruptHandlers();
#if SHADOWLAB_VIEWER
        if (*view) tool::installInterruptHandlers();  // the window loop stops at its next frame, as an error
#endif
        if (*render) return runRender(renderArgs);
        if (*compare) return runCompare(compareArgs);
        if (*bench) {
            checkTime(benchArgs.timeSeconds, "--time");
            checkFps(benchArgs.fps);
            benchArgs.output = benchOutput;
            return runBenchCommand(benchArgs);
        }
        if (*info) return runInfo();
#if SHADOWLAB_VIEWER
        if (*view) {
            if (!viewArgs.screenshot.empty() && viewArgs.frames == 0) throw Error("--screenshot: needs --frames N (the frame to take)");
            if (!viewArgs.screenshot.empty()) tool::checkOutput(viewArgs.screenshot, "--screenshot");
            checkMemory(viewArgs.width, viewArgs.height);  // the window's targets, as render's
            return runView(viewArgs);
        }
#endif
        if (*techniquesCommand) return runTechniques(techniquesMarkdown);
    } catch (const std::exception& e) {
        std::string message = e.what();
        // A file-system call that still throws: its path and reason, without the library's "filesystem error:" text.
        if (const auto* f = dynamic_cast<const fs::filesystem_error*>(&e))
            message = (f->path1().empty() ? std::string("a file") : f->path1().string()) + ": " + f->code().message();
        // Memory ran out past the frame-size checks (256 lights of unlimited
        // reach in one clustered list at 4096x4096 under an address-space
        // limit said "std::bad_alloc" alone): what to lower.
        if (dynamic_cast<const std::bad_alloc*>(&e))
            message = "out of memory (lower --width and --height, or the scene's lights, meshes or shadow map sizes)";
        if (*render) message = withValueSource(message, renderArgs.scene.empty() ? "the default scene" : renderArgs.scene, renderArgs.overrides);
        if (*compare) message = withValueSource(message, compareArgs.scene.empty() ? "the default scene" : compareArgs.scene, compareArgs.overrides);
#if SHADOWLAB_VIEWER
        if (*view) message = withValueSource(message, viewArgs.scene.empty() ? "the default scene" : viewArgs.scene, viewArgs.overrides);
#endif
        // Escaped once more here: whatever a message quotes, it stays one line.
        std::cerr << "shadowlab: error: " << text::escapeControl(text::clipMiddle(message)) << "\n";
        return 1;
    }
    return 1;
}
