// The Python module's shared parts (Module.h): the context and the renderer
// it keeps, images as arrays.
#include "Module.h"

#include <cstring>

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
