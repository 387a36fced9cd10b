// The Python module's shared parts (Module.h): the context, errors named
// as Python names things, images as arrays.
#include "Module.h"

#include <cctype>
#include <cstring>
#include <string_view>

namespace shadowlab::python {

namespace {

struct Gl {
    std::mutex lock;
    std::optional<Context> context;
    // Declared after the context: destroyed before it.
    std::shared_ptr<const Scene> keptScene;
    std::unique_ptr<Renderer> kept;
};
Gl& gl() {
    static Gl g;
    return g;
}

} // namespace

std::mutex& glLock() { return gl().lock; }

Context& contextLocked() {
    Gl& g = gl();
    if (!g.context) {
        try {
            g.context.emplace(Context::createHeadless());
        } catch (const Error& e) {
            throw std::runtime_error(e.what());
        }
    }
    g.context->makeCurrent();
    return *g.context;
}

Renderer& rendererFor(Context& context, const std::shared_ptr<const Scene>& scene) {
    Gl& g = gl();
    if (g.kept && g.keptScene == scene) return *g.kept;
    g.kept.reset();  // the old one's GL objects gone before the new one's are made
    g.keptScene.reset();
    auto renderer = std::make_unique<Renderer>(context);
    renderer->upload(*scene);
    g.kept = std::move(renderer);
    g.keptScene = scene;
    return *g.kept;
}

void forgetRenderer() {
    gl().kept.reset();
    gl().keptScene.reset();
}

void forgetRendererAtExit() {
    Gl& g = gl();
    std::lock_guard hold(g.lock);
    if (!g.kept || !g.context) return;
    g.context->makeCurrent();  // its GL objects are deleted in the context they belong to
    forgetRenderer();
    g.context->releaseCurrent();
}

Released::~Released() {
    if (gl().context) gl().context->releaseCurrent();
}

namespace {

// Every `FLAG KEY=` in `message` as `NAME[KEY]=`.
std::string keyed(std::string message, const std::string& flag, const std::string& name) {
    for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at)) {
        const std::size_t key = at + flag.size(), eq = message.find('=', key);
        if (eq == std::string::npos) break;
        const std::string replacement = name + "[" + message.substr(key, eq - key) + "]";
        message.replace(at, eq - at, replacement);
        at += replacement.size();
    }
    return message;
}

} // namespace

std::string pythonNames(std::string message) {
    message = keyed(keyed(std::move(message), "--set ", "overrides"), "--vary ", "vary");
    // `overrides[K]=V: ...` said first: the key alone, as load_scene names it.
    if (message.rfind("overrides[", 0) == 0) {
        const std::size_t close = message.find("]=");
        const std::size_t colon = close == std::string::npos ? close : message.find(": ", close);
        if (colon != std::string::npos) message = message.substr(0, close + 1) + message.substr(colon);
    }
    // bench's flags as the keyword arguments.
    static const std::pair<std::string_view, std::string_view> flags[] = {
        {"--frames", "frames"}, {"--warmup", "warmup"},        {"--time", "time"},    {"--fps", "fps"},
        {"--flips", "flips"},   {"--samples", "soft_samples"}, {"--width", "width"}, {"--height", "height"}};
    for (const auto& [flag, name] : flags)
        for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at + name.size())) {
            const std::size_t end = at + flag.size();
            if (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-')) {
                at = end - name.size();  // a longer flag (--frames-x): not this one
                continue;
            }
            message.replace(at, flag.size(), name);
        }
    return message;
}

void raiseInput(const Error& e) { throw py::value_error(pythonNames(e.what())); }

py::array_t<std::uint8_t> rgba(ImageRGBA8&& image) {
    // The array takes the pixels over (a capsule frees them with it): no copy.
    auto* owned = new std::vector<std::uint8_t>(std::move(image.pixels));
    const py::capsule free(owned, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
    return py::array_t<std::uint8_t>({image.height, image.width, 4}, owned->data(), free);
}

py::array_t<std::uint8_t> rgba(const ImageRGBA8& image) {
    py::array_t<std::uint8_t> out({image.height, image.width, 4});
    std::memcpy(out.mutable_data(), image.pixels.data(), image.pixels.size());
    return out;
}

py::array_t<float> unit(const ImageGray16& image) {
    py::array_t<float> out({image.height, image.width});
    float* d = out.mutable_data();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) d[i] = static_cast<float>(image.pixels[i]) / 65535.0f;
    return out;
}

py::array_t<bool> mask(const ImageGray8& image) {
    py::array_t<bool> out({image.height, image.width});
    bool* d = out.mutable_data();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) d[i] = image.pixels[i] != 0;
    return out;
}

RenderOptions frameOptions(int width, int height, double time) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.timeSeconds = time;
    return options;
}

} // namespace shadowlab::python
