// The Python module `shadowlab` (pybind11): scenes from files with the same
// override paths as `--set`, renders as numpy arrays, and the techniques'
// options tables, over the library's public API (docs/python.md).
//
// One headless GL context per process, made on first use; every call that
// draws takes it on the calling thread, one call at a time, with the GIL
// released while it draws. Bad input raises ValueError with the one-line
// message the CLI prints (the overrides' key named where `--set` would
// be); GL and system errors raise RuntimeError.
#include <shadowlab/Compare.h>
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace shadowlab;

namespace {

// The process's context and the lock every drawing call holds.
struct Gl {
    std::mutex lock;
    std::optional<Context> context;
};
Gl& gl() {
    static Gl g;
    return g;
}

// The context, made on first use (RuntimeError when there is no OpenGL 4.5).
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

// Lets go of the context on this thread at the end of a call, so that the
// next call may take it on another (after the call's Renderer is gone).
struct Released {
    ~Released() {
        if (gl().context) gl().context->releaseCurrent();
    }
};

// `overrides` as `--set` lines: each value as JSON (Python's json.dumps),
// so a str is a JSON string and numbers, bools and lists are themselves.
std::vector<std::string> overrideLines(const py::dict& overrides) {
    const py::object dumps = py::module_::import("json").attr("dumps");
    std::vector<std::string> lines;
    for (const auto& [key, value] : overrides) {
        if (!py::isinstance<py::str>(key)) throw py::value_error("overrides: keys are scene paths as strings, e.g. \"lights[0].shadow.map.size\"");
        lines.push_back(key.cast<std::string>() + "=" + dumps(value).cast<std::string>());
    }
    return lines;
}

// An Error from the scene parser as ValueError, the `--set K=V` the CLI
// would name said as the overrides' key.
[[noreturn]] void raiseInput(const Error& e) {
    std::string message = e.what();
    if (message.rfind("--set ", 0) == 0) message = "overrides[" + message.substr(6, message.find('=') - 6) + "]" + message.substr(message.find(':'));
    throw py::value_error(message);
}

// A loaded scene and what it was loaded from, read-only from Python.
struct PyScene {
    std::shared_ptr<const Scene> scene;
    std::string path;                    ///< the scene file ("" for the built-in default scene or JSON text)
    std::vector<std::string> overrides;  ///< as `--set` lines
    std::optional<std::string> text;     ///< load_scene_json: the JSON text
    std::string baseDir;                 ///< load_scene_json: where its relative paths start
};

PyScene load(const std::string& path, std::vector<std::string> lines) {
    try {
        Scene s = path.empty() ? defaultScene(lines) : loadSceneFile(path, lines);
        return {std::make_shared<const Scene>(std::move(s)), path, std::move(lines), std::nullopt, {}};
    } catch (const Error& e) {
        raiseInput(e);
    }
}

PyScene loadJson(const std::string& text, const std::string& baseDir, std::vector<std::string> lines) {
    try {
        Scene s = parseScene(text, "<json>", baseDir, lines);
        return {std::make_shared<const Scene>(std::move(s)), "", std::move(lines), text, baseDir};
    } catch (const Error& e) {
        raiseInput(e);
    }
}

PyScene reload(const PyScene& s, std::vector<std::string> lines) { return s.text ? loadJson(*s.text, s.baseDir, std::move(lines)) : load(s.path, std::move(lines)); }

py::list vec3(const glm::vec3& v) { return py::cast(std::vector<float>{v.x, v.y, v.z}); }

py::dict lightDict(const Light& l) {
    py::dict d;
    d["name"] = l.name;
    d["type"] = toString(l.type);
    d["color"] = vec3(l.color);
    d["intensity"] = l.intensity;
    if (l.type != LightType::Directional) d["position"] = vec3(l.position);
    if (l.type != LightType::Point) d["direction"] = vec3(l.direction);
    d["range"] = l.range;
    d["size"] = l.size;
    d["technique"] = l.shadow.technique;
    return d;
}

py::array_t<std::uint8_t> rgba(const ImageRGBA8& image);

// The scaffolding of every drawing call: the size checked, the GIL let go,
// the context taken on this thread (one call at a time) and let go after,
// the scene at `time` uploaded to a renderer of its own, `use` run with
// both; the library's errors as ValueError (a size past the GPU's limit:
// the caller's) or RuntimeError (GL's).
template <class Use>
void drawn(const PyScene& s, int width, int height, double time, const Use& use) {
    if (width < 1 || height < 1)
        throw py::value_error("width and height must be at least 1 pixel, got " + std::to_string(width) + "x" + std::to_string(height));
    std::string failure;
    {
        py::gil_scoped_release unlocked;
        std::lock_guard hold(gl().lock);
        const Released release;
        Context& context = contextLocked();
        try {
            const Scene at = sceneAtTime(*s.scene, time);
            Renderer renderer(context);
            renderer.upload(at);
            use(renderer, at);
        } catch (const Error& e) {
            failure = e.what();
        }
    }
    if (failure.rfind("render size", 0) == 0) throw py::value_error(failure);
    if (!failure.empty()) throw std::runtime_error(failure);
}

RenderOptions frameOptions(int width, int height, double time) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.timeSeconds = time;
    return options;
}

// The frame as the CLI writes it: RGBA bytes, top row first.
py::array_t<std::uint8_t> render(const PyScene& s, int width, int height, double time) {
    ImageRGBA8 image;
    drawn(s, width, height, time, [&](Renderer& renderer, const Scene& at) {
        renderer.render(at, frameOptions(width, height, time));
        image = renderer.readColor();
    });
    return rgba(image);
}

py::array_t<std::uint8_t> rgba(const ImageRGBA8& image) {
    py::array_t<std::uint8_t> out({image.height, image.width, 4});
    std::memcpy(out.mutable_data(), image.pixels.data(), image.pixels.size());
    return out;
}

// A 16-bit visibility image as float32 in 0..1.
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

// compare's metrics.json as a dict, its image files as arrays under "images"
// (the frame's and the reference's) and each light's "images" (error,
// visibility and techniqueVisibility in 0..1, reach as a mask).
py::dict compare(const PyScene& s, int width, int height, int softSamples, double time) {
    if (softSamples < 1) throw py::value_error("compare: soft_samples must be at least 1, got " + std::to_string(softSamples));
    Comparison c;
    std::vector<std::string> records;
    drawn(s, width, height, time, [&](Renderer& renderer, const Scene& at) {
        CompareOptions options;
        options.width = width;
        options.height = height;
        options.softSamples = softSamples;
        options.timeSeconds = time;
        c = compareWithReference(renderer, at, options);
        for (std::size_t i = 0; i < c.lights.size(); ++i) records.push_back(lightMetricsJson(at.lights[i], c.lights[i]));
    });
    const py::object loads = py::module_::import("json").attr("loads");
    py::list lights;
    for (std::size_t i = 0; i < c.lights.size(); ++i) {
        py::dict record = loads(records[i]);
        py::dict images;
        images["error"] = rgba(c.lights[i].errorImage);
        images["visibility"] = unit(c.lights[i].referenceVisibility);
        images["techniqueVisibility"] = unit(c.lights[i].techniqueVisibility);
        images["reach"] = mask(c.lights[i].reach);
        record["images"] = images;
        lights.append(record);
    }
    py::dict out;
    out["scene"] = s.scene->name;
    out["sceneFile"] = s.path.empty() ? std::string("<default>") : s.path;
    out["width"] = width;
    out["height"] = height;
    out["softSamples"] = softSamples;
    out["time"] = time;
    out["referenceMs"] = c.referenceMs;
    out["lights"] = lights;
    py::dict images;
    images["technique"] = rgba(c.technique);
    images["reference"] = rgba(c.reference);
    out["images"] = images;
    return out;
}

// Light `light`'s visibility as its technique computes it in the frame
// (1 lit, 0 shadowed, 0 on the background), HxW float32, or HxWx3 with
// `coloured` (transmittance through translucent casters); and the
// techniques' debug images as {name: HxWx4 uint8}.
struct Frame {
    std::vector<glm::vec3> visibility;
    std::vector<DebugImage> images;
};

Frame frameOf(const PyScene& s, int width, int height, double time, int light, bool images) {
    if (light >= 0 && static_cast<std::size_t>(light) >= s.scene->lights.size())
        throw py::value_error("light " + std::to_string(light) + ": the scene has " + std::to_string(s.scene->lights.size()) + " light(s)");
    Frame f;
    drawn(s, width, height, time, [&](Renderer& renderer, const Scene& at) {
        renderer.render(at, frameOptions(width, height, time));
        if (light >= 0) f.visibility = renderer.readVisibilityRgb(at, static_cast<std::size_t>(light));
        if (images) f.images = renderer.debugImages(at);
    });
    return f;
}

py::array_t<float> visibility(const PyScene& s, int light, int width, int height, bool coloured, double time) {
    if (light < 0) throw py::value_error("light " + std::to_string(light) + ": expected an index from 0");
    const Frame f = frameOf(s, width, height, time, light, false);
    if (coloured) {
        py::array_t<float> out({height, width, 3});
        std::memcpy(out.mutable_data(), f.visibility.data(), f.visibility.size() * sizeof(glm::vec3));
        return out;
    }
    py::array_t<float> out({height, width});
    float* d = out.mutable_data();
    for (std::size_t i = 0; i < f.visibility.size(); ++i) d[i] = (f.visibility[i].r + f.visibility[i].g + f.visibility[i].b) / 3.0f;
    return out;
}

py::dict debugImages(const PyScene& s, int width, int height, double time) {
    const Frame f = frameOf(s, width, height, time, -1, true);
    py::dict out;
    for (const DebugImage& d : f.images) out[py::str(d.name)] = rgba(d.image);
    return out;
}

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

} // namespace

PYBIND11_MODULE(shadowlab, m) {
    m.doc() = "shadowlab: real-time shadow techniques on OpenGL 4.5, measured against exact ray-traced shadows";

    py::class_<PyScene>(m, "Scene", "A loaded scene, read-only; with_overrides() makes a changed copy")
        .def_property_readonly("name", [](const PyScene& s) { return s.scene->name; })
        .def_property_readonly("path", [](const PyScene& s) { return s.path; })
        .def_property_readonly("lights", [](const PyScene& s) {
            py::list out;
            for (const Light& l : s.scene->lights) out.append(lightDict(l));
            return out;
        })
        .def_property_readonly("camera", [](const PyScene& s) {
            py::dict d;
            d["position"] = vec3(s.scene->camera.position);
            d["target"] = vec3(s.scene->camera.target);
            d["fovY"] = s.scene->camera.fovYDeg;
            d["near"] = s.scene->camera.nearPlane;
            d["far"] = s.scene->camera.farPlane;
            return d;
        })
        .def_property_readonly("nodes", [](const PyScene& s) {
            py::list out;
            for (const Node& n : s.scene->nodes) out.append(n.name);
            return out;
        })
        .def("with_overrides", [](const PyScene& s, const py::dict& overrides) {
            std::vector<std::string> lines = s.overrides;
            for (std::string& l : overrideLines(overrides)) lines.push_back(std::move(l));
            return reload(s, std::move(lines));
        }, py::arg("overrides"), "A new scene: this one's file and overrides, then these (the same paths as --set)")
        .def("__repr__", [](const PyScene& s) { return "<shadowlab.Scene '" + s.scene->name + "', " + std::to_string(s.scene->lights.size()) + " lights>"; });

    m.def("load_scene", [](const std::string& path, const py::dict& overrides) {
        if (path.empty()) throw py::value_error("load_scene: path is empty (default_scene() gives the built-in scene)");
        return load(path, overrideLines(overrides));
    }, py::arg("path"), py::arg("overrides") = py::dict(),
          "A scene file (JSON) with overrides {path: value} as --set takes them, e.g. {\"lights[0].shadow.map.size\": 1024}");
    m.def("load_scene_json", [](const std::string& text, const std::string& baseDir, const py::dict& overrides) {
        return loadJson(text, baseDir, overrideLines(overrides));
    }, py::arg("text"), py::arg("base_dir") = ".", py::arg("overrides") = py::dict(),
          "A scene from JSON text (errors name it \"<json>\"), its relative paths (meshes, textures) from base_dir");
    m.def("default_scene", [](const py::dict& overrides) { return load("", overrideLines(overrides)); }, py::arg("overrides") = py::dict(),
          "The built-in default scene (what `shadowlab render` draws without a scene file)");
    m.def("render", &render, py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("time") = 0.0,
          "The frame as a numpy uint8 array of height x width x 4 (RGBA, top row first): the pixels `shadowlab render` writes");
    m.def("visibility", &visibility, py::arg("scene"), py::arg("light"), py::arg("width"), py::arg("height"), py::arg("coloured") = false,
          py::arg("time") = 0.0,
          "Light `light`'s visibility as its technique computes it (1 lit, 0 shadowed, 0 on the background): float32 HxW, or HxWx3 with coloured=True");
    m.def("debug_images", &debugImages, py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("time") = 0.0,
          "The techniques' debug images of the frame (maps, cube crosses, texel density, the shadow atlas): {name: HxWx4 uint8}");
    m.def("compare", &compare, py::arg("scene"), py::arg("width"), py::arg("height"), py::arg("soft_samples") = 256, py::arg("time") = 0.0,
          "The scene against the ray-traced reference: compare's metrics.json as a dict (per light its record), with the images as arrays under \"images\"");
    m.def("techniques", &techniqueTables, "Every technique's options: {name: {\"summary\", \"options\": {key: {unit, range, default, doc[, choices]}}}}");
}
