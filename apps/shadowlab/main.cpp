// shadowlab: the command-line tool. Subcommands:
//   render [SCENE.json] -o out.png [--width W --height H] [--set key=value ...]
//          [--time T] [--frames N --fps F -o frame_%03d.png]
//   compare [SCENE.json] [-o DIR] [--set ...] [--time T]  technique vs ray-traced reference
//   bench [SCENES...] [--set ...] [--vary key=v1,v2] [--frames N] [--rounds R] [--time T --fps F] [--flips] [-o DIR]
//   export [SCENE] -o out.gltf [--set ...]  the scene as one glTF file with its camera and lights
//   info
// Every failure prints one line `shadowlab: error: ...` and exits non-zero;
// no output file is written unless the whole render succeeded.
#include "BenchCommand.h"
#include "Commands.h"
#include "CompareCommand.h"
#include "ExportCommand.h"
#include "InfoCommands.h"
#include "Interrupt.h"
#include "OutputFiles.h"
#include "RenderCommand.h"
#if SHADOWLAB_VIEWER
#include "ViewCommand.h"
#endif

#include <shadowlab/Error.h>
#include <shadowlab/Limits.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Text.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>  // mallopt
#endif

namespace fs = std::filesystem;
using namespace shadowlab;
using namespace shadowlab::tool;

namespace {

// Every subcommand's arguments and its CLI11 command (kept where main
// made them: the commands hold pointers into the arguments).
struct Commands {
    RenderArgs render;
    CompareArgs compare;
    BenchArgs bench;
    ExportArgs exportScene;
    std::string benchOutput = "bench";
    bool techniquesMarkdown = false;
    CLI::App* renderCommand = nullptr;
    CLI::App* compareCommand = nullptr;
    CLI::App* benchCommand = nullptr;
    CLI::App* exportCommand = nullptr;
    CLI::App* techniquesCommand = nullptr;
    CLI::App* infoCommand = nullptr;
#if SHADOWLAB_VIEWER
    ViewArgs view;
    CLI::App* viewCommand = nullptr;
#endif
};

void addCommands(CLI::App& app, Commands& c) {
    c.renderCommand = addRender(app, c.render);
    c.compareCommand = addCompare(app, c.compare);
    c.benchCommand = addBench(app, c.bench, c.benchOutput);
    c.exportCommand = addExport(app, c.exportScene);
    c.techniquesCommand = app.add_subcommand("techniques", "List the shadow techniques and their options");
    c.techniquesCommand->add_flag("--markdown", c.techniquesMarkdown, "Print the options tables as docs/scene-format.md carries them");
    c.infoCommand = app.add_subcommand("info", "Print the OpenGL implementation, its limits and the build options");
#if SHADOWLAB_VIEWER
    c.viewCommand = addView(app, c.view);
#endif
}

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

// The parsed command's checks, then the command itself.
int run(const Commands& c) {
    requireNonEmpty(c.renderCommand, "scene", c.render.scene, "render: scene");
    requireNonEmpty(c.renderCommand, "--output", c.render.output, "-o");
    requireNonEmpty(c.compareCommand, "scene", c.compare.scene, "compare: scene");
    requireNonEmpty(c.compareCommand, "--output", c.compare.output, "-o");
    requireNonEmpty(c.benchCommand, "--output", c.benchOutput, "-o");
    requireNonEmpty(c.exportCommand, "scene", c.exportScene.scene, "export: scene");
    requireNonEmpty(c.exportCommand, "--output", c.exportScene.output, "-o");
    for (const std::vector<std::string>* sets : {&c.render.overrides, &c.compare.overrides, &c.bench.overrides, &c.exportScene.overrides}) requireDistinctSets(*sets);
#if SHADOWLAB_VIEWER
    requireDistinctSets(c.view.overrides);
#endif
    if (*c.renderCommand || *c.compareCommand || *c.benchCommand) installInterruptHandlers();
#if SHADOWLAB_VIEWER
    if (*c.viewCommand) installInterruptHandlers();  // the window loop stops at its next frame, as an error
#endif
    if (*c.renderCommand) return runRender(c.render);
    if (*c.compareCommand) return runCompare(c.compare);
    if (*c.benchCommand) {
        checkTime(c.bench.timeSeconds, "--time");
        checkFps(c.bench.fps);
        BenchArgs args = c.bench;
        args.output = c.benchOutput;
        return runBenchCommand(args);
    }
    if (*c.exportCommand) return runExport(c.exportScene);
    if (*c.infoCommand) return runInfo();
#if SHADOWLAB_VIEWER
    if (*c.viewCommand) {
        if (!c.view.screenshot.empty() && c.view.frames == 0) throw Error("--screenshot: needs --frames N (the frame to take)");
        if (!c.view.screenshot.empty()) checkOutput(c.view.screenshot, "--screenshot");
        checkMemory(c.view.width, c.view.height);  // the window's targets, as render's
        return runView(c.view);
    }
#endif
    if (*c.techniquesCommand) return runTechniques(c.techniquesMarkdown);
    return 1;
}

// The one line a failure prints: the message, where the value came from.
std::string failureMessage(const std::exception& e, const Commands& c) {
    std::string message = e.what();
    // A file-system call that still throws: its path and reason, without the library's "filesystem error:" text.
    if (const auto* f = dynamic_cast<const fs::filesystem_error*>(&e))
        message = (f->path1().empty() ? std::string("a file") : f->path1().string()) + ": " + f->code().message();
    // Memory ran out past the frame-size checks (256 lights of unlimited
    // reach in one clustered list at 4096x4096 under an address-space
    // limit said "std::bad_alloc" alone): what to lower.
    if (dynamic_cast<const std::bad_alloc*>(&e))
        message = "out of memory (lower --width and --height, or the scene's lights, meshes or shadow map sizes)";
    if (*c.renderCommand) message = withValueSource(message, c.render.scene.empty() ? "the default scene" : c.render.scene, c.render.overrides);
    if (*c.compareCommand) message = withValueSource(message, c.compare.scene.empty() ? "the default scene" : c.compare.scene, c.compare.overrides);
#if SHADOWLAB_VIEWER
    if (*c.viewCommand) message = withValueSource(message, c.view.scene.empty() ? "the default scene" : c.view.scene, c.view.overrides);
#endif
    return message;
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
    Commands commands;
    addCommands(app, commands);
    refuseEmptyValues(app);
    ignoreFileSizeSignal();
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
        return run(commands);
    } catch (const std::exception& e) {
        // Escaped once more here: whatever a message quotes, it stays one line.
        std::cerr << "shadowlab: error: " << text::escapeControl(text::clipMiddle(failureMessage(e, commands))) << "\n";
        return 1;
    }
}
