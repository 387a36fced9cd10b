// The viewer's --script files (ViewerScript.h): read and checked whole before
// the window opens, then run one action a frame.
#include "ViewerScript.h"

#include "OutputFiles.h"
#include "ViewerSession.h"

#include <shadowlab/Limits.h>
#include <shadowlab/Error.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace shadowlab::viewer {

// A script is a small text file: at most this many bytes (100,000 frames of
// actions at ~10 bytes a line). A FIFO would block the viewer and /dev/zero
// would grow without end, so only regular files are read.
constexpr std::uintmax_t kMaxScriptBytes = 1u << 20;

std::vector<Action> readScript(const std::string& path) {
    const std::filesystem::file_status status = tool::pathStatus(path, "--script " + path);
    if (!std::filesystem::exists(status)) throw Error("--script " + path + ": no such file");
    if (!std::filesystem::is_regular_file(status)) throw Error("--script " + path + ": not a regular file (expected a script file)");
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (ec || bytes > kMaxScriptBytes)
        throw Error("--script " + path + ": " + (ec ? std::string("cannot read its size") : std::to_string(bytes) + " bytes, more than the limit of 1 MiB"));
    std::ifstream in(path);
    if (!in) throw Error("--script " + path + ": cannot open the script");
    std::vector<Action> out;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (text.find('\0') != std::string::npos) throw Error(path + ":" + std::to_string(line) + ": a NUL byte in the line (expected text)");
        const auto hash = text.find('#');
        if (hash != std::string::npos) text.resize(hash);
        std::istringstream words(text);
        Action a;
        a.line = line;
        if (!(words >> a.verb)) continue;
        std::getline(words, a.argument);
        a.argument.erase(0, a.argument.find_first_not_of(" \t"));
        while (!a.argument.empty() && (a.argument.back() == ' ' || a.argument.back() == '\t' || a.argument.back() == '\r')) a.argument.pop_back();
        const std::string where = path + ":" + std::to_string(line) + ": ";
        if (a.verb == "set") {
            if (a.argument.find('=') == std::string::npos) throw Error(where + "set: expected KEY=VALUE, got '" + a.argument + "'");
        } else if (a.verb == "wait") {
            char* end = nullptr;
            const long n = std::strtol(a.argument.c_str(), &end, 10);
            if (a.argument.empty() || *end != '\0' || n < 0 || n > 100000) throw Error(where + "wait: expected a number of frames 0..100000, got '" + a.argument + "'");
        } else if (a.verb == "screenshot" || a.verb == "save" || a.verb == "layout") {
            if (a.argument.empty()) throw Error(where + a.verb + ": expected a file name");
            // A screenshot is a PNG, as render -o's: refused before the first frame.
            if (a.verb == "screenshot") tool::checkOutput(a.argument, where + "screenshot");
            // The scene JSON's or the layout's name: not a directory, in one that exists.
            if (a.verb == "save" || a.verb == "layout") {
                const std::string what = where + a.verb + " " + a.argument;
                const std::filesystem::path file(a.argument), dir = file.parent_path();
                // pathStatus: a name in a loop of links or too long is this line's error too.
                if (std::filesystem::is_directory(tool::pathStatus(file, what)))
                    throw Error(what + ": is a directory (expected a file name for the " + (a.verb == "save" ? "scene JSON)" : "layout JSON)"));
                if (!dir.empty() && !std::filesystem::is_directory(tool::pathStatus(dir, what)))
                    throw Error(what + ": directory " + dir.string() + " does not exist");
            }
        } else if (a.verb == "resize") {
            std::istringstream size(a.argument);
            int w = 0, h = 0;
            std::string rest;
            if (!(size >> w >> h) || (size >> rest) || w < 64 || h < 64 || w > 16384 || h > 16384)
                throw Error(where + "resize: expected a width and a height, 64..16384, got '" + a.argument + "'");
            try {
                checkMemory(w, h);  // the window's targets, as --width and --height's (GL's limits: when it runs)
            } catch (const Error& e) {
                throw Error(where + "resize " + a.argument + ": " + e.what());
            }
        } else if (a.verb == "compare") {
            // An optional directory for the error images: it must exist before anything is traced.
            if (!a.argument.empty() && !std::filesystem::is_directory(tool::pathStatus(a.argument, where + "compare " + a.argument)))
                throw Error(where + "compare " + a.argument + ": not a directory (the error images go there; create it first)");
        } else if (a.verb != "quit" && a.verb != "minimize" && a.verb != "restore" && a.verb != "show-maps" && a.verb != "show-light" &&
                   a.verb != "show-density" && a.verb != "hide-maps" && a.verb != "hide-light" && a.verb != "hide-density" && a.verb != "uploads" &&
                   a.verb != "collapse-panel" && a.verb != "expand-panel") {
            throw Error(where + "unknown action '" + a.verb +
                        "' (expected set, wait, screenshot, save, layout, show-maps, show-light, show-density, hide-maps, hide-light, hide-density, compare, "
                        "uploads, resize, minimize, restore, collapse-panel, expand-panel or quit)");
        } else if (!a.argument.empty()) {
            throw Error(where + a.verb + ": expected nothing after it, got '" + a.argument + "'");
        }
        out.push_back(a);
    }
    return out;
}

void ViewerSession::runScript() {
    // The script: one action per frame, "wait N" holds it N frames, a
    // comparison holds it until the reference is traced.
    while (waitFrames == 0 && nextAction < script.size() && !referenceAsked && !tracing && !resizing()) {
        const Action& a = script[nextAction++];
        if (a.verb == "set") {
            const auto eq = a.argument.find('=');
            apply(a.argument.substr(0, eq), a.argument.substr(eq + 1));
            if (!error.empty()) throw Error(args.script + ":" + std::to_string(a.line) + ": " + error);
            scriptSets.emplace_back(a.argument, args.script + ":" + std::to_string(a.line) + ": set " + a.argument);
        } else if (a.verb == "wait") {
            waitFrames = std::stoi(a.argument);
        } else if (a.verb == "screenshot" || a.verb == "layout") {
            --nextAction;  // taken after this frame is drawn
            break;
        } else if (a.verb == "save") {
            try {
                save(a.argument);
            } catch (const Error& e) {
                throw Error(args.script + ":" + std::to_string(a.line) + ": save: " + e.what());
            }
            std::cout << a.argument << "\n";
        } else if (a.verb == "resize") {
            std::istringstream size(a.argument);
            int w = 0, h = 0;
            size >> w >> h;
            try {
                checkSize(w, h, context.info());  // GL's limits and the device's memory
            } catch (const Error& e) {
                throw Error(args.script + ":" + std::to_string(a.line) + ": resize " + a.argument + ": " + e.what());
            }
            glfwSetWindowSize(window, w, h);
            scriptResize = args.script + ":" + std::to_string(a.line) + ": resize " + a.argument;
            resizeWidth = w;  // the next action waits for a frame of this size (endFrame)
            resizeHeight = h;
            resizeFrames = 0;
        } else if (a.verb == "uploads") {
            std::cout << "uploads: " << uploads << "\n";  // how often the scene was read whole and uploaded
        } else if (a.verb == "show-maps") {
            showDebug = true;
        } else if (a.verb == "show-light") {
            showLight = true;
        } else if (a.verb == "show-density") {
            showDensity = true;
        } else if (a.verb == "hide-maps") {  // each view off again (a script could turn them on only)
            showDebug = false;
        } else if (a.verb == "hide-light") {
            showLight = false;
        } else if (a.verb == "hide-density") {
            showDensity = false;
        } else if (a.verb == "compare") {
            referenceAsked = true;
            referenceAskedAt = frame;
            compareDirectory = a.argument;
            compareLabel = args.script + ":" + std::to_string(a.line) + ": compare " + a.argument;
            break;
        } else if (a.verb == "collapse-panel" || a.verb == "expand-panel") {
            collapsePanel = a.verb == "collapse-panel" ? 1 : 0;
        } else if (a.verb == "minimize") {
            glfwIconifyWindow(window);
        } else if (a.verb == "restore") {
            glfwRestoreWindow(window);
        } else if (a.verb == "quit") {
            quit = true;
        }
    }
}

} // namespace shadowlab::viewer
