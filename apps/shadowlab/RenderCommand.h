#pragma once
// `shadowlab render`: a scene to a PNG image, or a sequence of frames, with
// the techniques' debug images beside it (RenderCommand.cpp).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowlab::tool {

struct RenderArgs {
    std::string scene;
    std::string output;
    int width = 1280;
    int height = 720;
    std::vector<std::string> overrides;
    int camera = -1;          ///< --camera: a glTF file's camera; -1 its first
    std::string debugImages;  ///< directory for the techniques' debug images; empty = none
    std::vector<std::string> debug; ///< --debug: which debug images to write beside the output (shadow-maps, texel-density, all)
    int viewFromLight = -1;   ///< --view-from-light: the light whose view replaces the camera; -1 none
    double timeSeconds = 0.0; ///< --time: seconds since the start of the animation, of the first frame
    int frames = 1;           ///< --frames: how many frames, each 1/fps seconds after the previous
    double fps = 30.0;        ///< --fps: frames per second of the sequence, > 0
};

/// The subcommand and its options, into `args`.
CLI::App* addRender(CLI::App& app, RenderArgs& args);
/// Renders; 0 when every file was written (an error throws).
int runRender(const RenderArgs& args);

} // namespace shadowlab::tool
