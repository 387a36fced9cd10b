#pragma once
// The Python module's shared parts (docs/python.md): the one GL context and
// the scaffold every drawing call runs in, scenes as Python sees them,
// images as numpy arrays, the library's errors as Python's. Each group of
// calls has a file: Scenes.cpp (loading, Scene), Frames.cpp (render,
// visibility, debug images), Reference.cpp (reference, compare), Bench.cpp
// (bench); module.cpp binds them.
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/Scene.h>
#include <shadowlab/SceneFile.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::python {

namespace py = pybind11;

// ---- the context ----------------------------------------------------------

/// The lock every call that uses the context holds.
std::mutex& glLock();
/// The process's context, made on first use (RuntimeError when there is no
/// OpenGL 4.5), made current on this thread. Call with glLock() held.
Context& contextLocked();
/// Lets go of the context on this thread at the end of a call, so that the
/// next call may take it on another.
struct Released {
    ~Released();
};
/// A renderer with `scene` uploaded: the one the previous call used when it
/// drew the same scene (a Scene object is immutable: its meshes are those
/// uploaded; the lights and the camera are read at each frame), else a new
/// one, which replaces it. Call with glLock() held and the context current.
Renderer& rendererFor(Context& context, const std::shared_ptr<const Scene>& scene);
/// Drops the kept renderer (after a failure: its state is not known).
void forgetRenderer();
/// The same, taking the lock and the context (Python's atexit calls it,
/// while the context is still there).
void forgetRendererAtExit();

// ---- scenes ---------------------------------------------------------------

/// A loaded scene and what it was loaded from, read-only from Python.
struct PyScene {
    std::shared_ptr<const Scene> scene;
    std::string path;                    ///< the scene file ("" for the built-in default scene or JSON text)
    std::vector<std::string> overrides;  ///< as `--set` lines
    std::optional<std::string> text;     ///< load_scene_json: the JSON text
    std::string baseDir;                 ///< load_scene_json: where its relative paths start
};

/// `overrides` as `--set` lines: each value as JSON (Python's json.dumps),
/// so a str is a JSON string and numbers, bools and lists are themselves.
std::vector<std::string> overrideLines(const py::dict& overrides);
/// A message of the library's as Python names things: `--set K=V` as
/// `overrides[K]=V`, `--vary K=...` as `vary[K]=...`, a leading flag
/// (`--frames`, `--samples`, ...) as the keyword argument.
std::string pythonNames(std::string message);
/// An Error for bad input as ValueError, named as pythonNames says.
[[noreturn]] void raiseInput(const Error& e);
PyScene load(const std::string& path, std::vector<std::string> lines);
PyScene loadJson(const std::string& text, const std::string& baseDir, std::vector<std::string> lines);
void bindScenes(py::module_& m);

// ---- images ---------------------------------------------------------------

py::array_t<std::uint8_t> rgba(const ImageRGBA8& image);  ///< HxWx4 uint8, a copy
py::array_t<std::uint8_t> rgba(ImageRGBA8&& image);       ///< the same, the pixels moved into the array
py::array_t<float> unit(const ImageGray16& image);        ///< HxW float32 in 0..1
py::array_t<bool> mask(const ImageGray8& image);          ///< HxW bool, true where not 0

// ---- drawing --------------------------------------------------------------

RenderOptions frameOptions(int width, int height, double time);

/// The scaffolding of every drawing call: the size checked, the GIL let go,
/// the context taken on this thread (one call at a time) and let go after,
/// a renderer with the scene uploaded (rendererFor: kept from the previous
/// call with the same scene), `use` run with it and the scene at `time`;
/// the library's errors as ValueError (a size past the GPU's limit: the
/// caller's) or RuntimeError (GL's).
template <class Use>
void drawn(const PyScene& s, int width, int height, double time, const Use& use) {
    if (width < 1 || height < 1)
        throw py::value_error("width and height must be at least 1 pixel, got " + std::to_string(width) + "x" + std::to_string(height));
    std::string failure;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard hold(glLock());
        const Released release;
        Context& context = contextLocked();
        try {
            const Scene at = sceneAtTime(*s.scene, time);
            use(rendererFor(context, s.scene), at);
        } catch (const Error& e) {
            failure = e.what();
            forgetRenderer();
        }
    }
    if (failure.rfind("render size", 0) == 0) throw py::value_error(failure);
    if (!failure.empty()) throw std::runtime_error(failure);
}

py::array_t<std::uint8_t> render(const PyScene& s, int width, int height, double time);
py::array_t<float> visibility(const PyScene& s, int light, int width, int height, bool coloured, double time);
py::dict debugImages(const PyScene& s, int width, int height, double time);
py::array_t<float> reference(const PyScene& s, int light, int width, int height, int softSamples, double time);
py::dict compare(const PyScene& s, int width, int height, int softSamples, double time);
py::list bench(const py::object& scenes, int width, int height, const py::object& vary, const py::dict& overrides, int frames, int warmup,
               double time, double fps, bool flips, int softSamples, const py::object& out);

} // namespace shadowlab::python
