// `--set` overrides (see Overrides.h): parsing `a.b[2].c` paths and
// writing values into the document.
#include "scene/Overrides.h"

#include <shadowlab/Text.h>

#include <shadowlab/Error.h>

#include <charconv>

namespace shadowlab::overrides {

using nlohmann::json;

const char* typeName(const json& j) {
    switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    case json::value_t::discarded: return "nothing";
    default: return "a number";
    }
}

namespace {

struct PathStep {
    bool isIndex = false;
    std::string key;
    std::size_t index = 0;
};

// Parses `a.b[2].c` into steps; throws with `flag` on bad syntax.
std::vector<PathStep> parsePath(const std::string& path, const std::string& flag) {
    std::vector<PathStep> steps;
    std::size_t i = 0;
    auto bad = [&](const std::string& why) { throw Error(flag + ": bad JSON path '" + path + "': " + why); };
    if (path.empty()) bad("empty");
    while (i < path.size()) {
        if (path[i] == '[') {
            const auto close = path.find(']', i);
            if (close == std::string::npos) bad("missing ']'");
            const std::string digits = path.substr(i + 1, close - i - 1);
            if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos)
                bad("expected an index in [], got '" + digits + "'");
            std::size_t index = 0;
            const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
            if (ec != std::errc() || end != digits.data() + digits.size()) bad("index " + digits + " is too large");
            steps.push_back({true, {}, index});
            i = close + 1;
            if (i < path.size() && path[i] == '.') ++i;
        } else {
            const auto end = path.find_first_of(".[", i);
            const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
            if (key.empty()) bad("empty key");
            steps.push_back({false, key, 0});
            i = end == std::string::npos ? path.size() : end;
            if (i < path.size() && path[i] == '.') {
                ++i;
                if (i == path.size()) bad("ends with '.'");
            }
        }
    }
    return steps;
}

std::string formatPath(const std::vector<PathStep>& steps) {
    std::string out;
    for (const PathStep& s : steps) {
        if (s.isIndex) out += "[" + std::to_string(s.index) + "]";
        else out += (out.empty() ? "" : ".") + s.key;
    }
    return out;
}

} // namespace

// Applies `key=value` overrides to the document; returns them for error attribution.
std::vector<Override> applyOverrides(json& doc, const std::vector<std::string>& overrides) {
    std::vector<Override> applied;
    for (const std::string& text : overrides) {
        const std::string flag = "--set " + text;
        const auto eq = text.find('=');
        if (eq == std::string::npos) throw Error(flag + ": expected key=value");
        const auto steps = parsePath(text.substr(0, eq), flag);
        const std::string valueText = text.substr(eq + 1);
        if (text::jsonDepth(valueText) > text::kMaxJsonDepth)
            throw Error(flag + ": value nested deeper than " + std::to_string(text::kMaxJsonDepth) + " levels");
        if (steps.size() > text::kMaxJsonDepth)
            throw Error(flag + ": path deeper than " + std::to_string(text::kMaxJsonDepth) + " levels");
        json value = json::parse(valueText, nullptr, false);
        if (value.is_discarded()) value = valueText;  // a bare word is a string
        json* node = &doc;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            const PathStep& step = steps[i];
            const std::string where = formatPath({steps.begin(), steps.begin() + static_cast<long>(i)});
            const std::string at = where.empty() ? "the scene" : "'" + where + "'";
            if (step.isIndex) {
                if (!node->is_array()) throw Error(flag + ": " + at + " is " + typeName(*node) + ", not an array");
                if (step.index >= node->size())
                    throw Error(flag + ": index " + std::to_string(step.index) + " out of range (" + at + " has " +
                                std::to_string(node->size()) + " elements)");
                node = &(*node)[step.index];
            } else {
                if (node->is_null() && i > 0) *node = json::object();
                if (!node->is_object()) throw Error(flag + ": " + at + " is " + typeName(*node) + ", not an object");
                node = &(*node)[step.key];
            }
        }
        *node = value;
        applied.push_back({flag, formatPath(steps)});
    }
    return applied;
}

std::vector<Override> describeOverrides(const std::vector<std::string>& overrides, const std::vector<std::string>& labels) {
    std::vector<Override> described;
    for (std::size_t i = 0; i < overrides.size(); ++i) {
        const std::string& text = overrides[i];
        const auto eq = text.find('=');
        if (eq == std::string::npos) continue;
        const std::string label = i < labels.size() ? labels[i] : "--set " + text;
        try {
            described.push_back({label, formatPath(parsePath(text.substr(0, eq), label))});
        } catch (const Error&) {
        }
    }
    return described;
}

namespace {

// Whether canonical path `inner` is `outer` or lies inside it.
bool within(const std::string& inner, const std::string& outer) {
    return inner == outer ||
           (inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 && (inner[outer.size()] == '.' || inner[outer.size()] == '['));
}

} // namespace

namespace {
// A path as canonical text (lights[00] is lights[0]); as written when it is
// not a valid path (parsing the scene refuses it).
std::string canonicalOrAsWritten(const std::string& path) {
    try {
        return formatPath(parsePath(path, path));
    } catch (const Error&) {
        return path;
    }
}
} // namespace

bool pathsOverlap(const std::string& a, const std::string& b) {
    const std::string ca = canonicalOrAsWritten(a), cb = canonicalOrAsWritten(b);
    return within(ca, cb) || within(cb, ca);
}

bool pathsEqual(const std::string& a, const std::string& b) { return canonicalOrAsWritten(a) == canonicalOrAsWritten(b); }

bool pathHolds(const std::string& outer, const std::string& inner) { return within(canonicalOrAsWritten(inner), canonicalOrAsWritten(outer)); }

const Override* overrideAt(const std::vector<Override>& applied, const std::string& path) {
    for (auto it = applied.rbegin(); it != applied.rend(); ++it)
        if (within(path, it->path) || within(it->path, path)) return &*it;
    return nullptr;
}

} // namespace shadowlab::overrides
