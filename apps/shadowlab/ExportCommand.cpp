// `shadowlab export` (ExportCommand.h).
#include "ExportCommand.h"

#include "Commands.h"
#include "OutputFiles.h"

#include <shadowlab/GltfExport.h>

#include <cctype>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace shadowlab::tool {

CLI::App* addExport(CLI::App& app, ExportArgs& args) {
    CLI::App* command = app.add_subcommand("export", "Write a scene as one glTF file with its camera and lights, which every command opens again");
    command->add_option("scene", args.scene, "Scene file (JSON or glTF); the built-in default scene when omitted");
    command->add_option("-o,--output", args.output, "Output .gltf (JSON, the buffer embedded) or .glb (binary); default <scene name>.gltf");
    command->add_option("--set", args.overrides, "Override a scene value by JSON path before writing, e.g. lights[0].intensity=2")->take_all();
    command->add_option("--camera", args.camera, "A glTF file's camera: its index among those the file's scene places, from 0 (default: the first)")->check(CLI::Range(0, 65535));
    return command;
}

int runExport(const ExportArgs& args) {
    const Scene scene = loadScene(args.scene, args.overrides, args.camera);
    const std::string name = args.output.empty() ? (args.scene.empty() ? std::string("default") : fs::path(args.scene).stem().string()) + ".gltf" : args.output;
    std::string extension = fs::path(name).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".gltf" && extension != ".glb") throw Error("-o " + name + ": expected a .gltf or .glb file name");
    const fs::path output = checkOutput(name, "-o", extension);
    for (const std::string& note : writeGltfScene(scene, output)) std::cerr << "shadowlab: note: " << note << "\n";
    std::cout << "wrote " << output.string() << "\n";
    return 0;
}

} // namespace shadowlab::tool
