// A glTF file as a whole scene (GltfScene.h): its lights, cameras and
// bounds from its JSON (glTF 2.0 and KHR_lights_punctual), the meshes left
// to the mesh loader.
#include "scene/GltfScene.h"

#include "scene/MeshFile.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace meshfile;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::uint32_t littleEndian32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<std::uint8_t>(bytes[at + static_cast<std::size_t>(k)]);
    return v;
}

// What a glTF file says of its scene: the nodes' world matrices in walk
// order, the cameras and lights they place, the meshes' bounds.
class GltfSceneReader {
public:
    GltfSceneReader(std::string file, json doc) : file_(std::move(file)), doc_(std::move(doc)) {}

    json document(const fs::path& path, const GltfSceneOptions& options, std::vector<std::string>& notes) {
        dir_ = fs::absolute(path).parent_path();
        walk();
        json scene = json::object();
        scene["name"] = path.stem().string();
        scene["nodes"] = json::array({json{{"name", path.filename().string()}, {"mesh", fs::absolute(path).string()}}});
        scene["lights"] = lights(notes, options.defaults);
        scene["camera"] = camera(options.camera, notes, options.defaults);
        // A file shadowlab wrote (GltfExport.h): the scene's own keys.
        const json& own = shadowlabExtras(doc_, "extras.shadowlab");
        for (const char* key : {"name", "ambient", "background", "shadowAtlas"})
            if (own.contains(key)) scene[key] = own[key];
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& at, const std::string& what) const { throw Error(text::escapeControl(file_ + ": " + at + ": " + what)); }

    const json& array(const json& parent, const char* key) const {
        static const json empty = json::array();
        const auto it = parent.find(key);
        return it != parent.end() && it->is_array() ? *it : empty;
    }

    double number(const json& object, const char* key, double fallback, const std::string& at) const {
        const auto it = object.find(key);
        if (it == object.end()) return fallback;
        if (!it->is_number() || !std::isfinite(it->get<double>())) fail(at + "." + key, "expected a finite number");
        return it->get<double>();
    }

    // The file's KHR_lights_punctual lights (none when it has no such extension).
    json punctualLights() const {
        const json ext = doc_.value("extensions", json::object());
        if (!ext.is_object()) return json::array();
        const json lights = ext.value("KHR_lights_punctual", json::object());
        return lights.is_object() ? lights.value("lights", json::array()) : json::array();
    }

    // `object`'s extras.shadowlab (GltfExport.h): an object of scene-file
    // keys, or an empty object when there is none.
    const json& shadowlabExtras(const json& object, const std::string& at) const {
        static const json none = json::object();
        const auto extras = object.find("extras");
        if (extras == object.end() || !extras->is_object()) return none;
        const auto own = extras->find("shadowlab");
        if (own == extras->end()) return none;
        if (!own->is_object()) fail(at, "expected an object of scene-file keys");
        return *own;
    }

    // extras.shadowlab's `key` as a finite vector, if it is one.
    static std::optional<glm::dvec3> vectorOf(const json& own, const char* key) {
        const auto v = own.find(key);
        if (v == own.end() || !v->is_array() || v->size() != 3 || !std::all_of(v->begin(), v->end(), [](const json& x) { return x.is_number(); }))
            return std::nullopt;
        const glm::dvec3 out((*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>());
        return std::isfinite(out.x + out.y + out.z) ? std::optional(out) : std::nullopt;
    }
    // Whether unit vector `a` is along unit vector `b`, to float precision.
    static bool along(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a) > 0.0 && glm::length(glm::normalize(a) - b) <= 1e-5; }
    // Whether point `a` is at `b`, to float precision.
    static bool closeTo(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) <= 1e-5 * std::max(1.0, glm::length(b)); }

    int index(const json& value, std::size_t count, const std::string& at, const char* what) const {
        if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() >= static_cast<long long>(count))
            fail(at, value.dump() + " is not one of the file's " + std::to_string(count) + " " + what);
        return value.get<int>();
    }

    glm::dmat4 local(const json& node) const {
        if (const auto m = node.find("matrix"); m != node.end() && m->is_array() && m->size() == 16) {
            glm::dmat4 out(1.0);
            for (int k = 0; k < 16; ++k) out[k / 4][k % 4] = (*m)[static_cast<std::size_t>(k)].get<double>();
            return out;
        }
        glm::dvec3 t(0.0), s(1.0);
        glm::dquat r(1.0, 0.0, 0.0, 0.0);
        if (const auto v = node.find("translation"); v != node.end() && v->size() == 3) t = {(*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>()};
        if (const auto v = node.find("scale"); v != node.end() && v->size() == 3) s = {(*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>()};
        if (const auto v = node.find("rotation"); v != node.end() && v->size() == 4)
            r = glm::dquat((*v)[3].get<double>(), (*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>());  // glTF: x, y, z, w
        return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(glm::normalize(r)) * glm::scale(glm::dmat4(1.0), s);
    }

    // The default scene's nodes, depth first with an explicit stack, each
    // with its world matrix; its cameras and lights; its meshes' bounds.
    void walk() {
        const json& nodes = array(doc_, "nodes");
        const json& scenes = array(doc_, "scenes");
        std::vector<int> roots;
        if (!scenes.empty()) {
            const int s = doc_.contains("scene") ? index(doc_["scene"], scenes.size(), "scene", "scenes") : 0;
            for (const json& n : array(scenes[static_cast<std::size_t>(s)], "nodes"))
                roots.push_back(index(n, nodes.size(), "scenes[" + std::to_string(s) + "].nodes", "nodes"));
        }
        const json lightList = punctualLights();
        const json& cameraList = array(doc_, "cameras");
        std::vector<std::pair<int, glm::dmat4>> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
        std::vector<char> seen(nodes.size(), 0);
        while (!stack.empty()) {
            const auto [n, parent] = stack.back();
            stack.pop_back();
            if (seen[static_cast<std::size_t>(n)]) continue;  // the mesh loader refuses a graph that is not a forest
            seen[static_cast<std::size_t>(n)] = 1;
            const json& node = nodes[static_cast<std::size_t>(n)];
            const std::string at = "nodes[" + std::to_string(n) + "]";
            const glm::dmat4 world = parent * local(node);
            if (node.contains("camera")) cameras_.push_back({index(node["camera"], cameraList.size(), at + ".camera", "cameras"), world});
            if (const auto e = node.find("extensions"); e != node.end() && e->is_object() && e->contains("KHR_lights_punctual")) {
                const json& ext = (*e)["KHR_lights_punctual"];
                if (!ext.is_object() || !ext.contains("light")) fail(at + ".extensions.KHR_lights_punctual", "expected an object with \"light\"");
                placed_.push_back({index(ext["light"], lightList.size(), at + ".extensions.KHR_lights_punctual.light", "KHR_lights_punctual lights"), world,
                                   node.value("name", std::string())});
            }
            if (node.contains("mesh")) bound(node["mesh"], world, at + ".mesh");
            const json& children = array(node, "children");
            for (auto c = children.rbegin(); c != children.rend(); ++c)
                stack.emplace_back(index(*c, nodes.size(), at + ".children", "nodes"), world);
        }
    }

    void bound(const json& meshIndex, const glm::dmat4& world, const std::string& at) {
        const json& meshes = array(doc_, "meshes");
        const json& accessors = array(doc_, "accessors");
        const int m = index(meshIndex, meshes.size(), at, "meshes");
        for (const json& p : array(meshes[static_cast<std::size_t>(m)], "primitives")) {
            const auto attributes = p.find("attributes");
            if (attributes == p.end() || !attributes->contains("POSITION")) continue;
            const json& position = (*attributes)["POSITION"];
            if (!position.is_number_integer() || position.get<long long>() < 0 || position.get<long long>() >= static_cast<long long>(accessors.size())) continue;
            const json& a = accessors[position.get<std::size_t>()];
            const json& lo = array(a, "min");
            const json& hi = array(a, "max");
            if (lo.size() != 3 || hi.size() != 3) continue;  // required by glTF for POSITION; the mesh loader reads the rest
            for (int corner = 0; corner < 8; ++corner) {
                glm::dvec4 p4(1.0);
                for (int k = 0; k < 3; ++k) p4[k] = ((corner >> k) & 1 ? hi : lo)[static_cast<std::size_t>(k)].get<double>();
                const glm::dvec3 w(world * p4);
                lo_ = glm::min(lo_, w);
                hi_ = glm::max(hi_, w);
            }
        }
    }

    bool hasBounds() const { return lo_.x <= hi_.x; }
    glm::dvec3 centre() const { return hasBounds() ? 0.5 * (lo_ + hi_) : glm::dvec3(0.0); }
    double radius() const { return hasBounds() ? std::max(0.5 * glm::length(hi_ - lo_), 1e-3) : 1.0; }

    static json vec(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

    // The lights the default scene places, mapped to shadowlab's (no
    // distance falloff): each one's illuminance at the scene's centre
    // (directional: its lux; point and spot: candela over the squared
    // distance), the brightest one intensity 1 and the others in proportion.
    json lights(std::vector<std::string>& notes, bool defaults) const {
        const json list = punctualLights();
        json out = json::array();
        std::vector<double> lux;
        for (const Placed& placed : placed_) {
            const json& l = list[static_cast<std::size_t>(placed.light)];
            const std::string at = "extensions.KHR_lights_punctual.lights[" + std::to_string(placed.light) + "]";
            if (!l.is_object()) fail(at, "expected an object");
            const std::string type = l.value("type", std::string());
            if (type != "directional" && type != "point" && type != "spot") fail(at + ".type", "\"" + type + "\" is not directional, point or spot");
            const double intensity = number(l, "intensity", 1.0, at);
            if (intensity < 0.0) fail(at + ".intensity", "must not be negative");
            glm::dvec3 colour(1.0);
            if (const auto c = l.find("color"); c != l.end()) {
                if (!c->is_array() || c->size() != 3 || !std::all_of(c->begin(), c->end(), [](const json& v) { return v.is_number() && v.get<double>() >= 0.0; }))
                    fail(at + ".color", "expected 3 numbers of at least 0");
                colour = {(*c)[0].get<double>(), (*c)[1].get<double>(), (*c)[2].get<double>()};
            }
            json light{{"name", !l.value("name", std::string()).empty() ? l.value("name", std::string()) : placed.node}, {"type", type}, {"color", vec(colour)}};
            // A file shadowlab wrote (GltfExport.h): the scene's own position
            // and direction beside the node's matrix, where they agree with it
            // (a light another tool moved keeps its node's pose).
            const json& own = shadowlabExtras(l, at + ".extras.shadowlab");
            glm::dvec3 position(placed.world[3]);
            glm::dvec3 forward = glm::normalize(glm::dvec3(placed.world * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
            if (const auto p = vectorOf(own, "position"); p && closeTo(*p, position)) position = *p;
            if (const auto d = vectorOf(own, "direction"); d && along(*d, forward)) forward = *d;
            if (type != "point") light["direction"] = vec(forward);
            if (type != "directional") {
                light["position"] = vec(position);
                const double range = number(l, "range", 0.0, at);
                if (l.contains("range") && !(range > 0.0)) fail(at + ".range", "must be greater than 0");
                if (range > 0.0) light["range"] = range;
            }
            if (type == "spot") {
                const json spot = l.value("spot", json::object());
                const double inner = number(spot, "innerConeAngle", 0.0, at + ".spot"), outer = number(spot, "outerConeAngle", kPi / 4.0, at + ".spot");
                if (!(outer > 0.0) || outer > kPi / 2.0) fail(at + ".spot.outerConeAngle", "must lie in (0, pi/2] radians");
                if (inner < 0.0 || inner >= outer) fail(at + ".spot.innerConeAngle", "must lie in [0, outerConeAngle)");
                light["innerCone"] = inner * 180.0 / kPi;
                light["outerCone"] = std::min(outer * 180.0 / kPi, 89.9);  // shadowlab's spots open under 90 degrees
            }
            const double distance = std::max(glm::length(position - centre()), 1e-3 * radius());
            lux.push_back(type == "directional" ? intensity : intensity / (distance * distance));
            out.push_back(std::move(light));
        }
        const double brightest = lux.empty() ? 0.0 : *std::max_element(lux.begin(), lux.end());
        for (std::size_t k = 0; k < out.size(); ++k) {
            out[k]["intensity"] = brightest > 0.0 ? lux[k] / brightest : 0.0;
            // A file shadowlab wrote: the light's own intensity, size and shadow settings.
            const int l = placed_[k].light;
            const json& own = shadowlabExtras(list[static_cast<std::size_t>(l)], "extensions.KHR_lights_punctual.lights[" + std::to_string(l) + "].extras.shadowlab");
            for (const char* key : {"intensity", "size", "shadow", "projector"})
                if (own.contains(key)) out[k][key] = own[key];
            // The projected image beside the file, wherever the scene including it is.
            if (own.contains("projector") && own["projector"].is_string()) out[k]["projector"] = (dir_ / own["projector"].get<std::string>()).string();
        }
        if (out.empty() && defaults) {
            notes.push_back(file_ + ": no KHR_lights_punctual light in its scene: lit by the default sun");
            out.push_back({{"name", "sun"}, {"type", "directional"}, {"direction", json::array({-0.4, -1.0, -0.3})}});
        }
        return out;
    }

    // Camera `which` of those the default scene places, or one framing the
    // bounds. glTF cameras look down their node's -Z with +Y up.
    json camera(int which, std::vector<std::string>& notes, bool defaults) const {
        const json& list = array(doc_, "cameras");
        if (cameras_.empty() && !defaults) return nullptr;
        if (cameras_.empty()) {
            if (which != 0) fail("cameras", "camera " + std::to_string(which) + ": the scene places no camera");
            notes.push_back(file_ + ": no camera in its scene: one framing its bounds");
            const glm::dvec3 c = centre();
            const double r = radius();
            return {{"position", vec(c + glm::dvec3(1.0, 0.8, 1.4) * (1.6 * r))}, {"target", vec(c)}, {"fovY", 45.0},
                    {"near", 0.01 * r}, {"far", 8.0 * r}};
        }
        if (which < 0 || which >= static_cast<int>(cameras_.size()))
            fail("cameras", "camera " + std::to_string(which) + ": the scene places " + std::to_string(cameras_.size()) + " camera(s), counted from 0");
        const auto& [index, world] = cameras_[static_cast<std::size_t>(which)];
        const std::string at = "cameras[" + std::to_string(index) + "]";
        const json& cam = list[static_cast<std::size_t>(index)];
        const glm::dvec3 position(world[3]);
        json out = lens(cam, at, position, notes);
        const glm::dvec3 forward = glm::normalize(glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
        const glm::dvec3 up = glm::normalize(glm::dvec3(world * glm::dvec4(0.0, 1.0, 0.0, 0.0)));
        glm::dvec3 eye = position, target = position + forward * std::max(glm::length(centre() - position), 1.0), upHint = up;
        // A file shadowlab wrote (GltfExport.h): the scene's own eye, target
        // and up hint, where they agree with the node's pose.
        const json& own = shadowlabExtras(cam, at + ".extras.shadowlab");
        const auto e = vectorOf(own, "position"), t = vectorOf(own, "target"), h = vectorOf(own, "up");
        if (e && t && h && closeTo(*e, position) && along(*t - *e, forward) && along(*h - glm::dot(*h, forward) * forward, up)) {
            eye = *e;
            target = *t;
            upHint = *h;
        }
        out["position"] = vec(eye);
        out["target"] = vec(target);
        out["up"] = vec(upHint);
        return out;
    }

    // A camera's projection as the scene file's camera keys: perspective
    // (fovY; no zfar: one past the bounds, with a note) or orthographic
    // (orthoHeight 2 ymag; a znear of 0: a ten-thousandth of zfar, with a
    // note). The frame's aspect replaces the file's (aspectRatio, xmag).
    json lens(const json& cam, const std::string& at, const glm::dvec3& position, std::vector<std::string>& notes) const {
        const std::string type = cam.value("type", std::string());
        if (type == "orthographic") {
            const json o = cam.value("orthographic", json::object());
            const std::string in = at + ".orthographic";
            const double ymag = number(o, "ymag", 0.0, in), znear = number(o, "znear", -1.0, in), zfar = number(o, "zfar", 0.0, in);
            if (!(ymag > 0.0)) fail(in + ".ymag", "must be greater than 0");
            if (!(znear >= 0.0)) fail(in + ".znear", "must be 0 or more");
            if (!(zfar > znear)) fail(in + ".zfar", "must be greater than znear");
            double near = znear;
            if (!(near > 0.0)) {
                near = 1e-4 * zfar;
                notes.push_back(file_ + ": " + at + " has znear 0: near " + std::to_string(near) + " (shadowlab's near plane lies in front of the eye)");
            }
            return {{"orthoHeight", 2.0 * ymag}, {"near", near}, {"far", zfar}};
        }
        if (type != "perspective") fail(at + ".type", "\"" + type + "\" is not perspective or orthographic");
        const json p = cam.value("perspective", json::object());
        const double yfov = number(p, "yfov", 0.0, at + ".perspective"), znear = number(p, "znear", 0.0, at + ".perspective");
        if (!(yfov > 0.0) || yfov >= kPi) fail(at + ".perspective.yfov", "must lie in (0, pi) radians");
        if (!(znear > 0.0)) fail(at + ".perspective.znear", "must be greater than 0");
        double zfar = number(p, "zfar", 0.0, at + ".perspective");
        if (p.contains("zfar") && !(zfar > znear)) fail(at + ".perspective.zfar", "must be greater than znear");
        if (!p.contains("zfar")) {
            zfar = std::max(2.0 * (glm::length(position - centre()) + radius()), 2.0 * znear);
            notes.push_back(file_ + ": " + at + " has no zfar (an infinite far plane): far " + std::to_string(zfar) + ", past the scene's bounds");
        }
        return {{"fovY", yfov * 180.0 / kPi}, {"near", znear}, {"far", zfar}};
    }

    struct Placed {
        int light;
        glm::dmat4 world;
        std::string node;
    };

    std::string file_;
    fs::path dir_;  ///< the file's directory, absolute
    json doc_;
    std::vector<std::pair<int, glm::dmat4>> cameras_;
    std::vector<Placed> placed_;
    glm::dvec3 lo_{std::numeric_limits<double>::max()}, hi_{-std::numeric_limits<double>::max()};
};

} // namespace

bool isGltfPath(const fs::path& path) {
    const std::string e = lowercaseExtension(path);
    return e == ".gltf" || e == ".glb";
}

json gltfSceneDocument(const fs::path& path, const GltfSceneOptions& options, std::vector<std::string>& notes) {
    const std::string file = displayName(path);
    const std::string bytes = readWholeFile(path);
    std::string_view text = bytes;
    if (lowercaseExtension(path) == ".glb") {
        if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0) throw Error(file + ": not a binary glTF file (missing 'glTF' magic)");
        text = std::string_view(bytes).substr(20, std::min<std::size_t>(littleEndian32(bytes, 12), bytes.size() - 20));
    }
    if (text::jsonDepth(text) > text::kMaxJsonDepth) throw Error(file + ": JSON nested deeper than " + std::to_string(text::kMaxJsonDepth) + " levels");
    json doc = json::parse(text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) throw Error(file + ": not a glTF JSON file (its JSON does not parse as an object)");
    return GltfSceneReader(file, std::move(doc)).document(path, options, notes);
}

} // namespace shadowlab
