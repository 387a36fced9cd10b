#pragma once
// One run of `shadowlab view` (Viewer.h): the window, the scene and the
// settings made on it, the camera, and what the panel and the picture show.
// Its work is split by part: the window loop and the scene read again or
// saved (Viewer.cpp), the script (ViewerScript.cpp), mouse and keys
// (ViewerControls.cpp), the panel (ViewerPanel.cpp), what is drawn over the
// picture (ViewerOverlay.cpp), and the images read back for them: the
// comparison with the reference and the techniques' debug images
// (ViewerImages.cpp).
#include "OutputFiles.h"
#include "Viewer.h"
#include "ViewerScript.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Context.h>
#include <shadowlab/Image.h>
#include <shadowlab/ImageTexture.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/Techniques.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <any>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace shadowlab::viewer {

/// `s` as a JSON string (quoted, escaped): override values and the layout file (ViewerLayout.cpp).
std::string jsonQuoted(const std::string& s);

// The settings made in the viewer, in the order made (a later one of the
// same key replaces an earlier one), after the command line's --set lines.
struct Overrides {
    std::vector<std::string> fromCommandLine;
    std::vector<std::pair<std::string, std::string>> made;
    void set(const std::string& key, const std::string& value) {
        for (auto& [k, v] : made)
            if (k == key) {
                v = value;
                return;
            }
        made.emplace_back(key, value);
    }
    std::vector<std::string> all() const {
        std::vector<std::string> out = fromCommandLine;
        for (const auto& [k, v] : made) out.push_back(k + "=" + v);
        return out;
    }
};

// An orbiting camera around the scene camera's target.
struct Orbit {
    glm::vec3 target{0.0f};
    float distance = 10.0f, yaw = 0.0f, pitch = 0.3f;
    void from(const Camera& c) {
        target = c.target;
        const glm::vec3 d = c.position - c.target;
        distance = std::max(glm::length(d), 1e-3f);
        yaw = std::atan2(d.x, d.z);
        pitch = std::asin(std::clamp(d.y / distance, -1.0f, 1.0f));
    }
    glm::vec3 position() const {
        return target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    }
};

// A comparison with the ray-traced reference in flight: the technique's
// frame was read when it was asked for; the tracing runs on a worker thread
// while the window goes on drawing; the result is classified on the window's
// thread once `done`. Destroying it cancels the tracing and waits for it.
struct ReferenceRun {
    std::unique_ptr<ComparisonJob> job;
    std::thread worker;
    std::atomic<bool> done{false};
    std::string error;  ///< the worker's failure, written before `done`
    std::string directory;  ///< the script's "compare DIR": where the error images go
    std::string label;      ///< the script line that asked for it ("s.txt:4: compare DIR"), for its errors
    int startFrame = 0;     ///< the window's frame when it started
    ReferenceRun() = default;
    ReferenceRun(const ReferenceRun&) = delete;
    ReferenceRun& operator=(const ReferenceRun&) = delete;
    ~ReferenceRun() {
        if (job) job->cancel();
        if (worker.joinable()) worker.join();
    }
};

class ViewerSession {
public:
    /// Reads the script and the scene (a bad one is the command's error,
    /// before any window), then opens the window.
    explicit ViewerSession(const ViewArgs& viewArgs);
    ViewerSession(const ViewerSession&) = delete;
    ViewerSession& operator=(const ViewerSession&) = delete;

    /// Draws frames until the window is closed or --frames / the script ends
    /// it; returns the exit code.
    int run();

private:
    // Viewer.cpp: the scene with every setting, and the window loop's steps.
    Scene load() const;
    void reload();
    void save(const std::filesystem::path& path);
    void apply(const std::string& key, const std::string& value);
    bool applyToLights(const std::string& key);
    std::string sceneText() const;
    void reloadIfChanged();
    void renderFrame(int width, int height);
    void endFrame(int width, int height, bool screenshotKey);
    void timeFrame();
    // ViewerScript.cpp
    void runScript();
    // ViewerImages.cpp
    void startComparison(int width, int height);
    void finishComparison();
    void refreshDebugImages();
    void freeReferenceTextures() { referenceTextures.clear(); }
    void freeDebugTextures() { debugTextures.clear(); }
    // ViewerControls.cpp
    void handleMouse(int height);
    bool handleKeys();
    // ViewerPanel.cpp
    void drawPanel(int height, bool& screenshotKey);
    void drawComparison();
    void drawLight(std::size_t l, const std::vector<TechniqueInfo>& all);
    void drawOptions(const Light& light, int index, const std::string& at);
    void drawOption(const OptionField& f, const std::any& current, const std::string& key, const std::string& label);
    // ViewerMaps.cpp
    void drawMapsWindow(int width, int height);
    // ViewerLayout.cpp
    void noteWindow(const char* name);
    std::string layoutJson() const;
    // ViewerOverlay.cpp
    void drawOverlay(int width, int height);

    // Declared in the order made: destroyed in reverse, the GL objects
    // before the renderer and the window's context.
    const ViewArgs& args;
    const bool fromFile;
    std::vector<Action> script;
    Overrides overrides;
    /// The script's `set` lines applied so far: KEY=VALUE and "FILE:LINE: set KEY=VALUE",
    /// so that an error a later frame raises about that value names the line.
    std::vector<std::pair<std::string, std::string>> scriptSets;
    /// The script line of the last resize ("FILE:LINE: resize W H"): named by
    /// a frame that then runs out of GPU memory.
    std::string scriptResize;
    /// A script's resize holds the script until a frame is drawn at that
    /// window size (the window system applies it some frames later), or
    /// kResizeFrames frames have passed (a window manager may refuse it).
    int resizeWidth = 0, resizeHeight = 0, resizeFrames = 0;
    static constexpr int kResizeFrames = 120;
    bool resizing() const { return resizeWidth > 0; }
    Scene scene;
    Context context;
    GLFWwindow* window;
    Renderer renderer;
    Orbit orbit;
    bool cameraMoved = false;
    std::string error;  // the last failed reload or setting, shown in the panel
    int uploads = 0;    // scene reads uploaded to the renderer (the script's "uploads" prints it)
    std::filesystem::file_time_type fileTime;
    std::deque<float> frameTimes;
    FrameStats stats;
    double seconds = 0.0;
    bool playing = false;
    int frame = 0, waitFrames = 0;
    std::size_t nextAction = 0;
    bool quit = false;
    std::map<int, bool> keysDown;
    int viewFromLight = -1;   // a light's own camera as the viewer's, -1: the orbit
    int selectedLight = 0;    // the light Shift + drag moves, and whose cone is drawn
    bool showLight = false;   // the selected light in wireframe over the picture
    bool showDebug = false;   // the techniques' debug images (maps, cube crosses) in a window of their own
    bool showDensity = false; // the selected light's texel density over the picture
    int collapsePanel = -1;   // the script's collapse-panel (1) or expand-panel (0), for the next frame; -1: as the user left it
    ImageTexture densityTexture;
    std::vector<DebugImage> debugImages;
    std::vector<ImageTexture> debugTextures;  // one per debug image, for ImGui::Image
    Scene lastShown;                     // what the last frame drew (its debug images are read from it)
    // The error image against the ray-traced reference: asked for (C, the
    // button or the script), traced on a worker thread, then shown.
    bool referenceAsked = false;
    int referenceAskedAt = 0;            // the frame count when it was asked: traced from a frame drawn after that (a script's set then compare)
    std::unique_ptr<ReferenceRun> tracing;
    std::vector<std::string> referenceLines;
    std::vector<ImageTexture> referenceTextures;
    std::vector<ImageRGBA8> referenceImages;
    std::string compareDirectory;  // the script's pending "compare DIR"
    std::string compareLabel;      // and its line, "s.txt:4: compare DIR"
    // The script's screenshots, under temporary names
    // until the script ends well (run() commits them): a script that fails
    // at a later line leaves none of them, as a failed render leaves no frame.
    tool::PendingFiles scriptOutputs;
    std::chrono::steady_clock::time_point lastFrame;
    // What the last frame's panel showed, for the script's "layout FILE":
    // its windows' screen rectangles (x, y from the top left, w, h, in
    // pixels) and each light's options with the reason one is unused
    // (optionUnused) and whether its value came from a preset.
    struct ShownOption {
        int light = 0;
        std::string key, unused;
        bool preset = false;
    };
    std::vector<std::pair<std::string, glm::vec4>> shownWindows;
    std::vector<ShownOption> shownOptions;
};

} // namespace shadowlab::viewer
