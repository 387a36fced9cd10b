// The Python module's scenes (Module.h): loaded from files or JSON text
// with `--set`'s override paths, and the read-only Scene class.
#include "Module.h"

#include <pybind11/stl.h>

namespace shadowlab::python {

PyScene load(const std::string& path, std::vector<std::string> lines, int camera) {
    if (path.empty() && camera >= 0) throw InputFailure("camera: needs a glTF file (the default scene has one camera)");
    try {
        Scene s = path.empty() ? defaultScene(lines) : loadSceneFile(path, lines, SceneFileOptions{camera});
        return {std::make_shared<const Scene>(std::move(s)), path, std::move(lines), std::nullopt, {}, camera};
    } catch (const Error& e) {
        raiseInput(e, lines);
    }
}

PyScene loadJson(const std::string& text, const std::string& baseDir, std::vector<std::string> lines) {
    try {
        Scene s = parseScene(text, "<json>", baseDir, lines);
        return {std::make_shared<const Scene>(std::move(s)), "", std::move(lines), text, baseDir};
    } catch (const Error& e) {
        raiseInput(e, lines);
    }
}

namespace {

PyScene reload(const PyScene& s, std::vector<std::string> lines) {
    return s.text ? loadJson(*s.text, s.baseDir, std::move(lines)) : load(s.path, std::move(lines), s.camera);
}

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

} // namespace

void bindScenes(py::module_& m) {
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
            d["orthoHeight"] = s.scene->camera.orthoHeight;
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
            // A key the scene was loaded with takes its new value: its earlier
            // line goes, and so do those inside it (a block given whole).
            std::vector<std::string> lines = s.overrides;
            for (std::string& l : overrideLines(overrides)) {
                std::erase_if(lines, [&](const std::string& old) { return overrideDiscarding({old, l}).has_value(); });
                lines.push_back(std::move(l));
            }
            return reload(s, std::move(lines));
        }, py::arg("overrides"), "A new scene: this one's file and overrides, with these set (a key it had takes the new value; the same paths as --set)")
        .def("__repr__", [](const PyScene& s) { return "<shadowlab.Scene '" + s.scene->name + "', " + std::to_string(s.scene->lights.size()) + " lights>"; });

    m.def("load_scene", [](const py::object& path, const py::dict& overrides, const py::object& camera) {
        int index = -1;
        if (!camera.is_none()) {
            if (PyBool_Check(camera.ptr()) || !py::isinstance<py::int_>(camera)) throw InputFailure("camera: expected an int or None");
            const long long v = camera.cast<long long>();
            if (v < 0 || v > 65535) throw InputFailure("camera " + std::to_string(v) + ": expected an index from 0 (a glTF file's cameras, in node order)");
            index = static_cast<int>(v);
        }
        return load(pathArgument(path, "path"), overrideLines(overrides), index);
    }, py::arg("path"), py::arg("overrides") = py::dict(), py::arg("camera") = py::none(),
          "A scene file (JSON, or a .gltf/.glb file as a whole scene; a str or os.PathLike) with overrides {path: value} as --set takes them, "
          "e.g. {\"lights[0].shadow.map.size\": 1024}; camera: a glTF file's camera by index (default its first)");
    m.def("load_scene_json", [](const py::object& text, const py::object& baseDir, const py::dict& overrides) {
        if (!py::isinstance<py::str>(text)) throw InputFailure("text: expected the scene's JSON as a str");
        std::string json;
        try {
            json = text.cast<std::string>();
        } catch (const std::exception&) {
            throw InputFailure("text: not valid UTF-8 text");
        }
        return loadJson(json, pathArgument(baseDir, "base_dir"), overrideLines(overrides));
    }, py::arg("text"), py::arg("base_dir") = ".", py::arg("overrides") = py::dict(),
          "A scene from JSON text (errors name it \"<json>\"), its relative paths (meshes, textures) from base_dir");
    m.def("default_scene", [](const py::dict& overrides) { return load("", overrideLines(overrides)); }, py::arg("overrides") = py::dict(),
          "The built-in default scene (what `shadowlab render` draws without a scene file)");
}

} // namespace shadowlab::python
