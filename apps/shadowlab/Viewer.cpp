// `shadowlab view`: a window on the renderer with a panel generated from the
// techniques' options tables. Every change the panel (or a script) makes is
// an override line, "key=value", the very path `--set` takes: the scene is
// read again from its file with all of them, so a setting has one name
// everywhere and a new option appears here without viewer code.
#include "Viewer.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include "gl/Object.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace shadowlab {

namespace {

constexpr float kPanelWidth = 340.0f;  ///< the panel's fixed place: x in [0, kPanelWidth)

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

// One action of a --script file, one per line: "set KEY=VALUE", "wait N"
// (frames), "screenshot FILE", "save FILE" (the scene with the settings made,
// as JSON), "show-maps", "show-light", "show-density", "compare [DIR]" (waits
// for the reference; prints the numbers, writes error-<i>.png into DIR),
// "resize W H", "minimize", "restore", "quit"; "#" starts a comment.
struct Action {
    std::string verb, argument;
    int line = 0;
};

std::vector<Action> readScript(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open the script");
    std::vector<Action> out;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
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
        } else if (a.verb == "screenshot" || a.verb == "save") {
            if (a.argument.empty()) throw Error(where + a.verb + ": expected a file name");
        } else if (a.verb == "resize") {
            std::istringstream size(a.argument);
            int w = 0, h = 0;
            std::string rest;
            if (!(size >> w >> h) || (size >> rest) || w < 64 || h < 64 || w > 16384 || h > 16384)
                throw Error(where + "resize: expected a width and a height, 64..16384, got '" + a.argument + "'");
        } else if (a.verb == "compare") {
            // An optional directory for the error images.
        } else if (a.verb != "quit" && a.verb != "minimize" && a.verb != "restore" && a.verb != "show-maps" && a.verb != "show-light" &&
                   a.verb != "show-density") {
            throw Error(where + "unknown action '" + a.verb +
                        "' (expected set, wait, screenshot, save, show-maps, show-light, show-density, compare, resize, minimize, restore or quit)");
        } else if (!a.argument.empty()) {
            throw Error(where + a.verb + ": expected nothing after it, got '" + a.argument + "'");
        }
        out.push_back(a);
    }
    return out;
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

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// An image as a texture for ImGui::Image.
gl::Texture textureOf(const ImageRGBA8& image) {
    gl::Texture texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGBA8, image.width, image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    return texture;
}

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
    int startFrame = 0;     ///< the window's frame when it started
    ReferenceRun() = default;
    ReferenceRun(const ReferenceRun&) = delete;
    ReferenceRun& operator=(const ReferenceRun&) = delete;
    ~ReferenceRun() {
        if (job) job->cancel();
        if (worker.joinable()) worker.join();
    }
};

// A segment in world space onto the window, clipped at the camera's near
// side (w > 0) so that a frustum reaching behind the viewer stays drawn.
void drawSegment(ImDrawList* draw, const glm::mat4& clipFromWorld, glm::vec2 size, glm::vec3 a, glm::vec3 b, ImU32 colour) {
    glm::vec4 ca = clipFromWorld * glm::vec4(a, 1.0f), cb = clipFromWorld * glm::vec4(b, 1.0f);
    constexpr float kNear = 1e-3f;
    if (ca.w < kNear && cb.w < kNear) return;
    if (ca.w < kNear) ca = glm::mix(ca, cb, (kNear - ca.w) / (cb.w - ca.w));
    if (cb.w < kNear) cb = glm::mix(cb, ca, (kNear - cb.w) / (ca.w - cb.w));
    auto screen = [&](const glm::vec4& c) { return ImVec2((c.x / c.w * 0.5f + 0.5f) * size.x, (0.5f - c.y / c.w * 0.5f) * size.y); };
    draw->AddLine(screen(ca), screen(cb), colour, 1.5f);
}

// The twelve edges of the volume that is [-1, 1]^3 in `lightClip`'s clip space.
void drawFrustum(ImDrawList* draw, const glm::mat4& clipFromWorld, glm::vec2 size, const glm::mat4& lightClip, ImU32 colour) {
    const glm::mat4 worldFromLight = glm::inverse(lightClip);
    std::array<glm::vec3, 8> corner{};
    for (int k = 0; k < 8; ++k) {
        const glm::vec4 p = worldFromLight * glm::vec4(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f, 1.0f);
        corner[static_cast<std::size_t>(k)] = glm::vec3(p) / p.w;
    }
    for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(k & bit)) drawSegment(draw, clipFromWorld, size, corner[static_cast<std::size_t>(k)], corner[static_cast<std::size_t>(k | bit)], colour);
}

} // namespace

int runView(const ViewArgs& args) {
    const bool fromFile = !args.scene.empty();
    std::vector<Action> script = args.script.empty() ? std::vector<Action>{} : readScript(args.script);
    Overrides overrides;
    overrides.fromCommandLine = args.overrides;
    auto load = [&] { return fromFile ? loadSceneFile(args.scene, overrides.all()) : defaultScene(overrides.all()); };
    Scene scene = load();  // a bad scene or --set is the command's error, before any window

    Context context = Context::createWindow(args.width, args.height, "shadowlab view: " + scene.name);
    GLFWwindow* window = context.window();
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450");

    Renderer renderer(context);
    renderer.upload(scene);
    Orbit orbit;
    orbit.from(scene.camera);
    bool cameraMoved = false;
    std::string error;  // the last failed reload or setting, shown in the panel
    fs::file_time_type fileTime = fromFile ? fs::last_write_time(args.scene) : fs::file_time_type{};
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
    bool showDebug = false;   // the techniques' debug images (maps, cube crosses) in the panel
    bool showDensity = false; // the selected light's texel density over the picture
    gl::Texture densityTexture{gl::NoCreate};
    std::vector<DebugImage> debugImages;
    std::vector<gl::Texture> debugTextures;  // one per debug image, for ImGui::Image
    Scene lastShown;                     // what the last frame drew (its debug images are read from it)
    // The error image against the ray-traced reference: asked for (C, the
    // button or the script), traced on a worker thread, then shown.
    bool referenceAsked = false;
    std::unique_ptr<ReferenceRun> tracing;
    std::vector<std::string> referenceLines;
    std::vector<gl::Texture> referenceTextures;
    std::vector<ImageRGBA8> referenceImages;
    auto freeReferenceTextures = [&] { referenceTextures.clear(); };
    auto freeDebugTextures = [&] { debugTextures.clear(); };
    std::string compareDirectory;  // the script's pending "compare DIR"
    auto lastFrame = std::chrono::steady_clock::now();

    // Reads the scene again with every override; on failure keeps the last good one.
    auto reload = [&] {
        tracing.reset();  // a comparison in flight would describe a frame no longer shown
        try {
            Scene next = load();
            renderer.upload(next);
            scene = std::move(next);
            if (!cameraMoved) orbit.from(scene.camera);
            error.clear();
        } catch (const Error& e) {
            error = e.what();
        }
    };
    // The scene with every setting made, as JSON that loads again (written
    // whole to a temporary file, then renamed: never half a file).
    auto save = [&](const fs::path& path) {
        std::string text;
        if (fromFile) {
            std::ifstream in(args.scene, std::ios::binary);
            std::stringstream s;
            s << in.rdbuf();
            text = s.str();
        } else {
            text = defaultSceneJson();
        }
        const std::string saved = sceneJsonWithOverrides(text, fromFile ? args.scene : std::string("<default scene>"), overrides.all());
        const fs::path partial = path.string() + ".partial";
        {
            std::ofstream out(partial, std::ios::binary);
            if (!(out << saved)) throw Error(path.string() + ": cannot write");
        }
        fs::rename(partial, path);
    };
    auto apply = [&](const std::string& key, const std::string& value) {
        overrides.set(key, value);
        reload();
    };

    while (!glfwWindowShouldClose(window) && !quit) {
        glfwPollEvents();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        if (width <= 0 || height <= 0) {  // minimised: nothing to draw
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        // The scene file changed on disk: read it again (a broken edit is shown, the last good scene kept).
        if (fromFile && frame % 15 == 0) {
            std::error_code ec;
            const auto t = fs::last_write_time(args.scene, ec);
            if (!ec && t != fileTime) {
                fileTime = t;
                reload();
            }
        }
        // The script: one action per frame, "wait N" holds it N frames, a
        // comparison holds it until the reference is traced.
        while (waitFrames == 0 && nextAction < script.size() && !referenceAsked && !tracing) {
            const Action& a = script[nextAction++];
            if (a.verb == "set") {
                const auto eq = a.argument.find('=');
                apply(a.argument.substr(0, eq), a.argument.substr(eq + 1));
                if (!error.empty()) throw Error(args.script + ":" + std::to_string(a.line) + ": " + error);
            } else if (a.verb == "wait") {
                waitFrames = std::stoi(a.argument);
            } else if (a.verb == "screenshot") {
                --nextAction;  // taken after this frame is drawn
                break;
            } else if (a.verb == "save") {
                save(a.argument);
                std::cout << a.argument << "\n";
            } else if (a.verb == "resize") {
                std::istringstream size(a.argument);
                int w = 0, h = 0;
                size >> w >> h;
                glfwSetWindowSize(window, w, h);
            } else if (a.verb == "show-maps") {
                showDebug = true;
            } else if (a.verb == "show-light") {
                showLight = true;
            } else if (a.verb == "show-density") {
                showDensity = true;
            } else if (a.verb == "compare") {
                referenceAsked = true;
                compareDirectory = a.argument;
                break;
            } else if (a.verb == "minimize") {
                glfwIconifyWindow(window);
            } else if (a.verb == "restore") {
                glfwRestoreWindow(window);
            } else if (a.verb == "quit") {
                quit = true;
            }
        }

        // The comparison: started from the last frame drawn, finished here
        // when the worker is done (per light the misclassified shares and the
        // error image, docs/metrics.md).
        if (referenceAsked && frame > 0 && !tracing) {
            referenceAsked = false;
            try {
                CompareOptions options;
                options.width = width;
                options.height = height;
                options.timeSeconds = seconds;
                auto run = std::make_unique<ReferenceRun>();
                run->directory = compareDirectory;
                run->startFrame = frame;
                run->job = std::make_unique<ComparisonJob>(renderer, lastShown, options);
                ReferenceRun* r = run.get();
                r->worker = std::thread([r] {
                    try {
                        r->job->trace();
                    } catch (const Error& e) {
                        r->error = e.what();
                    }
                    r->done = true;
                });
                tracing = std::move(run);
            } catch (const Error& e) {
                error = e.what();
                if (!script.empty()) throw;
            }
            compareDirectory.clear();
        }
        if (tracing && tracing->done) {
            tracing->worker.join();
            const std::unique_ptr<ReferenceRun> run = std::move(tracing);
            if (!run->error.empty()) {
                error = run->error;
                if (!script.empty()) throw Error(args.script + ": compare: " + run->error);
            } else {
                const Comparison c = run->job->finish(renderer);
                if (!script.empty())
                    std::cout << "compare: traced in " << std::lround(c.referenceMs) << " ms while the window drew " << frame - run->startFrame << " frames\n";
                freeReferenceTextures();
                referenceLines.clear();
                referenceImages.clear();
                for (std::size_t l = 0; l < c.lights.size(); ++l) {
                    const LightComparison& lc = c.lights[l];
                    char line[240];
                    std::snprintf(line, sizeof line, "%s: %.3f %% wrong away from edges, %.3f %% in all (%zu receiver pixels)", lc.name.c_str(),
                                  100.0 * (lc.falseLitAwayFromEdges + lc.falseShadowAwayFromEdges), 100.0 * (lc.falseLit + lc.falseShadow),
                                  lc.receiverPixels);
                    referenceLines.push_back(line);
                    referenceImages.push_back(lc.errorImage);
                    referenceTextures.push_back(textureOf(lc.errorImage));
                    if (!script.empty()) std::cout << "compare: light " << l << " " << line << "\n";
                    if (!run->directory.empty()) {
                        const std::string file = (fs::path(run->directory) / ("error-" + std::to_string(l) + ".png")).string();
                        writePng(file, lc.errorImage);
                        std::cout << file << "\n";
                    }
                }
            }
        }

        // The techniques' debug images of the last frame drawn, before this
        // frame's panel names their textures.
        // Read back every tenth frame for the panel, every fourth for the
        // texel-density tint (it follows the camera).
        if (frame > 0 && ((showDebug && frame % 10 == 1) || (showDensity && frame % 4 == 1))) {
            debugImages = renderer.debugImages(lastShown);
            freeDebugTextures();
            if (showDebug)
                for (const DebugImage& d : debugImages) debugTextures.push_back(textureOf(d.image));
            densityTexture = gl::Texture(gl::NoCreate);
            for (const DebugImage& d : debugImages)
                if (showDensity && d.name == "light" + std::to_string(selectedLight) + "-texel-density") densityTexture = textureOf(d.image);
        }
        if (!showDebug && !debugTextures.empty()) freeDebugTextures();
        if (!showDensity) densityTexture = gl::Texture(gl::NoCreate);
        if (!showDebug && !showDensity) debugImages.clear();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        ImGuiIO& io = ImGui::GetIO();
        // Camera: left drag orbits, right drag pans, the wheel zooms, R resets.
        // Shift + left drag moves the selected point or spot light across the view.
        const bool dragLight = io.KeyShift && selectedLight >= 0 && static_cast<std::size_t>(selectedLight) < scene.lights.size() &&
                               scene.lights[static_cast<std::size_t>(selectedLight)].type != LightType::Directional;
        if (!io.WantCaptureMouse && dragLight && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
            const Light& light = scene.lights[static_cast<std::size_t>(selectedLight)];
            const glm::vec3 eye = cameraMoved ? orbit.position() : scene.camera.position;
            const glm::vec3 at = cameraMoved ? orbit.target : scene.camera.target;
            const glm::vec3 forward = glm::normalize(at - eye);
            const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
            const glm::vec3 up = glm::cross(right, forward);
            // A pixel moves the light by one pixel's width at its distance.
            const float perPixel = 2.0f * glm::length(light.position - eye) * std::tan(glm::radians(scene.camera.fovYDeg) * 0.5f) / static_cast<float>(height);
            const glm::vec3 p = light.position + (io.MouseDelta.x * right - io.MouseDelta.y * up) * perPixel;
            std::ostringstream s;
            s << "[" << p.x << ", " << p.y << ", " << p.z << "]";
            apply("lights[" + std::to_string(selectedLight) + "].position", s.str());
        } else if (!io.WantCaptureMouse) {
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
                orbit.yaw -= io.MouseDelta.x * 0.008f;
                orbit.pitch = std::clamp(orbit.pitch + io.MouseDelta.y * 0.008f, -1.5f, 1.5f);
                cameraMoved = true;
            }
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
                const glm::vec3 forward = glm::normalize(orbit.target - orbit.position());
                const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
                const glm::vec3 up = glm::cross(right, forward);
                orbit.target += (-io.MouseDelta.x * right + io.MouseDelta.y * up) * orbit.distance * 0.002f;
                cameraMoved = true;
            }
            if (io.MouseWheel != 0.0f) {
                orbit.distance *= std::pow(0.9f, io.MouseWheel);
                cameraMoved = true;
            }
        }
        // Keys (ImGui 1.86 names only a few): pressed on this frame, not held.
        auto pressed = [&](int key) {
            const bool down = glfwGetKey(window, key) == GLFW_PRESS;
            const bool was = keysDown[key];
            keysDown[key] = down;
            return down && !was && !io.WantCaptureKeyboard;
        };
        if (pressed(GLFW_KEY_R)) {
            orbit.from(scene.camera);
            cameraMoved = false;
        }
        if (pressed(GLFW_KEY_SPACE)) playing = !playing;
        // WASD (and Q/E down/up) fly: the orbit's centre moves with the camera.
        if (!io.WantCaptureKeyboard) {
            const glm::vec3 forward = glm::normalize(orbit.target - orbit.position());
            const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
            glm::vec3 move(0.0f);
            if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) move += forward;
            if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) move -= forward;
            if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) move += right;
            if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) move -= right;
            if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) move.y += 1.0f;
            if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) move.y -= 1.0f;
            if (glm::length(move) > 0.0f) {
                orbit.target += glm::normalize(move) * orbit.distance * 0.6f * std::max(io.DeltaTime, 1.0f / 240.0f);
                cameraMoved = true;
            }
        }
        bool screenshotKey = pressed(GLFW_KEY_F12);
        if (pressed(GLFW_KEY_C) && !tracing) referenceAsked = true;

        // The panel, at a fixed place on the left.
        ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
        ImGui::SetNextWindowSize(ImVec2(kPanelWidth, static_cast<float>(height)));
        ImGui::Begin("shadowlab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
        ImGui::TextUnformatted(scene.name.c_str());
        if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", error.c_str());
        ImGui::Text("%.1f ms a frame, t = %.2f s %s", frameTimes.empty() ? 0.0 : static_cast<double>(frameTimes.back()), seconds, playing ? "(playing)" : "");
        if (!frameTimes.empty()) {
            std::vector<float> values(frameTimes.begin(), frameTimes.end());
            ImGui::PlotLines("##frames", values.data(), static_cast<int>(values.size()), 0, "frame ms", 0.0f, 60.0f, ImVec2(kPanelWidth - 20.0f, 50.0f));
        }
        for (const PassTiming& p : stats.passes) ImGui::Text("  %-22s %6.2f ms", p.name.c_str(), p.ms);
        if (ImGui::Button("reset camera (R)")) {
            orbit.from(scene.camera);
            cameraMoved = false;
        }
        ImGui::SameLine();
        if (ImGui::Button(playing ? "pause (space)" : "play (space)")) playing = !playing;
        if (ImGui::Button("screenshot (F12)")) screenshotKey = true;
        ImGui::Checkbox("show shadow maps", &showDebug);
        ImGui::SameLine();
        ImGui::Checkbox("show light", &showLight);
        ImGui::Checkbox("texel density", &showDensity);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The selected light's shadow-map texels per screen pixel over the picture: green about one, red blocky (a texel over many pixels), blue wasted; grey outside the map");
        ImGui::SameLine();
        if (ImGui::Button("compare (C)") && !tracing) referenceAsked = true;
        if (tracing) {
            ImGui::ProgressBar(static_cast<float>(tracing->job->progress()), ImVec2(kPanelWidth - 100.0f, 0.0f), "tracing the reference");
            ImGui::SameLine();
            if (ImGui::Button("cancel")) tracing.reset();
        } else if (referenceAsked) {
            ImGui::TextUnformatted("tracing the reference ...");
        }
        if (!referenceLines.empty()) {
            for (const std::string& line : referenceLines) ImGui::TextWrapped("%s", line.c_str());
            for (std::size_t r = 0; r < referenceTextures.size(); ++r) {
                const float w = kPanelWidth - 30.0f;
                const float h = w * static_cast<float>(referenceImages[r].height) / static_cast<float>(std::max(referenceImages[r].width, 1));
                ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(referenceTextures[r].id())), ImVec2(w, h));
            }
            if (ImGui::Button("hide comparison")) {
                referenceLines.clear();
                referenceImages.clear();
                freeReferenceTextures();
            }
        }
        ImGui::Text("GL objects: %ld", liveGlObjects());
        if (fromFile) {
            ImGui::SameLine();
            if (ImGui::Button("save scene")) {
                // Into the scene file itself: it is read again, now with the settings in it.
                try {
                    save(args.scene);
                    overrides.made.clear();
                } catch (const Error& e) {
                    error = e.what();
                }
            }
        }
        const std::vector<TechniqueInfo> all = techniques();
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            const Light& light = scene.lights[l];
            const std::string at = "lights[" + std::to_string(l) + "]";
            ImGui::PushID(static_cast<int>(l));
            if (ImGui::CollapsingHeader((at + " " + light.name).c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
                // Its technique, then every option of it from its table.
                if (ImGui::BeginCombo("technique", light.shadow.technique.c_str())) {
                    for (const TechniqueInfo& t : all)
                        if (ImGui::Selectable(t.name.c_str(), t.name == light.shadow.technique)) apply(at + ".shadow.technique", jsonString(t.name));
                    ImGui::EndCombo();
                }
                const TechniqueInfo* technique = findTechnique(light.shadow.technique);
                const OptionTable* table = technique ? technique->options : nullptr;
                if (table) {
                    const auto stored = light.shadow.options.find(table->block);
                    const std::any current = stored != light.shadow.options.end() ? stored->second : table->makeDefault();
                    for (const OptionField& f : table->fields) {
                        const std::string key = at + ".shadow." + table->block + "." + f.key;
                        switch (f.kind) {
                        case OptionKind::Number: {
                            float v = static_cast<float>(f.get(current));
                            if (ImGui::SliderFloat(f.key.c_str(), &v, static_cast<float>(f.minimum), static_cast<float>(f.maximum), "%.4g")) {
                                std::ostringstream s;
                                s << v;
                                apply(key, s.str());
                            }
                            break;
                        }
                        case OptionKind::Integer: {
                            int v = static_cast<int>(f.get(current));
                            if (ImGui::InputInt(f.key.c_str(), &v, 1, 100, ImGuiInputTextFlags_EnterReturnsTrue))
                                apply(key, std::to_string(std::clamp(v, static_cast<int>(f.minimum), static_cast<int>(f.maximum))));
                            break;
                        }
                        case OptionKind::Boolean: {
                            bool v = f.get(current) != 0.0;
                            if (ImGui::Checkbox(f.key.c_str(), &v)) apply(key, v ? "true" : "false");
                            break;
                        }
                        case OptionKind::Choice: {
                            const auto index = static_cast<std::size_t>(f.get(current));
                            if (ImGui::BeginCombo(f.key.c_str(), index < f.choices.size() ? f.choices[index].c_str() : "?")) {
                                for (std::size_t c = 0; c < f.choices.size(); ++c)
                                    if (ImGui::Selectable(f.choices[c].c_str(), c == index)) apply(key, jsonString(f.choices[c]));
                                ImGui::EndCombo();
                            }
                            break;
                        }
                        case OptionKind::Text: {
                            char buffer[256] = {};
                            const std::string v = f.getText(current);
                            v.copy(buffer, sizeof buffer - 1);
                            if (ImGui::InputText(f.key.c_str(), buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue)) apply(key, jsonString(buffer));
                            break;
                        }
                        }
                        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s%s%s", f.doc.c_str(), f.unit.empty() ? "" : "; ", f.unit.c_str());
                    }
                }
                ImGui::RadioButton("selected (shift + drag moves it)", &selectedLight, static_cast<int>(l));
                bool fromThis = viewFromLight == static_cast<int>(l);
                if (ImGui::Checkbox("view from this light", &fromThis)) viewFromLight = fromThis ? static_cast<int>(l) : -1;
                // Its debug images (a map, a cube's cross), refreshed every few frames.
                if (showDebug)
                    for (std::size_t d = 0; d < debugImages.size() && d < debugTextures.size(); ++d)
                        if (debugImages[d].name.rfind("light" + std::to_string(l) + "-", 0) == 0) {
                            const float w = kPanelWidth - 30.0f;
                            const float h = w * static_cast<float>(debugImages[d].image.height) / static_cast<float>(std::max(debugImages[d].image.width, 1));
                            ImGui::TextUnformatted(debugImages[d].name.c_str());
                            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(debugTextures[d].id())), ImVec2(w, h));
                        }
                // Where the light is: point and spot lights move with the sliders.
                if (light.type != LightType::Directional) {
                    glm::vec3 p = light.position;
                    if (ImGui::DragFloat3("position", &p.x, 0.05f)) {
                        std::ostringstream s;
                        s << "[" << p.x << ", " << p.y << ", " << p.z << "]";
                        apply(at + ".position", s.str());
                    }
                }
            }
            ImGui::PopID();
        }
        ImGui::End();

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
        options.width = width;
        options.height = height;
        options.timeSeconds = seconds;
        options.clock = TimingClock::Auto;
        stats = renderer.render(shown, options);
        lastShown = std::move(shown);
        renderer.blitToDefaultFramebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        const glm::vec2 windowSize(static_cast<float>(width), static_cast<float>(height));
        ImDrawList* background = ImGui::GetBackgroundDrawList();
        // The selected light's texel density over the picture, half opaque.
        if (showDensity && densityTexture.id() != 0)
            background->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(densityTexture.id())), ImVec2(0.0f, 0.0f),
                                 ImVec2(windowSize.x, windowSize.y), ImVec2(0.0f, 0.0f), ImVec2(1.0f, 1.0f), IM_COL32(255, 255, 255, 150));
        // The selected light in wireframe over the picture: a spot's cone out
        // to its reach, a point light's position, a directional light's
        // direction from the target; and in blue the frustums its technique
        // rendered from last frame, fitted (a 2D map's one, a cube's six).
        if (showLight && selectedLight >= 0 && static_cast<std::size_t>(selectedLight) < lastShown.lights.size()) {
            const Light& light = lastShown.lights[static_cast<std::size_t>(selectedLight)];
            const glm::mat4 clip = lastShown.camera.clipFromView(windowSize.x / windowSize.y) * lastShown.camera.viewFromWorld();
            const ImU32 colour = IM_COL32(255, 220, 90, 220), frustumColour = IM_COL32(90, 170, 255, 200);
            auto line = [&](const glm::vec3& a, const glm::vec3& b) { drawSegment(background, clip, windowSize, a, b, colour); };
            if (light.type == LightType::Spot) {
                const glm::vec3 axis = glm::normalize(light.direction);
                const glm::vec3 side = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
                const glm::vec3 other = glm::cross(axis, side);
                const float reach = light.range > 0.0f ? light.range : 1.1f * glm::length(lastShown.camera.target - light.position);
                const float radius = reach * std::tan(glm::radians(light.outerConeDeg));
                glm::vec3 previous{};
                for (int k = 0; k <= 24; ++k) {
                    const float a = 6.2831853f * static_cast<float>(k) / 24.0f;
                    const glm::vec3 rim = light.position + axis * reach + radius * (std::cos(a) * side + std::sin(a) * other);
                    if (k % 6 == 0) line(light.position, rim);
                    if (k > 0) line(previous, rim);
                    previous = rim;
                }
            } else if (light.type == LightType::Point) {
                for (const glm::vec3 d : {glm::vec3(0.3f, 0, 0), glm::vec3(0, 0.3f, 0), glm::vec3(0, 0, 0.3f)}) line(light.position - d, light.position + d);
            } else {
                const glm::vec3 target = lastShown.camera.target;
                line(target - glm::normalize(light.direction) * 3.0f, target);
            }
            for (const LightFrustum& f : renderer.lightFrustums(lastShown))
                if (f.light == selectedLight) drawFrustum(background, clip, windowSize, f.clipFromWorld, frustumColour);
        }
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        if (screenshotKey) {
            const std::string name = "shadowlab-view-" + std::to_string(frame) + ".png";
            writePng(name, readWindow(width, height));
            std::cout << name << "\n";
        }
        if (waitFrames == 0 && nextAction < script.size() && script[nextAction].verb == "screenshot") {
            writePng(script[nextAction].argument, readWindow(width, height));
            std::cout << script[nextAction].argument << "\n";
            ++nextAction;
        }
        ++frame;
        if (waitFrames > 0) --waitFrames;
        if (args.frames > 0 && frame >= args.frames) {
            if (!args.screenshot.empty()) {
                writePng(args.screenshot, readWindow(width, height));
                std::cout << args.screenshot << "\n";
            }
            quit = true;
        }
        if (!args.script.empty() && nextAction >= script.size() && waitFrames == 0) quit = true;
        glfwSwapBuffers(window);

        const auto now = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(now - lastFrame).count();
        lastFrame = now;
        frameTimes.push_back(static_cast<float>(dt * 1000.0));
        if (frameTimes.size() > 120) frameTimes.pop_front();
        if (playing) seconds += dt;
    }

    tracing.reset();
    freeDebugTextures();
    freeReferenceTextures();
    densityTexture = gl::Texture(gl::NoCreate);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

} // namespace shadowlab
