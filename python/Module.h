#pragma once
// The Python module's shared parts (docs/python.md): the one GL context and
// the scaffold every drawing call runs in, scenes as Python sees them,
// images as numpy arrays, the library's errors as Python's. Each group of
// calls has a file: Scenes.cpp (loading, Scene), Frames.cpp (render,
// visibility, debug images), Reference.cpp (reference, compare), Bench.cpp
// (bench); module.cpp binds them, Signatures.cpp explains arguments of the
// wrong type.
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Limits.h>
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
    int camera = -1;                     ///< load_scene's camera=: a glTF file's camera index; -1 its first
};

// ---- arguments (Arguments.cpp) --------------------------------------------

/// `overrides` as `--set` lines: each key a scene path (text without '='
/// or NUL), each value as JSON (json.dumps, no NaN: a str is a JSON
/// string); ValueError naming `overrides[KEY]` otherwise.
std::vector<std::string> overrideLines(const py::dict& overrides);
/// bench's `vary` ({key: [values]} or [(key, [values]), ...]) as `--vary`
/// lines, each value as JSON; ValueError naming `vary[KEY]` otherwise.
std::vector<std::string> varyLines(const py::object& vary);
/// A path argument (str or os.PathLike) as UTF-8 text; ValueError naming
/// `name` when it is none, empty, not UTF-8 or holds a NUL.
std::string pathArgument(const py::handle& value, const std::string& name);
/// A message of the library's as Python names things, one line: the
/// call's `overrides` lines' `--set K=V` as `overrides[K]`, other `--set
/// K=V` as `overrides[K]=V`, `--vary K=V` as `vary[K]=V`, the flags
/// (`--frames`, `--samples`, `--width`, ...) as the keyword arguments;
/// control characters escaped, a huge message clipped in its middle.
std::string pythonNames(std::string message, const std::vector<std::string>& overrides = {});
/// Bad input: raised as `shadowlab.InputError`, a ValueError (module.cpp
/// registers it), for every value of the caller's that is wrong, wherever
/// it is found: in the arguments, in reading the scene, or while drawing
/// (the library's InputError).
struct InputFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The message of a library error found while drawing, with the file or
/// override that set the value it blames (withValueSource), named as
/// pythonNames says.
std::string drawingMessage(const Error& e, const std::string& sourceName, const std::vector<std::string>& overrides);

/// An Error for bad input as InputError, named as pythonNames says.
[[noreturn]] void raiseInput(const Error& e, const std::vector<std::string>& overrides = {});
/// A frame's size (at least 1 pixel; within the host's memory: the
/// library's checkMemory) and time (finite); ValueError otherwise.
void checkFrame(int width, int height, double time);
/// soft_samples within 1..kMaxSoftSamples and the reference's rays for the
/// frame within the library's limit (checkReferenceRays); ValueError otherwise.
void checkSoftSamples(int softSamples, int width, int height);

// ---- scenes (Scenes.cpp) --------------------------------------------------

PyScene load(const std::string& path, std::vector<std::string> lines, int camera = -1);
PyScene loadJson(const std::string& text, const std::string& baseDir, std::vector<std::string> lines);
void bindScenes(py::module_& m);

// ---- images ---------------------------------------------------------------

py::array_t<std::uint8_t> rgba(const ImageRGBA8& image);  ///< HxWx4 uint8, a copy
py::array_t<std::uint8_t> rgba(ImageRGBA8&& image);       ///< the same, the pixels moved into the array
py::array_t<float> unit(const ImageGray16& image);        ///< HxW float32 in 0..1
py::array_t<bool> mask(const ImageGray8& image);          ///< HxW bool, true where not 0

// ---- drawing --------------------------------------------------------------

RenderOptions frameOptions(int width, int height, double time);

/// The scaffolding of every drawing call: the frame checked (checkFrame;
/// GL's size limits once the context is there), the GIL let go, the
/// context taken on this thread (one call at a time) and let go after, a
/// renderer with the scene uploaded (rendererFor: kept from the previous
/// call with the same scene), `use` run with it and the scene at `time`;
/// the library's errors as InputError (a size past the GPU's limit, a
/// value of the scene's that cannot be drawn: named with the override or
/// file that set it) or RuntimeError (GL's), named as pythonNames says.
template <class Use>
void drawn(const PyScene& s, int width, int height, double time, const Use& use) {
    checkFrame(width, height, time);
    std::string failure;
    bool input = false;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard hold(glLock());
        const Released release;
        Context& context = contextLocked();
        try {
            checkSize(width, height, context.info());
        } catch (const Error& e) {
            failure = pythonNames(e.what());
            input = true;
        }
        if (!input) try {
                const Scene at = sceneAtTime(*s.scene, time);
                use(rendererFor(context, s.scene), at);
            } catch (const Error& e) {
                input = dynamic_cast<const InputError*>(&e) != nullptr;
                failure = drawingMessage(e, s.text ? "<json>" : s.path, s.overrides);
                forgetRenderer();
            }
    }
    if (input) throw InputFailure(failure);
    if (!failure.empty()) throw std::runtime_error(failure);
}

py::array_t<std::uint8_t> render(const PyScene& s, int width, int height, double time);
py::array_t<float> visibility(const PyScene& s, int light, int width, int height, bool coloured, double time);
py::dict debugImages(const PyScene& s, int width, int height, double time);
py::array_t<float> reference(const PyScene& s, int light, int width, int height, int softSamples, double time);
py::dict compare(const PyScene& s, int width, int height, int softSamples, double time);
/// Every call's and Scene.with_overrides's arguments of the wrong type
/// explained in one line naming the argument (Signatures.cpp); after the
/// bindings.
void explainArgumentErrors(py::module_& m);

py::list bench(const py::object& scenes, int width, int height, const py::object& vary, const py::dict& overrides, int frames, int warmup,
               double time, double fps, bool flips, int softSamples, const py::object& out, int rounds, bool skipUnsupported);

} // namespace shadowlab::python
