#pragma once
// `shadowlab view`: the interactive viewer (GLFW window, Dear ImGui panel)
// on the same renderer as the command line.
#include <string>
#include <vector>

namespace shadowlab {

struct ViewArgs {
    std::string scene;                   ///< scene file; the built-in default scene when empty
    std::vector<std::string> overrides;  ///< --set lines, applied before the panel's own
    int camera = -1;                     ///< --camera: a glTF file's camera; -1 its first
    int width = 1280, height = 720;      ///< window size, screen coordinates
    int frames = 0;                      ///< > 0: quit after this many frames (with --screenshot: write it first)
    std::string screenshot;              ///< with --frames: the window's last frame as a PNG
    std::string script;                  ///< a file of actions (README, "The viewer"), run one per frame
};

/// Opens the window and runs until it is closed (or --frames / the script
/// ends it). Returns the process exit code; throws shadowlab::Error for a
/// bad scene, script or missing display.
int runView(const ViewArgs& args);

} // namespace shadowlab
