// shadowlab: the command-line tool. Subcommands:
//   render [SCENE.json] -o out.png [--width W --height H] [--set key=value ...]
//   info
// Every failure prints one line `shadowlab: error: ...` and exits non-zero;
// no output file is written unless the whole render succeeded.
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace shadowlab;

namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    int width = 1280;
    int height = 720;
    std::vector<std::string> overrides;
};

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
    return path.empty() ? defaultScene(overrides) : loadSceneFile(path, overrides);
}

// Checks an output path before any work is done, so bad paths fail fast.
fs::path checkOutput(const std::string& output, const std::string& flag) {
    const fs::path path(output);
    if (path.extension() != ".png" && path.extension() != ".PNG")
        throw Error(flag + " " + output + ": expected a .png file name");
    const fs::path dir = path.parent_path();
    if (!dir.empty() && !fs::is_directory(dir))
        throw Error(flag + " " + output + ": directory " + dir.string() + " does not exist");
    return path;
}

void checkSize(const RenderArgs& args, const GlInfo& info) {
    const int limit = std::min({info.maxTextureSize, info.maxViewportWidth, info.maxViewportHeight});
    if (args.width > limit) throw Error("--width " + std::to_string(args.width) + ": exceeds this GPU's limit of " + std::to_string(limit) + " pixels");
    if (args.height > limit) throw Error("--height " + std::to_string(args.height) + ": exceeds this GPU's limit of " + std::to_string(limit) + " pixels");
}

int runRender(const RenderArgs& args) {
    const Scene scene = loadScene(args.scene, args.overrides);
    const std::string defaultName = (args.scene.empty() ? std::string("default") : fs::path(args.scene).stem().string()) + ".png";
    const fs::path output = checkOutput(args.output.empty() ? defaultName : args.output, "-o");
    Context context = Context::createHeadless();
    checkSize(args, context.info());
    Renderer renderer(context);
    renderer.upload(scene);
    renderer.render(scene, {args.width, args.height});
    writePng(output, renderer.readColor());
    if (context.debugErrorCount() > 0)
        throw Error("OpenGL reported " + std::to_string(context.debugErrorCount()) + " error(s); last: " + context.lastDebugError());
    std::cout << output.string() << "\n";
    return 0;
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
              << "build: viewer " << (SHADOWLAB_VIEWER ? "on" : "off")
#ifdef SHADOWLAB_WITH_EMBREE
              << ", embree reference on"
#else
              << ", embree reference off"
#endif
              << "\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"shadowlab: real-time shadows on OpenGL 4.5, measured against exact ray-traced shadows"};
    app.require_subcommand(1);
    app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string("shadowlab: error: ") + e.what() + "\n"; });

    RenderArgs renderArgs;
    CLI::App* render = app.add_subcommand("render", "Render a scene to a PNG image");
    render->add_option("scene", renderArgs.scene, "Scene file (JSON); the built-in default scene when omitted");
    render->add_option("-o,--output", renderArgs.output, "Output PNG (default: <scene name>.png)");
    render->add_option("--width", renderArgs.width, "Image width in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    render->add_option("--height", renderArgs.height, "Image height in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    render->add_option("--set", renderArgs.overrides, "Override a scene value by JSON path, e.g. lights[0].intensity=2")->take_all();

    CLI::App* info = app.add_subcommand("info", "Print the OpenGL implementation, its limits and the build options");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (*render) return runRender(renderArgs);
        if (*info) return runInfo();
    } catch (const Error& e) {
        std::cerr << "shadowlab: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "shadowlab: error: " << e.what() << "\n";
        return 1;
    }
    return 1;
}
