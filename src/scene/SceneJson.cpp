// Reading a scene file's JSON (SceneJson.h): the error that names the file,
// the JSON path or the `--set` flag; the Reader's checked values; keyframes.
#include "scene/SceneJson.h"

#include <shadowlab/Text.h>

#include <shadowlab/Error.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shadowlab::scenefile {

using overrides::typeName;

// --- Reading values with their JSON path ------------------------------------

namespace {
// The message of ParseContext::fail: the --set whose value `path` lies in, else the source.
std::string failure(const ParseContext& c, const std::string& path, const std::string& message) {
    // An error inside an overridden value is the flag's fault: name the flag.
    if (const overrides::Override* o = overrides::overrideAt(c.overrides, path)) return text::escapeControl(o->flag + ": " + path + ": " + message);
    // Keys, values and file names are quoted as written: escape them so
    // the message stays on one line.
    return text::escapeControl(c.source + ": " + (path.empty() ? "" : path + ": ") + message);
}
} // namespace

void ParseContext::fail(const std::string& path, const std::string& message) const { throw Error(failure(*this, path, message)); }

void ParseContext::failUnsupported(const std::string& path, const std::string& message) const {
    throw UnsupportedError(failure(*this, path, message));
}

void Reader::checkKeys(const std::vector<const char*>& known) const {
    requireObject();
    for (const auto& [key, _] : value_.items()) {
        bool found = false;
        for (const char* k : known) found = found || key == k;
        if (!found) {
            std::string list;
            for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
            ctx_.fail(path_.empty() ? key : path_ + "." + key, "unknown key (expected one of: " + list + ")");
        }
    }
}

double Reader::real() const {
    if (!value_.is_number()) fail(std::string("expected a number, got ") + typeName(value_));
    const double d = value_.get<double>();
    // The limit is a float's range, where every scene value ends up.
    if (!std::isfinite(d) || std::fabs(d) > 3.0e38) fail("expected a finite number of magnitude at most 3e38 (a float's range), got " + text::numberText(d));
    return d;
}

int Reader::integer() const {
    if (!value_.is_number_integer()) fail(std::string("expected an integer, got ") + typeName(value_));
    // Unsigned values past 2^63 would wrap to negative as long long.
    if (value_.is_number_unsigned() && value_.get<unsigned long long>() > 1000000000ULL)
        fail("expected an integer in -1000000000..1000000000, got " + std::to_string(value_.get<unsigned long long>()));
    const auto v = value_.get<long long>();
    if (v < -1000000000LL || v > 1000000000LL) fail("expected an integer in -1000000000..1000000000, got " + std::to_string(v));
    return static_cast<int>(v);
}

bool Reader::boolean() const {
    if (!value_.is_boolean()) fail(std::string("expected true or false, got ") + typeName(value_));
    return value_.get<bool>();
}

std::string Reader::string() const {
    if (!value_.is_string()) fail(std::string("expected a string, got ") + typeName(value_));
    return value_.get<std::string>();
}

glm::vec3 Reader::vec3() const {
    if (!value_.is_array()) fail(std::string("expected 3 numbers, got ") + typeName(value_));
    if (value_.size() != 3) fail("expected 3 numbers, got " + std::to_string(value_.size()));
    return {element(0).number(), element(1).number(), element(2).number()};
}

// Optional members with defaults and checks.

float Reader::positive(const std::string& key, float def) const {
    if (!has(key)) return def;
    const float v = child(key).number();
    if (!(v > 0.0f)) child(key).fail("expected a number > 0, got " + fmt(child(key).value().get<double>()) + (v == 0.0f ? " (0 as a 32-bit float)" : ""));
    return v;
}

float Reader::nonNegative(const std::string& key, float def) const {
    if (!has(key)) return def;
    const float v = child(key).number();
    if (v < 0.0f) child(key).fail("expected a number >= 0, got " + fmt(v));
    return v;
}

int Reader::integer(const std::string& key, int def, int minimum, int maximum) const {
    if (!has(key)) return def;
    // Checked against the key's own range, not integer()'s +-10^9: a seed's
    // documented 2147483647 was refused as "out of range".
    const Reader c = child(key);
    const nlohmann::json& value = c.value();
    if (!value.is_number_integer()) c.fail(std::string("expected an integer, got ") + typeName(value));
    const std::string range = "expected an integer in " + std::to_string(minimum) + ".." + std::to_string(maximum) + ", got ";
    if (value.is_number_unsigned() && value.get<unsigned long long>() > static_cast<unsigned long long>(std::max(maximum, 0)))
        c.fail(range + std::to_string(value.get<unsigned long long>()));
    const long long v = value.get<long long>();
    if (v < minimum || v > maximum) c.fail(range + std::to_string(v));
    return static_cast<int>(v);
}

glm::vec3 Reader::color(const std::string& key, glm::vec3 def) const {
    if (!has(key)) return def;
    const glm::vec3 c = child(key).vec3();
    if (c.x < 0 || c.y < 0 || c.z < 0) child(key).fail("expected 3 numbers >= 0 (linear RGB)");
    return c;
}

glm::vec3 Reader::direction(const std::string& key, glm::vec3 def) const {
    if (!has(key)) return def;
    const glm::vec3 d = child(key).vec3();
    // Scale by the largest component first: the length of [1e30, 1e30, 1e30]
    // overflows a float and the plain normalisation would give [0, 0, 0].
    const float largest = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    if (!(largest > 0.0f)) child(key).fail("expected a non-zero direction, got [0, 0, 0]");
    const glm::vec3 unit = glm::normalize(d / largest);
    if (!std::isfinite(unit.x) || !std::isfinite(unit.y) || !std::isfinite(unit.z)) child(key).fail("cannot normalise this direction");
    return unit;
}

std::string Reader::fmt(double v) { return text::numberText(v); }

// --- Keyframes --------------------------------------------------------------

std::vector<double> readKeyTimes(const Reader& r) {
    if (!r.has("times")) r.fail("missing key 'times' (seconds, strictly increasing)");
    const Reader times = r.child("times");
    times.requireArray();
    if (times.value().empty()) times.fail("expected at least one time");
    std::vector<double> out;
    for (std::size_t i = 0; i < times.value().size(); ++i) {
        const Reader t = times.element(i);
        const double seconds = t.real();
        if (i > 0 && !(seconds > out.back()))
            t.fail("expected times strictly increasing, got " + Reader::fmt(seconds) + " after " + Reader::fmt(out.back()));
        out.push_back(seconds);
    }
    return out;
}

std::vector<glm::vec3> readKeyPoints(const Reader& r, const std::string& key, const std::string& what, std::size_t count) {
    if (!r.has(key)) r.fail("missing key '" + key + "' (one [x, y, z] per time)");
    const Reader points = r.child(key);
    points.requireArray();
    if (points.value().size() != count)
        points.fail("expected one " + what + " per time (" + std::to_string(count) + "), got " + std::to_string(points.value().size()));
    std::vector<glm::vec3> out;
    for (std::size_t i = 0; i < count; ++i) out.push_back(points.element(i).vec3());
    return out;
}

} // namespace shadowlab::scenefile
