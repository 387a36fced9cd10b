// `shadowlab view`'s options (ViewCommand.h).
#include "ViewCommand.h"

namespace shadowlab::tool {

CLI::App* addView(CLI::App& app, ViewArgs& args) {
    CLI::App* view = app.add_subcommand("view", "Open a window on a scene with a panel of every light's technique and options (needs a display)");
    view->add_option("scene", args.scene, "Scene file (JSON); the built-in default scene when omitted");
    view->add_option("--set", args.overrides, "Override a scene value by JSON path, as for render")->take_all();
    view->add_option("--camera", args.camera, "A glTF file's camera: its index among those the file's scene places, from 0 (default: the first)")->check(CLI::Range(0, 65535));
    view->add_option("--width", args.width, "Window width")->check(CLI::Range(64, 16384))->capture_default_str();
    view->add_option("--height", args.height, "Window height")->check(CLI::Range(64, 16384))->capture_default_str();
    view->add_option("--frames", args.frames, "Quit after this many frames (0: run until closed)")->check(CLI::Range(0, 1000000))->capture_default_str();
    view->add_option("--screenshot", args.screenshot, "With --frames: write the window's last frame (panel included) as this PNG");
    view->add_option("--script", args.script, "Run a file of actions, one per frame: set KEY=VALUE, wait N, screenshot FILE, save FILE, layout FILE (the panel's windows and options as JSON), show-maps, show-light, show-density (hide-...), compare [DIR], resize W H, minimize, restore, collapse-panel, expand-panel, uploads, quit");
    return view;
}

} // namespace shadowlab::tool
