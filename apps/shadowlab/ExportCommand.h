#pragma once
// `shadowlab export`: a scene written as one glTF file with its camera and
// lights (ExportCommand.cpp; the library's writeGltfScene, GltfExport.h).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowlab::tool {

struct ExportArgs {
    std::string scene;
    std::string output;
    std::vector<std::string> overrides;
    int camera = -1;  ///< --camera: a glTF file's camera; -1 its first
};

/// The subcommand and its options, into `args`.
CLI::App* addExport(CLI::App& app, ExportArgs& args);
/// Writes the file; 0 when it was written (an error throws).
int runExport(const ExportArgs& args);

} // namespace shadowlab::tool
