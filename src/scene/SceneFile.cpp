// JSON scene files: every key, unit and default is in docs/scene-format.md.
// Each value is read through a Reader that knows its JSON path, so any error
// names the file, the path and what was expected, and unknown keys are errors.
#include <shadowlab/SceneFile.h>

#include "scene/MeshFile.h"
#include "scene/Overrides.h"

#include "core/Text.h"

#include <shadowlab/Error.h>
#include <shadowlab/Shapes.h>
#include <shadowlab/Techniques.h>

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace shadowlab {

using nlohmann::json;
namespace fs = std::filesystem;
using overrides::Override, overrides::applyOverrides, overrides::typeName;

namespace {

// --- Reading values with their JSON path ------------------------------------

struct ParseContext {
    std::string source;  // file name for messages
    fs::path baseDir;
    std::vector<Override> overrides;

    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        // An error inside an overridden value is the flag's fault: name the flag.
        for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
            // The flag is at fault when the bad value lies inside what it set,
            // or contains it (setting camera.fovY.x turned fovY into an object).
            auto within = [](const std::string& inner, const std::string& outer) {
                return inner == outer ||
                       (inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
                        (inner[outer.size()] == '.' || inner[outer.size()] == '['));
            };
            if (within(path, it->path) || within(it->path, path))
                throw Error(text::escapeControl(it->flag + ": " + path + ": " + message));
        }
        // Keys, values and file names are quoted as written: escape them so
        // the message stays on one line.
        throw Error(text::escapeControl(source + ": " + (path.empty() ? "" : path + ": ") + message));
    }
};

class Reader {
public:
    Reader(const ParseContext& ctx, const json& value, std::string path)
        : ctx_(ctx), value_(value), path_(std::move(path)) {}

    const json& value() const { return value_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const { ctx_.fail(path_, message); }

    Reader child(const std::string& key) const {
        return Reader(ctx_, value_.at(key), path_.empty() ? key : path_ + "." + key);
    }
    Reader element(std::size_t i) const { return Reader(ctx_, value_.at(i), path_ + "[" + std::to_string(i) + "]"); }

    void requireObject() const { if (!value_.is_object()) fail(std::string("expected an object, got ") + typeName(value_)); }
    void requireArray() const { if (!value_.is_array()) fail(std::string("expected an array, got ") + typeName(value_)); }

    // Errors for keys that are not in `known`.
    void checkKeys(std::initializer_list<const char*> known) const { checkKeys(std::vector<const char*>(known)); }
    void checkKeys(const std::vector<const char*>& known) const {
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
    bool has(const std::string& key) const { return value_.contains(key); }

    float number() const { return static_cast<float>(real()); }
    /// The same checks as number() (finite, within a float's range), kept in double.
    double real() const {
        if (!value_.is_number()) fail(std::string("expected a number, got ") + typeName(value_));
        const double d = value_.get<double>();
        if (!std::isfinite(d) || std::fabs(d) > 3.0e38) fail("expected a finite number");
        return d;
    }
    int integer() const {
        if (!value_.is_number_integer()) fail(std::string("expected an integer, got ") + typeName(value_));
        // Unsigned values past 2^63 would wrap to negative as long long.
        if (value_.is_number_unsigned() && value_.get<unsigned long long>() > 1000000000ULL)
            fail("integer out of range, got " + std::to_string(value_.get<unsigned long long>()));
        const auto v = value_.get<long long>();
        if (v < -1000000000LL || v > 1000000000LL) fail("integer out of range, got " + std::to_string(v));
        return static_cast<int>(v);
    }
    bool boolean() const {
        if (!value_.is_boolean()) fail(std::string("expected true or false, got ") + typeName(value_));
        return value_.get<bool>();
    }
    std::string string() const {
        if (!value_.is_string()) fail(std::string("expected a string, got ") + typeName(value_));
        return value_.get<std::string>();
    }
    glm::vec3 vec3() const {
        if (!value_.is_array()) fail(std::string("expected 3 numbers, got ") + typeName(value_));
        if (value_.size() != 3) fail("expected 3 numbers, got " + std::to_string(value_.size()));
        return {element(0).number(), element(1).number(), element(2).number()};
    }

    // Optional members with defaults and checks.
    float number(const std::string& key, float def) const { return has(key) ? child(key).number() : def; }
    float positive(const std::string& key, float def) const {
        if (!has(key)) return def;
        const float v = child(key).number();
        if (!(v > 0.0f)) child(key).fail("expected a number > 0, got " + fmt(v));
        return v;
    }
    float nonNegative(const std::string& key, float def) const {
        if (!has(key)) return def;
        const float v = child(key).number();
        if (v < 0.0f) child(key).fail("expected a number >= 0, got " + fmt(v));
        return v;
    }
    int integer(const std::string& key, int def, int minimum, int maximum) const {
        if (!has(key)) return def;
        const int v = child(key).integer();
        if (v < minimum || v > maximum)
            child(key).fail("expected an integer in " + std::to_string(minimum) + ".." + std::to_string(maximum) + ", got " +
                            std::to_string(v));
        return v;
    }
    glm::vec3 vec3(const std::string& key, glm::vec3 def) const { return has(key) ? child(key).vec3() : def; }
    glm::vec3 color(const std::string& key, glm::vec3 def) const {
        if (!has(key)) return def;
        const glm::vec3 c = child(key).vec3();
        if (c.x < 0 || c.y < 0 || c.z < 0) child(key).fail("expected 3 numbers >= 0 (linear RGB)");
        return c;
    }
    glm::vec3 direction(const std::string& key, glm::vec3 def) const {
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
    std::string string(const std::string& key, const std::string& def) const { return has(key) ? child(key).string() : def; }
    bool boolean(const std::string& key, bool def) const { return has(key) ? child(key).boolean() : def; }

    const ParseContext& context() const { return ctx_; }

    static std::string fmt(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }

private:
    const ParseContext& ctx_;
    const json& value_;
    std::string path_;
};

// --- Scene parts --------------------------------------------------------------

// Keyframes, shared by `lights[i].path` and `camera.path`: `times` (seconds,
// at least one, strictly increasing) and, under `key`, one [x, y, z] per
// time, each called `what` in messages.
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

// Why a camera at `position` looking at `target` with `up` has no view
// direction, or "" when it has one.
std::string viewProblem(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 forward = target - position;
    if (!std::isfinite(glm::length(forward))) return "camera position and target are too far apart (their distance overflows a float)";
    if (glm::length(forward) < 1e-9f) return "camera position and target coincide";
    if (glm::length(glm::cross(glm::normalize(forward), up)) < 1e-6f) return "camera up is parallel to the view direction";
    return "";
}

// The distance from the origin to the segment [a, b], in double.
double closestToOrigin(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = b - a;
    const double dd = glm::dot(d, d);
    const double s = dd > 0.0 ? std::clamp(-glm::dot(a, d) / dd, 0.0, 1.0) : 0.0;
    return glm::length(a + s * d);
}

// `camera.path`: the eye and target moving along keyframes (CameraPath in
// Scene.h). Every key, and every point between two keys, must give the
// camera a view direction, as a static camera's position and target must.
CameraPath readCameraPath(const Reader& r, const glm::vec3& up) {
    r.requireObject();
    if (!r.has("type")) r.fail("missing key 'type' (keyframes)");
    const std::string type = r.child("type").string();
    if (type != "keyframes") r.child("type").fail("unknown path type '" + type + "' (a camera path has keyframes only)");
    r.checkKeys({"type", "times", "positions", "targets", "loop"});
    CameraPath path;
    path.times = readKeyTimes(r);
    path.positions = readKeyPoints(r, "positions", "position", path.times.size());
    path.targets = readKeyPoints(r, "targets", "target", path.times.size());
    path.loop = r.boolean("loop", path.loop);
    const Reader targets = r.child("targets");
    for (std::size_t i = 0; i < path.times.size(); ++i) {
        const std::string problem = viewProblem(path.positions[i], path.targets[i], up);
        if (!problem.empty()) targets.element(i).fail("key " + std::to_string(i) + ": " + problem);
    }
    // Between keys the view direction is the linear blend of the keys' own
    // (eye and target move linearly): it vanishes where that blend passes
    // the origin, and turns parallel to up where its cross product with up
    // does. That is measured against the longer key's length (|blend| is at
    // most that), so it is never looser than the per-key check above.
    for (std::size_t i = 1; i < path.times.size(); ++i) {
        const glm::dvec3 a(path.targets[i - 1] - path.positions[i - 1]), b(path.targets[i] - path.positions[i]), u(up);
        const double longer = std::max(glm::length(a), glm::length(b));
        const std::string between = "between keys " + std::to_string(i - 1) + " and " + std::to_string(i) + " the camera ";
        if (closestToOrigin(a, b) < 1e-9)
            targets.element(i).fail(between + "passes through its target (add a key in between)");
        if (closestToOrigin(glm::cross(a, u), glm::cross(b, u)) < 1e-6 * longer)
            targets.element(i).fail(between + "looks along camera up (add a key in between, or change up)");
    }
    return path;
}

void readCamera(const Reader& r, Camera& cam) {
    r.checkKeys({"position", "target", "up", "fovY", "near", "far", "path"});
    cam.position = r.vec3("position", cam.position);
    cam.target = r.vec3("target", cam.target);
    cam.up = r.direction("up", cam.up);
    cam.fovYDeg = r.positive("fovY", cam.fovYDeg);
    if (cam.fovYDeg >= 180.0f) r.child("fovY").fail("expected degrees in (0, 180), got " + Reader::fmt(cam.fovYDeg));
    cam.nearPlane = r.positive("near", cam.nearPlane);
    cam.farPlane = r.positive("far", cam.farPlane);
    if (cam.farPlane <= cam.nearPlane)
        (r.has("far") ? r.child("far") : r).fail("expected far > near (" + Reader::fmt(cam.nearPlane) + ")");
    if (const std::string problem = viewProblem(cam.position, cam.target, cam.up); !problem.empty()) r.fail(problem);
    if (r.has("path")) cam.path = readCameraPath(r.child("path"), cam.up);
}

std::string techniqueList() {
    std::string list;
    for (const TechniqueInfo& t : techniques()) list += (list.empty() ? "" : ", ") + t.name;
    return list;
}

// One technique's block, `lights[i].shadow.<name>`, read through its options
// table: every key known, every value of its kind and within its range.
std::any readOptions(const Reader& r, const OptionTable& table) {
    r.requireObject();
    if (table.fields.empty() && !r.value().empty())
        r.child(r.value().begin().key()).fail("unknown key (technique '" + table.block + "' has no options)");
    std::vector<const char*> keys;
    for (const OptionField& f : table.fields) keys.push_back(f.key.c_str());
    r.checkKeys(keys);
    std::any options = table.makeDefault();
    for (const OptionField& f : table.fields) {
        if (!r.has(f.key)) continue;
        const Reader v = r.child(f.key);
        const std::string allowed = OptionTable::rangeText(f);
        switch (f.kind) {
        case OptionKind::Number: {
            // Compared as the float the member stores, so that the range's own ends (0.1) are allowed.
            const float x = v.number();
            if (x < static_cast<float>(f.minimum) || x > static_cast<float>(f.maximum)) v.fail("expected a number in " + allowed + ", got " + Reader::fmt(static_cast<float>(x)));
            f.set(options, x);
            break;
        }
        case OptionKind::Integer: {
            const int x = v.integer();
            if (x < f.minimum || x > f.maximum) v.fail("expected an integer in " + allowed + ", got " + std::to_string(x));
            f.set(options, x);
            break;
        }
        case OptionKind::Boolean: f.set(options, v.boolean() ? 1.0 : 0.0); break;
        case OptionKind::Choice: {
            const std::string name = v.string();
            const auto it = std::find(f.choices.begin(), f.choices.end(), name);
            if (it == f.choices.end()) v.fail("expected one of " + allowed + ", got \"" + name + "\"");
            f.set(options, static_cast<double>(it - f.choices.begin()));
            break;
        }
        case OptionKind::Text: f.setText(options, v.string()); break;
        }
    }
    return options;
}

void readShadow(const Reader& r, ShadowSettings& shadow, const Light& light) {
    std::vector<const char*> keys{"technique"};
    const std::vector<TechniqueInfo> all = techniques();
    for (const TechniqueInfo& t : all) keys.push_back(t.name.c_str());
    r.checkKeys(keys);
    if (r.has("technique")) {
        const Reader t = r.child("technique");
        shadow.technique = t.string();
        if (!findTechnique(shadow.technique))
            t.fail("unknown technique '" + shadow.technique + "' (expected one of: " + techniqueList() + ")");
    }
    // Every block is read and checked, the chosen technique's or not, so a
    // scene can carry several and switch between them.
    for (const TechniqueInfo& t : all)
        if (r.has(t.name)) shadow.options[t.name] = readOptions(r.child(t.name), *t.options);
    // Whether the technique can shadow this light may depend on its options
    // (a preset), so this comes after the blocks.
    const std::string reason = unsupportedReason(shadow.technique, light);
    if (!reason.empty()) (r.has("technique") ? r.child("technique") : r).fail(reason);
}

// `lights[i].path`: how a spot or point light moves (LightPath in Scene.h).
LightPath readPath(const Reader& r, const glm::vec3& base) {
    r.requireObject();
    if (!r.has("type")) r.fail("missing key 'type' (sine or keyframes)");
    const std::string type = r.child("type").string();
    LightPath path;
    // Every position the path reaches must be a finite float, as a static light's is.
    const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (type == "sine") {
        r.checkKeys({"type", "amplitude", "angularFrequency", "phase"});
        path.type = LightPath::Type::Sine;
        path.amplitude = r.vec3("amplitude", path.amplitude);
        if (!finite(base + path.amplitude) || !finite(base - path.amplitude))
            r.child("amplitude").fail("position + amplitude overflows a float");
        if (r.has("angularFrequency")) {
            const Reader w = r.child("angularFrequency");
            path.angularFrequency = w.real();
            if (path.angularFrequency < 0.0)
                w.fail("expected radians per second >= 0, got " + Reader::fmt(path.angularFrequency) +
                       " (reverse the motion with a negative amplitude or a phase)");
        }
        if (r.has("phase")) path.phase = r.child("phase").real();
        return path;
    }
    if (type == "keyframes") {
        r.checkKeys({"type", "times", "positions", "loop"});
        path.type = LightPath::Type::Keyframes;
        path.times = readKeyTimes(r);
        path.positions = readKeyPoints(r, "positions", "position", path.times.size());
        path.loop = r.boolean("loop", path.loop);
        return path;
    }
    r.child("type").fail("unknown path type '" + type + "' (expected sine or keyframes)");
}

Light readLight(const Reader& r) {
    r.checkKeys({"name", "type", "color", "intensity", "position", "direction", "range", "innerCone", "outerCone",
                 "size", "projector", "path", "shadow"});
    Light light;
    if (!r.has("type")) r.fail("missing key 'type' (directional, spot or point)");
    const std::string type = r.child("type").string();
    if (type == "directional") light.type = LightType::Directional;
    else if (type == "spot") light.type = LightType::Spot;
    else if (type == "point") light.type = LightType::Point;
    else r.child("type").fail("expected directional, spot or point, got '" + type + "'");
    light.name = r.string("name", type);
    light.color = r.color("color", light.color);
    light.intensity = r.nonNegative("intensity", light.intensity);
    const bool positional = light.type != LightType::Directional;
    if (positional && !r.has("position")) r.fail("missing key 'position' (a " + type + " light needs one)");
    if (!positional && r.has("position")) r.child("position").fail("a directional light has no position (use direction)");
    light.position = r.vec3("position", light.position);
    if (light.type == LightType::Point && r.has("direction")) r.child("direction").fail("a point light has no direction");
    light.direction = r.direction("direction", light.direction);
    light.range = r.nonNegative("range", light.range);
    if (light.type != LightType::Spot && (r.has("innerCone") || r.has("outerCone")))
        r.child(r.has("innerCone") ? "innerCone" : "outerCone").fail("only spot lights have cone angles");
    light.innerConeDeg = r.nonNegative("innerCone", light.innerConeDeg);
    light.outerConeDeg = r.positive("outerCone", light.outerConeDeg);
    if (light.outerConeDeg >= 90.0f) r.child("outerCone").fail("expected degrees in (0, 90), got " + Reader::fmt(light.outerConeDeg));
    if (light.innerConeDeg > light.outerConeDeg)
        (r.has("innerCone") ? r.child("innerCone") : r).fail("expected innerCone <= outerCone (" + Reader::fmt(light.outerConeDeg) + ")");
    light.size = r.nonNegative("size", light.size);
    if (light.type == LightType::Directional && light.size >= 90.0f)
        r.child("size").fail("expected an angular diameter in degrees < 90, got " + Reader::fmt(light.size));
    if (r.has("projector") && light.type != LightType::Spot) r.child("projector").fail("only spot lights project an image");
    if (r.has("path")) {
        if (!positional) r.child("path").fail("a directional light has no position to move (only spot and point lights have a path)");
        light.path = readPath(r.child("path"), light.position);
    }
    if (r.has("shadow")) readShadow(r.child("shadow"), light.shadow, light);
    return light;
}

ImageRGBA8 loadTexture(const Reader& r, const fs::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (!fs::exists(status)) r.fail("texture file not found: " + name);
    if (!fs::is_regular_file(status)) r.fail("texture " + name + " is not a regular file");
    int w = 0, h = 0, channels = 0;
    // The header first: a small PNG may declare a size that cannot be allocated.
    if (stbi_info(name.c_str(), &w, &h, &channels) &&
        (w > kMaxImageSide || h > kMaxImageSide || static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > kMaxImagePixels))
        r.fail(name + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " + std::to_string(kMaxImageSide) +
               " pixels per side and " + std::to_string(kMaxImagePixels) + " pixels");
    stbi_uc* data = stbi_load(name.c_str(), &w, &h, &channels, 4);
    if (!data) r.fail(name + ": not a readable image (" + std::string(stbi_failure_reason()) + ")");
    ImageRGBA8 image{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 4)};
    stbi_image_free(data);
    return image;
}

class SceneBuilder {
public:
    SceneBuilder(Scene& scene, const ParseContext& ctx) : scene_(scene), ctx_(ctx) {}

    void readMaterials(const Reader& r) {
        r.requireObject();
        for (const auto& [name, _] : r.value().items()) {
            const Reader m = r.child(name);
            m.checkKeys({"baseColor", "baseColorTexture", "ambient", "diffuse", "specular", "shininess", "alpha", "alphaMode", "alphaCutoff"});
            Material mat;
            mat.name = name;
            mat.baseColor = m.color("baseColor", mat.baseColor);
            mat.ambient = m.color("ambient", mat.ambient);
            mat.diffuse = m.color("diffuse", mat.diffuse);
            mat.specular = m.color("specular", mat.specular);
            mat.shininess = m.positive("shininess", mat.shininess);
            for (const auto& [key, field] : {std::pair<const char*, float*>{"alpha", &mat.alpha}, {"alphaCutoff", &mat.alphaCutoff}})
                if (m.has(key)) {
                    const float v = m.child(key).number();
                    if (!(v >= 0.0f && v <= 1.0f)) m.child(key).fail("expected a number in 0..1, got " + Reader::fmt(v));
                    *field = v;
                }
            if (m.has("alphaMode")) {
                const Reader a = m.child("alphaMode");
                const std::string mode = a.string();
                if (mode == "opaque") mat.alphaMode = AlphaMode::Opaque;
                else if (mode == "mask") mat.alphaMode = AlphaMode::Mask;
                else if (mode == "blend") mat.alphaMode = AlphaMode::Blend;
                else a.fail("expected \"opaque\", \"mask\" or \"blend\", got \"" + text::escapeControl(mode) + "\"");
            }
            if (m.has("baseColorTexture")) {
                const Reader t = m.child("baseColorTexture");
                scene_.textures.push_back(loadTexture(t, ctx_.baseDir / t.string()));
                scene_.textureSources.push_back(ctx_.source + ": " + t.path() + " (" + (ctx_.baseDir / t.string()).string() + ")");
                mat.baseColorTexture = static_cast<int>(scene_.textures.size()) - 1;
            }
            materialIndex_[name] = static_cast<int>(scene_.materials.size());
            scene_.materials.push_back(std::move(mat));
        }
    }

    void readNodes(const Reader& r, int parent) {
        r.requireArray();
        for (std::size_t i = 0; i < r.value().size(); ++i) readNode(r.element(i), parent);
    }

private:
    int material(const Reader& r) const {
        const std::string name = r.string();
        const auto it = materialIndex_.find(name);
        if (it == materialIndex_.end()) {
            std::string list;
            for (const auto& [n, _] : materialIndex_) list += (list.empty() ? "" : ", ") + n;
            r.fail("unknown material '" + name + "' (defined: " + (list.empty() ? "none" : list) + ")");
        }
        return it->second;
    }

    Mesh shape(const Reader& r) const {
        r.requireObject();
        if (!r.has("type")) r.fail("missing key 'type' (plane, box, sphere, torus, cylinder, cone or pyramid)");
        const std::string type = r.child("type").string();
        // Segment counts stop at kMaxSegments: enough for any smooth shape, and
        // a typo like 1000000000 cannot exhaust memory.
        constexpr int kMaxSegments = 1024;
        // Parameters are validated here with their JSON paths; the shape
        // functions' own checks (segment minimums) then cannot fire, but if
        // one does its message is attached to this shape's path.
        auto build = [&](auto&& make) -> Mesh {
            try {
                return make();
            } catch (const Error& e) {
                r.fail(e.what());
            }
        };
        if (type == "plane") {
            r.checkKeys({"type", "size"});
            const glm::vec2 s = r.has("size") ? sizeOf2(r.child("size")) : glm::vec2(10.0f);
            return build([&] { return shapes::plane(s.x, s.y); });
        }
        if (type == "box") {
            r.checkKeys({"type", "size"});
            const glm::vec3 s = r.vec3("size", glm::vec3(1.0f));
            if (s.x <= 0 || s.y <= 0 || s.z <= 0) r.child("size").fail("expected 3 numbers > 0");
            return build([&] { return shapes::box(s); });
        }
        if (type == "sphere") {
            r.checkKeys({"type", "radius", "segments", "rings"});
            const float radius = r.positive("radius", 1.0f);
            const int segments = r.integer("segments", 48, 3, kMaxSegments), rings = r.integer("rings", 24, 2, kMaxSegments);
            return build([&] { return shapes::sphere(radius, segments, rings); });
        }
        if (type == "torus") {
            r.checkKeys({"type", "majorRadius", "minorRadius", "majorSegments", "minorSegments"});
            const float major = r.positive("majorRadius", 1.0f), minor = r.positive("minorRadius", 0.3f);
            if (minor >= major) r.fail("expected minorRadius < majorRadius");
            const int majorSegments = r.integer("majorSegments", 64, 3, kMaxSegments), minorSegments = r.integer("minorSegments", 32, 3, kMaxSegments);
            return build([&] { return shapes::torus(major, minor, majorSegments, minorSegments); });
        }
        if (type == "cylinder" || type == "cone") {
            r.checkKeys({"type", "radius", "height", "segments"});
            const float radius = r.positive("radius", 0.5f), height = r.positive("height", 1.0f);
            const int segments = r.integer("segments", 48, 3, kMaxSegments);
            return build([&] {
                return type == "cylinder" ? shapes::cylinder(radius, height, segments) : shapes::cone(radius, height, segments);
            });
        }
        if (type == "disc") {
            r.checkKeys({"type", "radius", "segments"});
            const float radius = r.positive("radius", 0.5f);
            const int segments = r.integer("segments", 128, 3, kMaxSegments);
            return build([&] { return shapes::disc(radius, segments); });
        }
        if (type == "pyramid") {
            r.checkKeys({"type", "baseWidth", "height"});
            const float width = r.positive("baseWidth", 1.0f), height = r.positive("height", 1.0f);
            return build([&] { return shapes::pyramid(width, height); });
        }
        r.child("type").fail("unknown shape '" + type + "' (expected plane, disc, box, sphere, torus, cylinder, cone or pyramid)");
    }

    static glm::vec2 sizeOf2(const Reader& r) {
        if (!r.value().is_array() || r.value().size() != 2)
            r.fail(std::string("expected 2 numbers [width, depth], got ") +
                   (r.value().is_array() ? std::to_string(r.value().size()) : typeName(r.value())));
        const glm::vec2 s(r.element(0).number(), r.element(1).number());
        if (s.x <= 0 || s.y <= 0) r.fail("expected 2 numbers > 0");
        return s;
    }

    void readNode(const Reader& r, int parent) {
        r.checkKeys({"name", "shape", "mesh", "material", "translation", "rotation", "scale", "castsShadows",
                     "receivesShadows", "children"});
        if (r.has("shape") && r.has("mesh")) r.fail("a node has either 'shape' or 'mesh', not both");
        Node node;
        node.parent = parent;
        node.name = r.string("name", "");
        node.translation = r.vec3("translation", node.translation);
        if (r.has("rotation")) {
            // Euler angles in degrees, applied about X, then Y, then Z.
            const glm::vec3 deg = r.child("rotation").vec3();
            node.rotation = glm::angleAxis(glm::radians(deg.z), glm::vec3(0, 0, 1)) *
                            glm::angleAxis(glm::radians(deg.y), glm::vec3(0, 1, 0)) *
                            glm::angleAxis(glm::radians(deg.x), glm::vec3(1, 0, 0));
        }
        if (r.has("scale")) {
            const Reader s = r.child("scale");
            node.scale = s.value().is_number() ? glm::vec3(s.number()) : s.vec3();
            if (node.scale.x <= 0 || node.scale.y <= 0 || node.scale.z <= 0)
                s.fail("expected a number > 0 or 3 numbers > 0");
        }
        node.castsShadows = r.boolean("castsShadows", true);
        node.receivesShadows = r.boolean("receivesShadows", true);
        const int materialOverride = r.has("material") ? material(r.child("material")) : -1;
        node.material = materialOverride;
        if (r.has("shape")) {
            Mesh mesh = shape(r.child("shape"));
            mesh.name = node.name.empty() ? r.child("shape").child("type").string() : node.name;
            node.mesh = addMesh(std::move(mesh));
        }
        const int index = static_cast<int>(scene_.nodes.size());
        scene_.nodes.push_back(node);
        nodeSources_.push_back(r.path());
        if (r.has("mesh")) importMesh(r.child("mesh"), index, materialOverride, node);
        if (r.has("children")) readNodes(r.child("children"), index);
    }

    int addMesh(Mesh mesh) {
        scene_.meshes.push_back(std::move(mesh));
        return static_cast<int>(scene_.meshes.size()) - 1;
    }

    void importMesh(const Reader& r, int parent, int materialOverride, const Node& owner) {
        const fs::path file = ctx_.baseDir / r.string();
        ImportedModel model;
        try {
            model = loadMeshFile(file);
        } catch (const Error& e) {
            r.fail(e.what());
        }
        const int meshBase = static_cast<int>(scene_.meshes.size());
        const int textureBase = static_cast<int>(scene_.textures.size());
        const int materialBase = static_cast<int>(scene_.materials.size());
        for (Mesh& m : model.meshes) scene_.meshes.push_back(std::move(m));
        for (ImageRGBA8& t : model.textures) scene_.textures.push_back(std::move(t));
        for (std::size_t t = 0; t < model.textures.size(); ++t)
            scene_.textureSources.push_back(ctx_.source + ": " + r.path() + ": " + file.string() + ": " +
                                            (t < model.textureSources.size() ? model.textureSources[t] : "texture " + std::to_string(t)));
        for (Material m : model.materials) {
            if (m.baseColorTexture >= 0) m.baseColorTexture += textureBase;
            scene_.materials.push_back(std::move(m));
        }
        std::vector<int> sceneIndex(model.nodes.size());
        for (std::size_t i = 0; i < model.nodes.size(); ++i) {
            const ImportedModel::Node& in = model.nodes[i];
            Node node;
            node.name = in.name;
            node.parent = in.parent >= 0 ? sceneIndex[static_cast<std::size_t>(in.parent)] : parent;
            node.translation = in.translation;
            node.rotation = in.rotation;
            node.scale = in.scale;
            node.castsShadows = owner.castsShadows;
            node.receivesShadows = owner.receivesShadows;
            sceneIndex[i] = static_cast<int>(scene_.nodes.size());
            scene_.nodes.push_back(node);
            const std::string source = r.path() + " (" + file.string() + ": node '" + in.name + "')";
            nodeSources_.push_back(source);
            // One child node per primitive: a node draws one mesh with one material.
            for (const auto& prim : in.primitives) {
                Node p;
                p.name = in.name;
                p.parent = sceneIndex[i];
                p.mesh = meshBase + prim.mesh;
                p.material = materialOverride >= 0 ? materialOverride : (prim.material >= 0 ? materialBase + prim.material : -1);
                p.castsShadows = owner.castsShadows;
                p.receivesShadows = owner.receivesShadows;
                scene_.nodes.push_back(p);
                nodeSources_.push_back(source);
            }
        }
    }

public:
    /// Every world transform and every transformed vertex must be finite:
    /// translations near 3e38 in a parent and a child, or a large scale on a
    /// large mesh, overflow only once composed.
    void checkFinite() const {
        const auto finite = [](const glm::vec4& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w); };
        for (const DrawItem& item : scene_.drawItems()) {
            const std::string& where = nodeSources_[static_cast<std::size_t>(item.node)];
            for (int c = 0; c < 4; ++c)
                if (!finite(item.worldFromObject[c])) ctx_.fail(where, "world transform is not finite (values overflow a float)");
            for (const glm::vec3& p : scene_.meshes[static_cast<std::size_t>(item.mesh)].positions)
                if (!finite(item.worldFromObject * glm::vec4(p, 1.0f)))
                    ctx_.fail(where, "a vertex's world position is not finite (values overflow a float)");
        }
    }

private:
    Scene& scene_;
    const ParseContext& ctx_;
    std::map<std::string, int> materialIndex_;
    std::vector<std::string> nodeSources_; ///< JSON path (and mesh file node) per scene_.nodes entry
};

/// Every string and key must be valid UTF-8 (results.json and the messages
/// are UTF-8); walked with an explicit stack, depth is bounded anyway.
void checkUtf8(const ParseContext& ctx, const json& doc) {
    std::vector<std::pair<const json*, std::string>> stack{{&doc, ""}};
    const auto join = [](const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; };
    while (!stack.empty()) {
        auto [node, path] = std::move(stack.back());
        stack.pop_back();
        if (node->is_string()) {
            if (text::invalidUtf8At(node->get_ref<const std::string&>()) != std::string::npos)
                ctx.fail(path, "invalid UTF-8 in the string '" + node->get<std::string>() + "'");
        } else if (node->is_object()) {
            for (const auto& [key, value] : node->items()) {
                if (text::invalidUtf8At(key) != std::string::npos) ctx.fail(join(path, key), "invalid UTF-8 in this key");
                stack.emplace_back(&value, join(path, key));
            }
        } else if (node->is_array()) {
            for (std::size_t i = 0; i < node->size(); ++i) stack.emplace_back(&(*node)[i], path + "[" + std::to_string(i) + "]");
        }
    }
}

} // namespace

Scene parseScene(const std::string& jsonText, const std::string& sourceName, const fs::path& baseDir,
                 const std::vector<std::string>& overrides) {
    ParseContext ctx{sourceName, baseDir, {}};
    // nlohmann::json copies and destroys recursively: refuse deep nesting first.
    if (text::jsonDepth(jsonText) > text::kMaxJsonDepth)
        throw Error(text::escapeControl(sourceName + ": JSON nested deeper than " + std::to_string(text::kMaxJsonDepth) + " levels"));
    json doc;
    try {
        doc = json::parse(jsonText);
    } catch (const json::exception& e) {
        // nlohmann's messages start with "[json.exception.parse_error.101] ";
        // a number too large for a double (1e999) is out_of_range.406.
        std::string what = e.what();
        const auto pos = what.find("] ");
        what = pos == std::string::npos ? what : what.substr(pos + 2);
        if (e.id == 406) what += " (numbers must be finite)";
        throw Error(text::escapeControl(sourceName + ": invalid JSON: " + what));
    }
    if (!doc.is_object()) throw Error(sourceName + ": expected a JSON object at the top level, got " + typeName(doc));
    try {
        ctx.overrides = applyOverrides(doc, overrides);
    } catch (const Error& e) {
        throw Error(text::escapeControl(e.what())); // the flag quotes the user's text
    }
    checkUtf8(ctx, doc);

    const Reader root(ctx, doc, "");
    root.checkKeys({"name", "camera", "ambient", "background", "materials", "lights", "nodes"});
    Scene scene;
    scene.name = root.string("name", fs::path(sourceName).stem().string());
    if (root.has("camera")) readCamera(root.child("camera"), scene.camera);
    scene.ambient = root.color("ambient", scene.ambient);
    scene.background = root.color("background", scene.background);
    SceneBuilder builder(scene, ctx);
    if (root.has("materials")) builder.readMaterials(root.child("materials"));
    if (root.has("lights")) {
        const Reader lights = root.child("lights");
        lights.requireArray();
        if (lights.value().size() > kMaxLights)
            lights.fail("expected at most " + std::to_string(kMaxLights) + " lights, got " + std::to_string(lights.value().size()) +
                        " (render time grows with every light)");
        for (std::size_t i = 0; i < lights.value().size(); ++i) {
            const Reader l = lights.element(i);
            l.requireObject();
            scene.lights.push_back(readLight(l));
            if (l.has("projector")) {  // the slide: an image file, relative to the scene
                const Reader t = l.child("projector");
                scene.textures.push_back(loadTexture(t, baseDir / t.string()));
                scene.textureSources.push_back(ctx.source + ": " + t.path() + " (" + (baseDir / t.string()).string() + ")");
                scene.lights.back().projectorTexture = static_cast<int>(scene.textures.size()) - 1;
            }
        }
    }
    if (root.has("nodes")) builder.readNodes(root.child("nodes"), -1);
    builder.checkFinite();
    return scene;
}

Scene loadSceneFile(const fs::path& path, const std::vector<std::string>& overrides) {
    const std::string name = path.string();
    if (!fs::exists(path)) throw Error(name + ": file not found");
    if (!fs::is_regular_file(path)) throw Error(name + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(name + ": cannot open for reading");
    std::stringstream text;
    text << in.rdbuf();
    return parseScene(text.str(), name, path.parent_path(), overrides);
}

std::string sceneJsonWithOverrides(const std::string& jsonText, const std::string& sourceName, const std::vector<std::string>& overrides) {
    // Checked the way a load checks it first (and the result loads again).
    parseScene(jsonText, sourceName, fs::current_path(), overrides);
    json doc = json::parse(jsonText);
    applyOverrides(doc, overrides);
    return doc.dump(2) + "\n";
}

const std::string& defaultSceneJson() {
    // The lecture's first scene: a torus floating above a ground plane under
    // a directional light, seen from above and to the side.
    static const std::string text = R"({
  "name": "default",
  "camera": { "position": [4.5, 4.0, 6.5], "target": [0, 0.6, 0], "fovY": 45 },
  "ambient": [0.15, 0.15, 0.15],
  "materials": {
    "ground": { "baseColor": [0.55, 0.55, 0.52] },
    "gold": { "baseColor": [0.85, 0.62, 0.2], "specular": [0.6, 0.55, 0.4], "shininess": 48 }
  },
  "lights": [
    { "name": "sun", "type": "directional", "direction": [-0.4, -1.0, -0.3], "intensity": 1.0 }
  ],
  "nodes": [
    { "name": "ground", "shape": { "type": "plane", "size": [12, 12] }, "material": "ground" },
    { "name": "torus", "shape": { "type": "torus", "majorRadius": 1.0, "minorRadius": 0.35 },
      "material": "gold", "translation": [0, 1.4, 0], "rotation": [25, 0, 0] }
  ]
})";
    return text;
}

Scene defaultScene(const std::vector<std::string>& overrides) {
    return parseScene(defaultSceneJson(), "<default scene>", fs::current_path(), overrides);
}

} // namespace shadowlab
