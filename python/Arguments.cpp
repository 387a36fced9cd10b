// The Python module's arguments (Module.h): each checked before anything is
// drawn, and the library's messages said as Python names things (the
// overrides' keys, bench's keyword arguments), one line each.
#include "Module.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Limits.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Text.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

namespace shadowlab::python {

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

std::string typeName(const py::handle& value) { return py::str(py::type::of(value).attr("__name__")).cast<std::string>(); }

// `value` as UTF-8 text, or ValueError naming `what` (a str with lone surrogates is not).
std::string utf8(const py::handle& value, const std::string& what) {
    try {
        return value.cast<std::string>();
    } catch (const py::error_already_set&) {
    } catch (const py::cast_error&) {
    }
    throw InputFailure(what + ": not valid UTF-8 text");
}

// A key of overrides or vary: a scene path, as text without '=' or NUL.
std::string sceneKey(const py::handle& key, const std::string& argument) {
    if (!py::isinstance<py::str>(key))
        throw InputFailure(argument + ": keys are scene paths as strings, e.g. \"lights[0].shadow.map.size\", got " + typeName(key));
    const std::string k = utf8(key, argument + " key");
    if (k.empty()) throw InputFailure(argument + ": an empty key");
    if (k.find('=') != std::string::npos || k.find('\0') != std::string::npos)
        throw InputFailure(argument + "[" + text::escapeControl(k) + "]: a key may not contain '=' or NUL");
    return k;
}

// A value as JSON text (json.dumps; NaN and infinities are not JSON), or
// ValueError naming `where`.
std::string jsonText(const py::handle& value, const std::string& where) {
    const py::object dumps = py::module_::import("json").attr("dumps");  // not static: a py::object must not outlive the interpreter
    try {
        return utf8(dumps(value, py::arg("allow_nan") = false), where);
    } catch (py::error_already_set& e) {
        const std::string why = e.what();
        throw InputFailure(where + ": not a JSON value (" + text::escapeControl(why.substr(0, why.find('\n'))) + ")");
    }
}

} // namespace

std::vector<std::string> overrideLines(const py::dict& overrides) {
    std::vector<std::string> lines, keys;
    for (const auto& [key, value] : overrides) {
        const std::string k = sceneKey(key, "overrides");
        lines.push_back(k + "=" + jsonText(value, "overrides[" + k + "]"));
        keys.push_back(k);
    }
    // One dict's keys are applied in order: one that drops what an earlier
    // one set (the same path spelt two ways, or a path holding it) would
    // leave that value unread, as two --set would.
    if (const auto clash = overrideDiscarding(lines)) {
        const std::string& later = keys[clash->first];
        const std::string& earlier = keys[clash->second];
        if (overridePathsEqual(later, earlier))
            throw InputFailure("overrides[" + later + "]: " + later + " is already set by overrides[" + earlier + "] (give each path once)");
        throw InputFailure("overrides[" + later + "]: replaces " + earlier + ", set by overrides[" + earlier +
                              "] (give the inner path after the outer one, or within its value)");
    }
    return lines;
}

std::vector<std::string> varyLines(const py::object& vary) {
    std::vector<std::string> lines;
    if (vary.is_none()) return lines;
    const bool isDict = py::isinstance<py::dict>(vary);
    if (!isDict && !py::isinstance<py::list>(vary) && !py::isinstance<py::tuple>(vary))
        throw InputFailure("vary: expected {key: [values]} or [(key, [values]), ...], got " + typeName(vary));
    const py::object pairs = isDict ? py::object(vary.attr("items")()) : vary;
    for (const py::handle& pair : pairs) {
        if (!(py::isinstance<py::tuple>(pair) || py::isinstance<py::list>(pair)) || py::len(pair) != 2)
            throw InputFailure("vary: expected {key: [values]} or [(key, [values]), ...]; an item is " + typeName(pair));
        const py::sequence kv = py::reinterpret_borrow<py::sequence>(pair);
        const std::string key = sceneKey(kv[0], "vary");
        const py::object values = kv[1];
        if (!(py::isinstance<py::list>(values) || py::isinstance<py::tuple>(values)))
            throw InputFailure("vary[" + key + "]: expected a list of values, got " + typeName(values));
        std::string line = key + "=";
        std::size_t count = 0;
        for (const py::handle& value : values) {
            if (count++ > 0) line += ',';
            line += jsonText(value, "vary[" + key + "]");
        }
        if (count == 0) throw InputFailure("vary[" + key + "]: no values");
        lines.push_back(line);
    }
    return lines;
}

std::string pathArgument(const py::handle& value, const std::string& name) {
    const py::object fspath = py::module_::import("os").attr("fspath");
    py::object text;
    try {
        text = fspath(value);
    } catch (const py::error_already_set&) {
        throw InputFailure(name + ": expected a path (str or os.PathLike), got " + typeName(value));
    }
    if (!py::isinstance<py::str>(text)) throw InputFailure(name + ": expected a path as text, got " + typeName(text));
    const std::string path = utf8(text, name);
    if (path.empty()) throw InputFailure(name + ": empty path");
    if (path.find('\0') != std::string::npos) throw InputFailure(name + " " + text::escapeControl(path) + ": a path may not contain NUL");
    return path;
}

std::string pythonNames(std::string message, const std::vector<std::string>& overrides) {
    // The call's own overrides as overrides[KEY] (the value is the caller's).
    for (const std::string& line : overrides) {
        const std::string flag = "--set " + line, name = "overrides[" + line.substr(0, line.find('=')) + "]";
        for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at + name.size()))
            message.replace(at, flag.size(), name);
    }
    message = keyed(keyed(std::move(message), "--set ", "overrides"), "--vary ", "vary");
    // The flags as the keyword arguments.
    static const std::pair<std::string_view, std::string_view> flags[] = {
        {"--frames", "frames"}, {"--warmup", "warmup"}, {"--rounds", "rounds"}, {"--time", "time"}, {"--fps", "fps"}, {"--flips", "flips"},
        {"--samples", "soft_samples"}, {"--width", "width"}, {"--height", "height"}, {"--vary", "vary"}, {"--set", "overrides"}};
    for (const auto& [flag, name] : flags)
        for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at + name.size())) {
            const std::size_t end = at + flag.size();
            if (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-')) {
                at = end - name.size();  // a longer flag (--frames-x): not this one
                continue;
            }
            message.replace(at, flag.size(), name);
        }
    return text::escapeControl(text::clipMiddle(message));
}

std::string drawingMessage(const Error& e, const std::string& sourceName, const std::vector<std::string>& overrides) {
    return pythonNames(withValueSource(e.what(), sourceName, overrides), overrides);
}

void raiseInput(const Error& e, const std::vector<std::string>& overrides) { throw InputFailure(pythonNames(e.what(), overrides)); }

void checkFrame(int width, int height, double time) {
    if (width < 1 || height < 1)
        throw InputFailure("width and height must be at least 1 pixel, got " + std::to_string(width) + "x" + std::to_string(height));
    if (!std::isfinite(time)) throw InputFailure("time " + text::numberText(time) + ": expected a finite number of seconds");
    try {
        checkMemory(width, height);  // the GPU's own limits: once the context is there (drawn)
    } catch (const Error& e) {
        raiseInput(e);
    }
}

void checkSoftSamples(int softSamples, int width, int height) {
    if (softSamples < 1 || softSamples > kMaxSoftSamples)
        throw InputFailure("soft_samples " + std::to_string(softSamples) + ": expected 1.." + std::to_string(kMaxSoftSamples));
    try {
        checkReferenceRays(width, height, softSamples);
    } catch (const Error& e) {
        raiseInput(e);
    }
}

} // namespace shadowlab::python
