// The Python module's shared parts (Module.h): the context and the renderer
// it keeps, images as arrays.
#include "Module.h"

#include <cstring>

#include <unistd.h>

namespace shadowlab::python {

namespace {

struct Gl {
    std::mutex lock;
    std::unique_ptr<Context> context;
    pid_t owner = 0;  ///< the process that made the context (0: none made yet)
    /// Set by the module's atexit hook: calls made after it (other atexit
    /// handlers, __del__ at shutdown) keep no renderer past their end.
    bool closing = false;
    // Declared after the context: destroyed before it.
    std::shared_ptr<const Scene> keptScene;
    std::unique_ptr<Renderer> kept;

    /// Whether this process is a child forked after the context was made:
    /// the child has the parent's memory but not its EGL display, so no GL
    /// call may be made there (libepoxy aborts the process).
    bool forked() const { return owner != 0 && owner != getpid(); }
    /// In a forked child, the parent's context and renderer are let go of
    /// without a GL call (their memory is the child's; the GL objects are
    /// the parent's).
    void abandonIfForked() {
        if (!forked()) return;
        (void)kept.release();
        keptScene.reset();
        (void)context.release();
    }
    ~Gl() {
        abandonIfForked();
        if (kept && context) {  // a renderer kept at exit: deleted in its own context
            context->makeCurrent();
            kept.reset();
        }
    }
};
Gl& gl() {
    static Gl g;
    return g;
}

} // namespace

std::mutex& glLock() { return gl().lock; }

Context& contextLocked() {
    Gl& g = gl();
    if (g.forked())
        throw std::runtime_error("shadowlab: this process was forked from one that had made its OpenGL context, which a forked child "
                                 "cannot use; start worker processes with multiprocessing's 'spawn' start method "
                                 "(multiprocessing.get_context('spawn')), or fork before the first shadowlab call");
    if (!g.context) {
        try {
            g.context = std::make_unique<Context>(Context::createHeadless());
            g.owner = getpid();
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
    g.closing = true;
    g.abandonIfForked();
    if (!g.kept || !g.context) return;
    g.context->makeCurrent();  // its GL objects are deleted in the context they belong to
    forgetRenderer();
    g.context->releaseCurrent();
}

Released::~Released() {
    Gl& g = gl();
    if (g.forked() || !g.context) return;
    if (g.closing) forgetRenderer();  // after the atexit hook nothing is kept: the next call may be the last
    g.context->releaseCurrent();
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
