// `shadowlab view`: a window on the renderer with a panel generated from the
// techniques' options tables. Every change the panel (or a script) makes is
// an override line, "key=value", the very path `--set` takes: the scene is
// read again from its file with all of them, so a setting has one name
// everywhere and a new option appears here without viewer code. A setting
// of a light (a technique's option, a position) reads the lights alone and
// keeps the meshes and textures on the GPU: it shows on the next frame.
// Here: the window and the loop that draws it, one step of ViewerSession
// (ViewerSession.h) after another, and the scene read again or saved with
// the settings made.
#include "Interrupt.h"
#include "ViewerSession.h"

#include <shadowlab/Limits.h>
#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/SceneFile.h>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string_view>

namespace fs = std::filesystem;

namespace shadowlab {

namespace viewer {

namespace {

// A window of the size asked for, with Dear ImGui on it, ready for the renderer.
Context openWindow(const ViewArgs& args, const std::string& title) {
    Context context = Context::createWindow(args.width, args.height, title);
    checkSize(args.width, args.height, context.info());  // GL's limits and the device's memory, as render's
    GLFWwindow* window = context.window();
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450");
    return context;
}

// The window's back buffer (panel included), rows top to bottom.
ImageRGBA8 readWindow(int width, int height) {
    ImageRGBA8 image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(image.pixels.begin() + static_cast<long>(y * row), image.pixels.begin() + static_cast<long>((y + 1) * row),
                         image.pixels.begin() + static_cast<long>((height - 1 - y) * row));
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
    return image;
}

} // namespace

ViewerSession::ViewerSession(const ViewArgs& viewArgs)
    : args(viewArgs),
      fromFile(!args.scene.empty()),
      script(args.script.empty() ? std::vector<Action>{} : readScript(args.script)),
      overrides{args.overrides, {}},
      scene(load()),  // a bad scene or --set is the command's error, before any window
      context(openWindow(args, "shadowlab view: " + scene.name)),
      window(context.window()),
      renderer(context) {
    renderer.upload(scene);
    ++uploads;
    orbit.from(scene.camera);
    fileTime = fromFile ? fs::last_write_time(args.scene) : fs::file_time_type{};
}

Scene ViewerSession::load() const {
    if (!fromFile && args.camera >= 0) throw Error("--camera " + std::to_string(args.camera) + ": needs a glTF file (the default scene has one camera)");
    return fromFile ? loadSceneFile(args.scene, overrides.all(), SceneFileOptions{args.camera}) : defaultScene(overrides.all());
}

// Reads the scene again with every override; on failure keeps the last good one.
void ViewerSession::reload() {
    tracing.reset();  // a comparison in flight would describe a frame no longer shown
    try {
        Scene next = load();
        renderer.upload(next);
        ++uploads;
        scene = std::move(next);
        if (!cameraMoved) orbit.from(scene.camera);
        error.clear();
    } catch (const Error& e) {
        error = e.what();
    }
}

// The scene with every setting made, as JSON that loads again (written
// whole to a temporary file, then renamed: never half a file).
void ViewerSession::save(const fs::path& path) {
    const std::string text = sceneText();
    const std::string saved = sceneJsonWithOverrides(text, fromFile ? args.scene : std::string("<default scene>"), overrides.all());
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw Error(path.string() + ": cannot save the scene (a directory of that name is in the way)");
    writeFileAtomically(path, saved);
}

// The scene's JSON text as read now: the file's, or the default scene's.
std::string ViewerSession::sceneText() const {
    if (!fromFile) return defaultSceneJson();
    std::ifstream in(args.scene, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A setting inside one light (`lights[N].<key>`, not its projector's
// image): the lights read again from the scene's text with every override,
// the meshes and textures kept. False when the scene must be read whole:
// another key, a projector, a light added or taken away, or the file
// changed on disk since it was read (then its nodes may have changed too).
bool ViewerSession::applyToLights(const std::string& key) {
    const std::size_t close = key.find("].");
    if (key.rfind("lights[", 0) != 0 || close == std::string::npos || key.compare(close + 2, 9, "projector") == 0) return false;
    if (fromFile) {
        std::error_code ec;
        if (fs::last_write_time(args.scene, ec) != fileTime || ec) return false;
    }
    const std::string text = sceneText();
    const fs::path base = fromFile ? fs::path(args.scene).parent_path() : fs::current_path();
    std::vector<Light> lights = parseSceneLights(text, fromFile ? args.scene : std::string("<default scene>"), base, overrides.all());
    if (lights.size() != scene.lights.size()) return false;
    for (std::size_t i = 0; i < lights.size(); ++i) lights[i].projectorTexture = scene.lights[i].projectorTexture;
    scene.lights = std::move(lights);
    return true;
}

void ViewerSession::apply(const std::string& key, const std::string& value) {
    overrides.set(key, value);
    try {
        if (applyToLights(key)) {
            tracing.reset();  // a comparison in flight would describe a frame no longer shown
            error.clear();
            return;
        }
    } catch (const Error& e) {
        error = e.what();  // as a failed reload: the last good scene stays
        return;
    }
    reload();
}

int ViewerSession::run() {
    lastFrame = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(window) && !quit) {
        tool::throwIfInterrupted();  // SIGINT, SIGTERM ...: one line and a non-zero exit, the script's images not kept
        glfwPollEvents();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        if (width <= 0 || height <= 0) {  // minimised: nothing to draw
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        // The scene file changed on disk: read it again (a broken edit is shown, the last good scene kept).
        if (fromFile && frame % 15 == 0) reloadIfChanged();
        runScript();
        // The comparison: started from the last frame drawn, finished here
        // when the worker is done (per light the misclassified shares and the
        // error image, docs/metrics.md).
        // From a frame drawn after it was asked: a script's `set` then
        // `compare` in one turn measured the frame before the change.
        if (referenceAsked && frame > referenceAskedAt && !tracing) startComparison(width, height);
        if (tracing && tracing->done) finishComparison();
        // The techniques' debug images of the last frame drawn, before this
        // frame's panel names their textures.
        refreshDebugImages();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        handleMouse(height);
        bool screenshotKey = handleKeys();
        shownWindows.clear();
        shownOptions.clear();
        drawPanel(height, screenshotKey);
        drawMapsWindow(width, height);
        renderFrame(width, height);
        drawOverlay(width, height);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        endFrame(width, height, screenshotKey);
        glfwSwapBuffers(window);

        timeFrame();
    }

    // The loop ended without an error (errors throw out of run()): the
    // script's images are put in place together.
    for (const std::filesystem::path& file : scriptOutputs.commit()) std::cout << file.string() << "\n";
    tracing.reset();
    freeDebugTextures();
    freeReferenceTextures();
    densityTexture = ImageTexture();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

void ViewerSession::reloadIfChanged() {
    std::error_code ec;
    const auto t = fs::last_write_time(args.scene, ec);
    if (!ec && t != fileTime) {
        fileTime = t;
        reload();
    }
}

void ViewerSession::renderFrame(int width, int height) {
    // The frame: the scene where its light paths are at `seconds`, from the orbiting camera.
    Scene shown = sceneAtTime(scene, seconds);
    if (cameraMoved) {
        shown.camera.position = orbit.position();
        shown.camera.target = orbit.target;
    }
    if (viewFromLight >= 0 && static_cast<std::size_t>(viewFromLight) < shown.lights.size()) {
        try {
            shown.camera = cameraFromLight(shown, shown.lights[static_cast<std::size_t>(viewFromLight)]);
        } catch (const Error& e) {
            error = e.what();
            viewFromLight = -1;
        }
    }
    RenderOptions options;
    options.cacheShadowMaps = true;  // a still view over a still scene keeps its maps
    options.width = width;
    options.height = height;
    options.timeSeconds = seconds;
    options.clock = TimingClock::Auto;
    try {
        stats = renderer.render(shown, options);
    } catch (const Error& e) {
        // A value the script set (the maps past their budget, say): named by its line.
        std::vector<std::string> sets, lines;
        for (const auto& [keyValue, line] : scriptSets) {
            sets.push_back(keyValue);
            lines.push_back(line);
        }
        // A window the script made too large for the GPU's memory: named by its resize line.
        if (!scriptResize.empty() && std::string_view(e.what()).find("GL_OUT_OF_MEMORY") != std::string_view::npos)
            throw Error(scriptResize + ": " + e.what());
        throw Error(withValueSource(e.what(), "", sets, lines));
    }
    lastShown = std::move(shown);
    renderer.blitToDefaultFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
}

// Screenshots (F12, the script's, --screenshot with --frames), then the
// frame is counted: --frames and the script's end quit.
void ViewerSession::endFrame(int width, int height, bool screenshotKey) {
    if (screenshotKey) {
        const std::string name = "shadowlab-view-" + std::to_string(frame) + ".png";
        writePng(name, readWindow(width, height));
        std::cout << name << "\n";
    }
    if (waitFrames == 0 && !resizing() && nextAction < script.size() && script[nextAction].verb == "screenshot") {
        try {
            scriptOutputs.write(script[nextAction].argument, readWindow(width, height));
        } catch (const Error& e) {
            throw Error(args.script + ":" + std::to_string(script[nextAction].line) + ": screenshot: " + e.what());
        }
        ++nextAction;  // named on stdout once it is in place (commit), not before: a failing later line keeps none
    }
    if (waitFrames == 0 && !resizing() && nextAction < script.size() && script[nextAction].verb == "layout") {
        const std::string json = layoutJson();
        try {
            scriptOutputs.write(script[nextAction].argument, [&](const std::filesystem::path& to) { writeFileAtomically(to, json); });
        } catch (const Error& e) {
            throw Error(args.script + ":" + std::to_string(script[nextAction].line) + ": layout: " + e.what());
        }
        ++nextAction;
    }
    ++frame;
    if (waitFrames > 0) --waitFrames;
    if (resizing()) {
        // The script's resize is done once a frame was drawn at that size.
        int windowWidth = 0, windowHeight = 0;
        glfwGetWindowSize(window, &windowWidth, &windowHeight);
        if ((windowWidth == resizeWidth && windowHeight == resizeHeight) || ++resizeFrames >= kResizeFrames) resizeWidth = resizeHeight = 0;
    }
    if (args.frames > 0 && frame == args.frames && !args.screenshot.empty()) {
        writePng(args.screenshot, readWindow(width, height));
        std::cout << args.screenshot << "\n";
    }
    // --frames ends the run, but not before a comparison the script asked for is traced and written.
    if (args.frames > 0 && frame >= args.frames && !referenceAsked && !tracing) quit = true;
    // The script ends once what it started is done: a comparison it asked for is traced and written first.
    if (!args.script.empty() && nextAction >= script.size() && waitFrames == 0 && !referenceAsked && !tracing && !resizing()) quit = true;
}

void ViewerSession::timeFrame() {
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(now - lastFrame).count();
    lastFrame = now;
    frameTimes.push_back(static_cast<float>(dt * 1000.0));
    if (frameTimes.size() > 120) frameTimes.pop_front();
    if (playing) seconds += dt;
}

} // namespace viewer

int runView(const ViewArgs& args) {
    viewer::ViewerSession session(args);
    return session.run();
}

} // namespace shadowlab
