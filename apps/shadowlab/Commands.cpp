// The tool's subcommands' shared checks and helpers (Commands.h).
#include "Commands.h"

#include <cstdio>

#include <cmath>
#include <iostream>
#include <set>

namespace shadowlab::tool {

void printNotes(const std::vector<std::string>& notes) {
    static std::set<std::string> printed;
    for (const std::string& note : notes)
        if (printed.insert(note).second) std::cerr << "shadowlab: note: " << note << "\n";
}

void checkTime(double seconds, const std::string& flag) {
    if (!std::isfinite(seconds)) throw Error(flag + " " + text::numberText(seconds) + ": expected a finite number of seconds");
}
void checkFps(double fps) {
    if (!std::isfinite(fps) || !(fps > 0.0)) throw Error("--fps " + text::numberText(fps) + ": expected a finite number of frames per second > 0");
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides, int camera) {
    if (path.empty() && camera >= 0) throw Error("--camera " + std::to_string(camera) + ": needs a glTF file (the default scene has one camera)");
    Scene scene = path.empty() ? defaultScene(overrides) : loadSceneFile(path, overrides, SceneFileOptions{camera});
    for (const std::string& note : scene.notes) std::fprintf(stderr, "shadowlab: note: %s\n", note.c_str());
    return scene;
}

void requireNoGlErrors(const Context& context) {
    if (context.debugErrorCount() > 0)
        throw Error("OpenGL reported " + std::to_string(context.debugErrorCount()) + " error(s); last: " + context.lastDebugError());
}

void requireDistinctSets(const std::vector<std::string>& overrides) {
    const auto clash = overrideDiscarding(overrides);
    if (!clash) return;
    const std::string& later = overrides[clash->first];
    const std::string& earlier = overrides[clash->second];
    const std::string a = earlier.substr(0, earlier.find('=')), b = later.substr(0, later.find('='));
    if (overridePathsEqual(a, b)) throw Error("--set " + later + ": " + b + " is already set by --set " + earlier + " (give each path once)");
    throw Error("--set " + later + ": replaces " + a + ", set by --set " + earlier + " before it (set the inner path after the outer one, or within it)");
}

void requireNonEmpty(const CLI::App* command, const char* option, const std::string& value, const std::string& what) {
    if (command->get_option(option)->count() > 0 && value.empty()) throw Error(what + ": empty path");
}

} // namespace shadowlab::tool
