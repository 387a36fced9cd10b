// `shadowlab render` (RenderCommand.h).
#include "RenderCommand.h"

#include "Commands.h"
#include "Interrupt.h"
#include "OutputFiles.h"

#include <shadowlab/DebugImage.h>
#include <shadowlab/Limits.h>
#include <shadowlab/Renderer.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace shadowlab::tool {

namespace {

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

} // namespace

// Each subcommand's options, into the arguments its run function takes.
CLI::App* addRender(CLI::App& app, RenderArgs& args) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to a PNG image");
    render->add_option("scene", args.scene, "Scene file (JSON); the built-in default scene when omitted");
    render->add_option("-o,--output", args.output, "Output PNG (default: <scene name>.png)");
    render->add_option("--width", args.width, "Image width in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    render->add_option("--height", args.height, "Image height in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    render->add_option("--set", args.overrides, "Override a scene value by JSON path, e.g. lights[0].intensity=2")->take_all();
    render->add_option("--camera", args.camera, "A glTF file's camera: its index among those the file's scene places, from 0 (default: the first)")->check(CLI::Range(0, 65535));
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

int runRender(const RenderArgs& args) {
    checkTime(args.timeSeconds, "--time");
    checkFps(args.fps);
    const Scene loaded = loadScene(args.scene, args.overrides, args.camera);
    // Without -o: <scene>.png, or <scene>-%03d.png for a sequence.
    std::string stem = args.scene.empty() ? std::string("default") : fs::path(args.scene).stem().string();
    for (std::size_t at = stem.find('%'); at != std::string::npos; at = stem.find('%', at + 2)) stem.insert(at, "%");
    const std::string defaultName = stem + (args.frames > 1 ? "-%03d" : "") + ".png";
    const std::string outputName = args.output.empty() ? defaultName : args.output;
    const FramePattern pattern = parseFramePattern(outputName);
    if (args.frames > 1 && !pattern.hasField())
        throw Error("-o " + outputName + ": --frames " + std::to_string(args.frames) +
                    " needs a frame number field in the name, e.g. frame_%03d.png");
    // Every name is checked before anything is rendered.
    std::vector<fs::path> outputs;
    for (int k = 0; k < args.frames; ++k) outputs.push_back(checkOutput(pattern.name(k), "-o"));
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
            throw Error("--time " + text::numberText(args.timeSeconds) + " --fps " + text::numberText(args.fps) + ": frame " + std::to_string(k) +
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
    MadeDirectories made;  // --debug-images DIR, if this run makes it (before the files in it)
    PendingFiles pending;
    Scene scene = loaded;
    for (int k = 0; k < args.frames; ++k) {
        throwIfInterrupted();
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

} // namespace shadowlab::tool
