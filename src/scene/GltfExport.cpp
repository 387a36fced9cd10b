// A scene written as one glTF 2.0 file (GltfExport.h): the meshes in one
// buffer embedded as base64, a node per scene node, a material per scene
// material (and the default one where a node has none), the camera and the
// lights on nodes of their own, and what glTF has no field for in
// extras.shadowlab, which GltfScene.cpp (lights, scene) and GltfData.cpp
// (materials) read back.
#include <shadowlab/GltfExport.h>

#include "core/Base64.h"
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/Image.h>
#include <shadowlab/Techniques.h>
#include <shadowlab/Text.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kFloat = 5126, kUnsignedInt = 5125;            // glTF componentType
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;  // bufferView target

json vec3(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

json matrix(const glm::mat4& m) {
    json out = json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out.push_back(m[c][r]);
    return out;
}

// A light's shadow settings as a scene file writes them: the technique and,
// per options block, the fields that differ from their defaults.
json shadowJson(const ShadowSettings& shadow) {
    json out{{"technique", shadow.technique}};
    for (const auto& [name, block] : shadow.options) {
        const TechniqueInfo* t = findTechnique(name);
        if (!t || !t->options) continue;
        json fields = json::object();
        for (const OptionField& f : t->options->fields) {
            const std::string value = t->options->valueText(f, block);
            if (value != t->options->defaultText(f)) fields[f.key] = json::parse(value);
        }
        if (!fields.empty()) out[name] = std::move(fields);
    }
    return out;
}

void append32(std::string& out, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xffu);
}

// A binary glTF (glTF 2.0, section 4.4): the header, the JSON chunk padded
// with spaces, the BIN chunk padded with zeros.
std::string glb(std::string json, std::string bin) {
    while (json.size() % 4 != 0) json += ' ';
    while (bin.size() % 4 != 0) bin += '\0';
    std::string out;
    append32(out, 0x46546C67u);  // "glTF"
    append32(out, 2u);
    append32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    append32(out, static_cast<std::uint32_t>(json.size()));
    append32(out, 0x4E4F534Au);  // "JSON"
    out += json;
    append32(out, static_cast<std::uint32_t>(bin.size()));
    append32(out, 0x004E4942u);  // "BIN"
    out += bin;
    return out;
}

class Writer {
public:
    Writer(Scene scene, fs::path file, bool binary) : scene_(std::move(scene)), file_(std::move(file)), binary_(binary) {}

    std::vector<std::string> run() {
        doc_ = {{"asset", {{"version", "2.0"}, {"generator", "shadowlab export"}}},
                {"extensionsUsed", json::array({"KHR_lights_punctual"})},
                {"scene", 0}};
        for (std::size_t m = 0; m < scene_.materials.size(); ++m) materials_.push_back(material(scene_.materials[m]));
        json roots = json::array();
        std::vector<int> gltfNode(scene_.nodes.size(), -1);
        for (std::size_t n = 0; n < scene_.nodes.size(); ++n) {
            const Node& node = scene_.nodes[n];
            json out{{"name", node.name},
                     {"translation", vec3(node.translation)},
                     {"rotation", json::array({node.rotation.x, node.rotation.y, node.rotation.z, node.rotation.w})},
                     {"scale", vec3(node.scale)}};
            if (node.mesh >= 0) out["mesh"] = mesh(node.mesh, node.material);
            if (!node.castsShadows || !node.receivesShadows)
                out["extras"] = {{"shadowlab", {{"castsShadows", node.castsShadows}, {"receivesShadows", node.receivesShadows}}}};
            gltfNode[n] = static_cast<int>(nodes_.size());
            nodes_.push_back(std::move(out));
            if (node.parent >= 0) nodes_[static_cast<std::size_t>(gltfNode[static_cast<std::size_t>(node.parent)])]["children"].push_back(gltfNode[n]);
            else roots.push_back(gltfNode[n]);
        }
        roots.push_back(camera());
        json lights = json::array();
        for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
            lights.push_back(light(scene_.lights[l], l));
            roots.push_back(static_cast<int>(nodes_.size()) - 1);
        }
        doc_["extensions"] = {{"KHR_lights_punctual", {{"lights", std::move(lights)}}}};
        doc_["scenes"] = json::array({{{"name", scene_.name}, {"nodes", std::move(roots)}}});
        doc_["extras"] = {{"shadowlab", {{"name", scene_.name}, {"ambient", vec3(scene_.ambient)}, {"background", vec3(scene_.background)},
                                         {"shadowAtlas", {{"size", scene_.shadowAtlas.size}, {"texelsPerPixel", scene_.shadowAtlas.texelsPerPixel},
                                                          {"minTile", scene_.shadowAtlas.minTile}, {"maxTile", scene_.shadowAtlas.maxTile},
                                                          {"budgetPerPixel", scene_.shadowAtlas.budgetPerPixel},
                                                          {"updateBudget", scene_.shadowAtlas.updateBudget}}}}}};
        doc_["nodes"] = std::move(nodes_);
        doc_["meshes"] = std::move(meshes_);
        if (!materials_.empty()) doc_["materials"] = std::move(materials_);
        if (!images_.empty()) {
            doc_["images"] = std::move(images_);
            doc_["textures"] = std::move(textures_);
        }
        doc_["accessors"] = std::move(accessors_);
        doc_["bufferViews"] = std::move(views_);
        if (binary_) {
            doc_["buffers"] = json::array({{{"byteLength", bin_.size()}}});
            writeFileAtomically(file_, glb(doc_.dump(), bin_));
        } else {
            doc_["buffers"] = json::array({{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin_)}}});
            writeFileAtomically(file_, doc_.dump(1) + "\n");
        }
        return notes_;
    }

private:
    // A buffer view over `bytes` (4-byte aligned in the one buffer).
    int view(const void* data, std::size_t bytes, int target) {
        while (bin_.size() % 4 != 0) bin_ += '\0';
        views_.push_back({{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}, {"target", target}});
        bin_.append(static_cast<const char*>(data), bytes);
        return static_cast<int>(views_.size()) - 1;
    }

    template <class V>
    int accessor(const std::vector<V>& values, const char* type, bool bounds) {
        json a{{"bufferView", view(values.data(), values.size() * sizeof(V), kArrayBuffer)}, {"componentType", kFloat},
               {"count", values.size()}, {"type", type}};
        if (bounds && !values.empty()) {
            V lo = values.front(), hi = values.front();
            for (const V& v : values) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            a["min"] = json::array();
            a["max"] = json::array();
            for (int k = 0; k < V::length(); ++k) {
                a["min"].push_back(lo[k]);
                a["max"].push_back(hi[k]);
            }
        }
        accessors_.push_back(std::move(a));
        return static_cast<int>(accessors_.size()) - 1;
    }

    // The glTF mesh of scene mesh `m` drawn with `material` (one each pair).
    int mesh(int m, int material) {
        const auto key = std::pair(m, material);
        if (const auto it = meshOf_.find(key); it != meshOf_.end()) return it->second;
        const Mesh& src = scene_.meshes[static_cast<std::size_t>(m)];
        if (!attributes_.count(m)) {
            json a{{"POSITION", accessor(src.positions, "VEC3", true)}, {"NORMAL", accessor(src.normals, "VEC3", false)}};
            if (!src.uvs.empty()) a["TEXCOORD_0"] = accessor(src.uvs, "VEC2", false);
            accessors_.push_back({{"bufferView", view(src.indices.data(), src.indices.size() * 4, kElementArrayBuffer)},
                                  {"componentType", kUnsignedInt}, {"count", src.indices.size()}, {"type", "SCALAR"}});
            attributes_[m] = {std::move(a), static_cast<int>(accessors_.size()) - 1};
        }
        const auto& [attributes, indices] = attributes_[m];
        meshes_.push_back({{"name", src.name}, {"primitives", json::array({{{"attributes", attributes}, {"indices", indices}, {"material", materialIndex(material)}}})}});
        return meshOf_[key] = static_cast<int>(meshes_.size()) - 1;
    }

    int materialIndex(int m) {
        if (m >= 0) return m;
        if (defaultMaterial_ < 0) {
            Material d;
            d.name = "default";
            materials_.push_back(material(d));
            defaultMaterial_ = static_cast<int>(materials_.size()) - 1;
        }
        return defaultMaterial_;
    }

    json material(const Material& m) {
        json pbr{{"baseColorFactor", json::array({m.baseColor.r, m.baseColor.g, m.baseColor.b, m.alpha})}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
        if (m.baseColorTexture >= 0) pbr["baseColorTexture"] = {{"index", texture(m.baseColorTexture)}};
        json out{{"name", m.name}, {"pbrMetallicRoughness", std::move(pbr)},
                 {"extras", {{"shadowlab", {{"ambient", vec3(m.ambient)}, {"diffuse", vec3(m.diffuse)}, {"specular", vec3(m.specular)}, {"shininess", m.shininess}}}}}};
        if (m.alphaMode == AlphaMode::Mask) {
            out["alphaMode"] = "MASK";
            out["alphaCutoff"] = m.alphaCutoff;
        } else if (m.alphaMode == AlphaMode::Blend) {
            out["alphaMode"] = "BLEND";
        }
        return out;
    }

    // Texture t of the scene as a PNG beside the file.
    int texture(int t) {
        if (const auto it = textureOf_.find(t); it != textureOf_.end()) return it->second;
        const std::string name = file_.stem().string() + "-texture" + std::to_string(t) + ".png";
        writePng(file_.parent_path() / name, scene_.textures[static_cast<std::size_t>(t)]);
        images_.push_back({{"uri", name}});
        textures_.push_back({{"source", static_cast<int>(images_.size()) - 1}});
        return textureOf_[t] = static_cast<int>(textures_.size()) - 1;
    }

    // The camera on a node of its own; returns the node's index.
    int camera() {
        const Camera& c = scene_.camera;
        json camera{{"extras", {{"shadowlab", {{"position", vec3(c.position)}, {"target", vec3(c.target)}, {"up", vec3(c.up)}}}}}};
        if (c.orthoHeight > 0.0f) {  // xmag: the frame's aspect is not the scene's; a square
            camera["type"] = "orthographic";
            camera["orthographic"] = {{"xmag", 0.5 * c.orthoHeight}, {"ymag", 0.5 * c.orthoHeight}, {"znear", c.nearPlane}, {"zfar", c.farPlane}};
        } else {
            camera["type"] = "perspective";
            camera["perspective"] = {{"yfov", glm::radians(static_cast<double>(c.fovYDeg))}, {"znear", c.nearPlane}, {"zfar", c.farPlane}};
        }
        doc_["cameras"] = json::array({std::move(camera)});
        if (c.path) notes_.push_back("camera.path: the camera's animation is not exported (its pose at time 0 is)");
        nodes_.push_back({{"name", "camera"}, {"camera", 0}, {"matrix", matrix(glm::inverse(c.viewFromWorld()))}});
        return static_cast<int>(nodes_.size()) - 1;
    }

    // Light l as a KHR_lights_punctual light on a node of its own (its -Z
    // the light's direction), its shadowlab keys in extras with its exact
// position and direction (the import takes them where they agree with the
// node's matrix). The glTF
    // intensity follows the import's rule backwards (docs/scene-format.md):
    // lux for a directional light, candela = intensity x the squared
    // distance to the bounds' centre for the others.
    json light(const Light& light, std::size_t l) {
        const std::string at = "lights[" + std::to_string(l) + "]";
        auto [lo, hi] = scene_.worldBounds();
        if (!(lo.x <= hi.x)) lo = hi = glm::vec3(0.0f);
        const glm::vec3 centre = 0.5f * (lo + hi);
        const double d2 = std::max(static_cast<double>(glm::dot(light.position - centre, light.position - centre)), 1e-6);
        json out{{"name", light.name}, {"color", vec3(light.color)},
                 {"intensity", light.type == LightType::Directional ? static_cast<double>(light.intensity) : light.intensity * d2}};
        const glm::vec3 axis = glm::normalize(light.direction);
        glm::mat4 world = glm::translate(glm::mat4(1.0f), light.position);
        switch (light.type) {
        case LightType::Directional: out["type"] = "directional"; break;
        case LightType::Point: out["type"] = "point"; break;
        case LightType::Spot:
            out["type"] = "spot";
            out["spot"] = {{"innerConeAngle", glm::radians(static_cast<double>(light.innerConeDeg))}, {"outerConeAngle", glm::radians(static_cast<double>(light.outerConeDeg))}};
            break;
        }
        if (light.type != LightType::Point) world = glm::inverse(glm::lookAt(light.position, light.position + axis, lightCameraUp(axis)));
        if (light.type != LightType::Directional && light.range > 0.0f) out["range"] = light.range;
        json keys{{"intensity", light.intensity}, {"shadow", shadowJson(light.shadow)}, {"position", vec3(light.position)}, {"direction", vec3(light.direction)}};
        if (light.size > 0.0f) keys["size"] = light.size;
        if (light.projectorTexture >= 0) {
            // The projected image beside the file, named in extras (a scene file's `projector`, relative to it).
            const std::string name = file_.stem().string() + "-projector" + std::to_string(l) + ".png";
            writePng(file_.parent_path() / name, scene_.textures[static_cast<std::size_t>(light.projectorTexture)]);
            keys["projector"] = name;
        }
        out["extras"] = {{"shadowlab", std::move(keys)}};
        if (light.path) notes_.push_back(at + ".path: the light's animation is not exported (its position at time 0 is)");
        nodes_.push_back({{"name", light.name}, {"matrix", matrix(world)}, {"extensions", {{"KHR_lights_punctual", {{"light", l}}}}}});
        return out;
    }

    const Scene scene_;
    fs::path file_;
    bool binary_ = false;  ///< .glb: the buffer as the BIN chunk
    json doc_;
    json nodes_ = json::array(), meshes_ = json::array(), materials_ = json::array(), accessors_ = json::array(), views_ = json::array();
    json images_ = json::array(), textures_ = json::array();
    std::string bin_;
    std::map<std::pair<int, int>, int> meshOf_;
    std::map<int, std::pair<json, int>> attributes_;
    std::map<int, int> textureOf_;
    int defaultMaterial_ = -1;
    std::vector<std::string> notes_;
};

} // namespace

std::vector<std::string> writeGltfScene(const Scene& scene, const fs::path& file) {
    const std::string ext = meshfile::lowercaseExtension(file);
    if (ext != ".gltf" && ext != ".glb") throw Error(text::escapeControl(file.string()) + ": expected a name ending in .gltf or .glb");
    if (file.string().size() > 4096) throw Error(text::escapeControl(file.string().substr(0, 64)) + "...: name too long");
    // The lights and the camera where their paths put them at time 0 (glTF animations are not written).
    return Writer(sceneAtTime(scene, 0.0), file, ext == ".glb").run();
}

} // namespace shadowlab
