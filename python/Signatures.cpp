// The Python module's calls with arguments of the wrong type: pybind11's
// own TypeError lists every signature over four lines and does not say
// which argument is wrong. Each function and method keeps its typed
// binding (and so every conversion pybind11 makes for a good call); a
// wrapper around it turns that error, and only that one, into one line
// naming the argument: TypeError for a value of the wrong type, an
// unknown keyword or a missing argument, ValueError for an integer past
// the C++ type's range (docs/python.md).
#include "Module.h"

#include <shadowlab/Text.h>

#include <climits>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::python {

namespace {

enum class Kind { Any, Int, Float, Bool, Dict, Scene };

struct Parameter {
    const char* name;
    Kind kind;
    bool required;
};

std::string typeOf(const py::handle& value) { return py::str(py::type::of(value).attr("__name__")).cast<std::string>(); }

// Why `value` cannot be parameter `p`, or "" when it can (as pybind11
// converts: an int from anything with __index__, a float from int or
// float, a bool from bool or numpy.bool_).
std::pair<std::string, bool> problem(const Parameter& p, const py::handle& value, const py::handle& sceneType) {
    const std::string name = p.name;
    switch (p.kind) {
    case Kind::Any: return {"", false};
    case Kind::Int: {
        if (!PyIndex_Check(value.ptr()) || PyFloat_Check(value.ptr())) return {name + ": expected an int, got " + typeOf(value), false};
        const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
        if (overflow != 0 || v < INT_MIN || v > INT_MAX) {
            const std::string shown = text::clipMiddle(py::cast<std::string>(py::str(i.ptr())));
            return {name + " " + shown + ": expected an integer in " + std::to_string(INT_MIN) + ".." + std::to_string(INT_MAX), true};
        }
        return {"", false};
    }
    case Kind::Float:
        if (PyBool_Check(value.ptr()) || !(PyFloat_Check(value.ptr()) || PyLong_Check(value.ptr()) || PyIndex_Check(value.ptr()) ||
                                          py::hasattr(value, "__float__")))
            return {name + ": expected a number, got " + typeOf(value), false};
        if (PyLong_Check(value.ptr()) || (!PyFloat_Check(value.ptr()) && PyIndex_Check(value.ptr()))) {
            // An integer past a double's range (10**400): pybind11 refuses it as a type.
            const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
            const double d = PyLong_AsDouble(i.ptr());
            if (d == -1.0 && PyErr_Occurred()) {
                PyErr_Clear();
                const std::string shown = text::clipMiddle(py::cast<std::string>(py::str(i.ptr())));
                return {name + " " + shown + ": expected a finite number (past a double's range)", true};
            }
        }
        return {"", false};
    case Kind::Bool:
        if (!PyBool_Check(value.ptr()) && typeOf(value) != "bool_") return {name + ": expected True or False, got " + typeOf(value), false};
        return {"", false};
    case Kind::Dict:
        if (!PyDict_Check(value.ptr())) return {name + ": expected a dict {path: value}, got " + typeOf(value), false};
        return {"", false};
    case Kind::Scene:
        if (!py::isinstance(value, sceneType))
            return {name + ": expected a shadowlab.Scene (load_scene, load_scene_json or default_scene), got " + typeOf(value), false};
        return {"", false};
    }
    return {"", false};
}

// Raises the one-line error for a call of `function` with `args` and
// `kwargs` that matched no typed binding; returns when it finds none.
void explain(const std::string& function, const std::vector<Parameter>& params, const py::tuple& args, const py::dict& kwargs,
             const py::handle& sceneType) {
    std::vector<py::object> bound(params.size());
    if (args.size() > params.size())
        throw py::type_error(function + "() takes at most " + std::to_string(params.size()) + " arguments, got " + std::to_string(args.size()));
    for (std::size_t i = 0; i < args.size(); ++i) bound[i] = py::reinterpret_borrow<py::object>(args[i]);
    for (const auto& [key, value] : kwargs) {
        const std::string k = py::str(key).cast<std::string>();
        std::size_t i = 0;
        while (i < params.size() && k != params[i].name) ++i;
        if (i == params.size()) throw py::type_error(function + "(): no argument named " + text::escapeControl(text::clipMiddle(k)));
        if (bound[i]) throw py::type_error(function + "(): " + k + " given twice (by position and by name)");
        bound[i] = py::reinterpret_borrow<py::object>(value);
    }
    for (std::size_t i = 0; i < params.size(); ++i) {
        if (!bound[i]) {
            if (params[i].required) throw py::type_error(function + "(): missing argument " + params[i].name);
            continue;
        }
        const auto [message, range] = problem(params[i], bound[i], sceneType);
        if (message.empty()) continue;
        if (range) throw InputFailure(message);
        throw py::type_error(message);
    }
}

// `original` called with the caller's arguments; pybind11's "incompatible
// function arguments" explained in one line.
py::object call(const py::object& original, const std::string& function, const std::vector<Parameter>& params, const py::args& args,
                const py::kwargs& kwargs, const py::handle& sceneType) {
    try {
        return original(*args, **kwargs);
    } catch (py::error_already_set& e) {
        if (!e.matches(PyExc_TypeError) || std::string(e.what()).find("incompatible function arguments") == std::string::npos) throw;
        explain(function, params, args, kwargs, sceneType);
        const std::string what = e.what();
        throw py::type_error(what.substr(0, what.find('\n')));  // no argument to blame: pybind11's first line
    }
}

void wrapFunction(py::module_& m, const char* name, std::vector<Parameter> params, const py::handle& sceneType) {
    const py::object original = m.attr(name);
    const std::string function = name;
    m.attr(name) = py::cpp_function(
        [original, function, params = std::move(params), sceneType](const py::args& args, const py::kwargs& kwargs) {
            return call(original, function, params, args, kwargs, sceneType);
        },
        py::name(name), py::doc(py::str(original.attr("__doc__")).cast<std::string>().c_str()));
}

void wrapMethod(const py::object& cls, const char* name, std::vector<Parameter> params, const py::handle& sceneType) {
    const py::object original = cls.attr(name);
    const std::string function = std::string("Scene.") + name;
    // The bound method's self arrives as the first positional argument.
    params.insert(params.begin(), Parameter{"self", Kind::Scene, true});
    py::setattr(cls, name,
                py::cpp_function(
                    [original, function, params = std::move(params), sceneType](const py::args& args, const py::kwargs& kwargs) {
                        return call(original, function, params, args, kwargs, sceneType);
                    },
                    py::name(name), py::is_method(cls), py::doc(py::str(original.attr("__doc__")).cast<std::string>().c_str())));
}

} // namespace

void explainArgumentErrors(py::module_& m) {
    const py::object scene = m.attr("Scene");
    const Parameter sceneArg{"scene", Kind::Scene, true}, width{"width", Kind::Int, true}, height{"height", Kind::Int, true};
    const Parameter light{"light", Kind::Int, true}, time{"time", Kind::Float, false}, softSamples{"soft_samples", Kind::Int, false};
    const Parameter overrides{"overrides", Kind::Dict, false};
    wrapFunction(m, "render", {sceneArg, width, height, time}, scene);
    wrapFunction(m, "visibility", {sceneArg, light, width, height, {"coloured", Kind::Bool, false}, time}, scene);
    wrapFunction(m, "debug_images", {sceneArg, width, height, time}, scene);
    wrapFunction(m, "compare", {sceneArg, width, height, softSamples, time}, scene);
    wrapFunction(m, "reference", {sceneArg, light, width, height, softSamples, time}, scene);
    wrapFunction(m, "bench",
                 {{"scenes", Kind::Any, false}, {"width", Kind::Int, false}, {"height", Kind::Int, false}, {"vary", Kind::Any, false}, overrides,
                  {"frames", Kind::Int, false}, {"warmup", Kind::Int, false}, time, {"fps", Kind::Float, false}, {"flips", Kind::Bool, false},
                  softSamples, {"out", Kind::Any, false}, {"rounds", Kind::Int, false}, {"skip_unsupported", Kind::Bool, false}},
                 scene);
    wrapFunction(m, "load_scene", {{"path", Kind::Any, true}, overrides, {"camera", Kind::Any, false}}, scene);
    wrapFunction(m, "load_scene_json", {{"text", Kind::Any, true}, {"base_dir", Kind::Any, false}, overrides}, scene);
    wrapFunction(m, "default_scene", {overrides}, scene);
    wrapFunction(m, "live_gl_objects", {}, scene);
    wrapFunction(m, "techniques", {}, scene);
    wrapMethod(scene, "with_overrides", {{"overrides", Kind::Dict, true}}, scene);
}

} // namespace shadowlab::python
