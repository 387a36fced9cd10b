// The Python module `shadowlab` (pybind11): scenes from files with the same
// override paths as `--set`, renders, exact references, comparisons and
// benches as numpy arrays and dicts, and the techniques' options tables,
// over the library's public API (docs/python.md). Module.h says which file
// holds which calls; this one binds them.
//
// One headless GL context per process, made on first use; every call that
// draws takes it on the calling thread, one call at a time, with the GIL
// released while it draws. Bad input raises ValueError with the one-line
// message the CLI prints (the overrides' key named where `--set` would
// be); GL and system errors raise RuntimeError.
#include "Module.h"

#include <shadowlab/Techniques.h>

#include <pybind11/stl.h>

using namespace shadowlab;
using namespace shadowlab::python;

namespace {

// Every technique's options table: {name: {"summary", "options": {key: {...}}}}.
py::dict techniqueTables() {
    py::dict out;
    for (const TechniqueInfo& t : techniques()) {
        py::dict options;
        if (t.options)
            for (const OptionField& f : t.options->fields) {
                py::dict o;
                o["unit"] = f.unit;
                o["range"] = OptionTable::rangeText(f);
                o["default"] = t.options->defaultText(f);
                o["doc"] = f.doc;
                if (!f.choices.empty() && f.kind == OptionKind::Choice) o["choices"] = f.choices;
                options[py::str(f.key)] = o;
            }
        py::dict entry;
        entry["summary"] = t.summary;
        entry["options"] = options;
        out[py::str(t.name)] = entry;
    }
    return out;
}

// A handle on the process's one context (Context() makes it on first use,
// later calls return handles on the same one): what it runs on.
struct ContextHandle {
    GlInfo info;
};

ContextHandle processContext() {
    ContextHandle c;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard hold(glLock());
        const Released release;
        c.info = contextLocked().info();
    }
    return c;
}

} // namespace

PYBIND11_MODULE(shadowlab, m) {
    // numpy's C API looked up now, while the import holds the GIL and no other
    // call of ours runs: pybind11 looks it up at the first array, inside a
    // function-local static whose guard a thread would hold while the import
    // lets go of the GIL, and another thread holding the GIL would wait on that
    // guard for ever (four threads' first render() calls hung so).
    (void)py::detail::npy_api::get();
    m.doc() = "shadowlab: real-time shadow techniques on OpenGL 4.5, measured against exact ray-traced shadows";
    py::class_<ContextHandle>(m, "Context",
                          "The process's one headless OpenGL 4.5 context (EGL): Context() makes it on first use, as the first drawing call "
                          "does, and raises RuntimeError when there is none; every Context() is the same context")
        .def(py::init(&processContext))
        .def_property_readonly("renderer", [](const ContextHandle& c) { return c.info.renderer; })
        .def_property_readonly("vendor", [](const ContextHandle& c) { return c.info.vendor; })
        .def_property_readonly("version", [](const ContextHandle& c) { return c.info.version; })
        .def_property_readonly("glsl_version", [](const ContextHandle& c) { return c.info.glslVersion; })
        .def_property_readonly("platform", [](const ContextHandle& c) { return c.info.platform; })
        .def_property_readonly("max_texture_size", [](const ContextHandle& c) { return c.info.maxTextureSize; })
        .def_property_readonly("max_cube_map_size", [](const ContextHandle& c) { return c.info.maxCubeMapSize; })
        .def_property_readonly("device_memory_bytes", [](const ContextHandle& c) { return c.info.deviceMemoryBytes; },
                               "free device memory the driver reported when the context was made; 0 when it reports none (llvmpipe)")
        .def("__repr__", [](const ContextHandle& c) { return "<shadowlab.Context " + c.info.platform + ": " + c.info.renderer + ", " + c.info.version + ">"; });
    py::register_exception<InputFailure>(m, "InputError", PyExc_ValueError)
        .doc() = "Bad input (a ValueError): an argument, a scene's value or an override that is wrong, named in one line with where it came from, "
                 "whether found in the arguments, in reading the scene or while drawing";
    bindScenes(m);
    // The kept renderer goes before the interpreter and the context do.
    py::module_::import("atexit").attr("register")(py::cpp_function([] {
        py::gil_scoped_release unlocked;
        forgetRendererAtExit();
    }));
    m.def("render", &render, py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("time") = 0.0,
          "The frame as a numpy uint8 array of height x width x 4 (RGBA, top row first): the pixels `shadowlab render` writes");
    m.def("visibility", &visibility, py::arg("scene"), py::arg("light"), py::arg("width"), py::arg("height"), py::arg("coloured") = false,
          py::arg("time") = 0.0,
          "Light `light`'s visibility as its technique computes it (1 lit, 0 shadowed, 0 on the background): float32 HxW, or HxWx3 with coloured=True");
    m.def("debug_images", &debugImages, py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("time") = 0.0,
          "The techniques' debug images of the frame (maps, cube crosses, texel density, the shadow atlas): {name: HxWx4 uint8}");
    m.def("compare", &compare, py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("soft_samples") = 256, py::arg("time") = 0.0,
          "The scene against the ray-traced reference: compare's metrics.json as a dict (per light its record), with the images as arrays under \"images\"");
    m.def("reference", &reference, py::arg("scene"), py::arg("light"), py::arg("width"), py::arg("height"), py::arg("soft_samples") = 256,
          py::arg("time") = 0.0,
          "Light `light`'s exact ray-traced visibility (Embree) at the frame's surface points: float32 HxW, 1 lit, 0 shadowed, 0 where the light does not reach");
    m.def("bench", &bench, py::arg("scenes") = py::none(), py::arg("width") = 960, py::arg("height") = 540, py::arg("vary") = py::none(),
          py::arg("overrides") = py::dict(), py::arg("frames") = 10, py::arg("warmup") = 2, py::arg("time") = 0.0, py::arg("fps") = 30.0,
          py::arg("flips") = false, py::arg("soft_samples") = 256, py::arg("out") = py::none(), py::arg("rounds") = 1, py::arg("skip_unsupported") = false,
          "`shadowlab bench`: every scene with every combination of vary's values ({key: [values]} or [(key, [values])]), timed and compared; "
          "results.json's rows as dicts with their images as arrays; with out=DIR also results.json, report.html and the images there");
    m.def("live_gl_objects", &liveGlObjects, "GL objects the library's handles own right now (0 between calls: each call's are gone at its end)");
    m.def("techniques", &techniqueTables, "Every technique's options: {name: {\"summary\", \"options\": {key: {unit, range, default, doc[, choices]}}}}");
    explainArgumentErrors(m);
}
