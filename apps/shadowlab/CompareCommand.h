#pragma once
// `shadowlab compare`: a scene's shadow techniques against exact ray-traced
// shadows, with the images and metrics.json (CompareCommand.cpp).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowlab::tool {

struct CompareArgs {
    std::string scene;
    std::string output = "compare";
    int width = 960;
    int height = 540;
    int softSamples = 256;
    std::vector<std::string> overrides;
    int camera = -1;  ///< --camera: a glTF file's camera; -1 its first
    double timeSeconds = 0.0; ///< --time: the lights and the camera where their paths put them at this time, seconds
};

/// The subcommand and its options, into `args`.
CLI::App* addCompare(CLI::App& app, CompareArgs& args);
/// Compares; 0 when every file was written (an error throws).
int runCompare(const CompareArgs& args);

} // namespace shadowlab::tool
