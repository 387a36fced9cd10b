// The `nodes` of a scene file: each node's transform, shadow flags and
// material, its shape or the mesh file it imports (one child node per
// primitive), its children; then the check that everything placed in the
// world stays finite.
#include "scene/SceneParts.h"

#include "scene/MeshFile.h"

#include <shadowlab/Error.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <utility>

namespace shadowlab::scenefile {

namespace fs = std::filesystem;

void SceneBuilder::readNodes(const Reader& r, int parent) {
    r.requireArray();
    for (std::size_t i = 0; i < r.value().size(); ++i) readNode(r.element(i), parent);
}

void SceneBuilder::readNode(const Reader& r, int parent) {
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
        Mesh mesh = readShape(r.child("shape"), shapeTrianglesLeft_);
        mesh.name = node.name.empty() ? r.child("shape").child("type").string() : node.name;
        node.mesh = addMesh(std::move(mesh));
    }
    const int index = static_cast<int>(scene_.nodes.size());
    scene_.nodes.push_back(node);
    nodeSources_.push_back(r.path());
    if (r.has("mesh")) importMesh(r.child("mesh"), index, materialOverride, node);
    if (r.has("children")) readNodes(r.child("children"), index);
}

int SceneBuilder::addMesh(Mesh mesh) {
    scene_.meshes.push_back(std::move(mesh));
    return static_cast<int>(scene_.meshes.size()) - 1;
}

void SceneBuilder::importMesh(const Reader& r, int parent, int materialOverride, const Node& owner) {
    const fs::path file = ctx_.baseDir / r.string();
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(file, ec);
    const std::string key = ec ? file.lexically_normal().string() : canonical.string();
    auto shared = meshFiles_.find(key);
    if (shared == meshFiles_.end()) {
        ImportedModel model;
        try {
            model = loadMeshFile(file);
        } catch (const Error& e) {
            r.fail(e.what());
        }
        // The file's triangles count against the scene's budget, once.
        std::size_t triangles = 0;
        for (const Mesh& m : model.meshes) triangles += m.triangleCount();
        if (triangles > shapeTrianglesLeft_)
            r.fail(file.string() + ": " + std::to_string(triangles) + " triangles, past what a scene may hold in all (" + std::to_string(kMaxShapeTriangles) +
                   " triangles of shapes and mesh files; " + std::to_string(shapeTrianglesLeft_) + " left)");
        shapeTrianglesLeft_ -= triangles;
        SharedFile added;
        added.meshBase = static_cast<int>(scene_.meshes.size());
        const int textureBase = static_cast<int>(scene_.textures.size());
        added.materialBase = static_cast<int>(scene_.materials.size());
        for (Mesh& m : model.meshes) scene_.meshes.push_back(std::move(m));
        for (ImageRGBA8& t : model.textures) scene_.textures.push_back(std::move(t));
        for (std::size_t t = 0; t < model.textures.size(); ++t)
            scene_.textureSources.push_back(ctx_.source + ": " + r.path() + ": " + file.string() + ": " +
                                            (t < model.textureSources.size() ? model.textureSources[t] : "texture " + std::to_string(t)));
        for (Material m : model.materials) {
            if (m.baseColorTexture >= 0) m.baseColorTexture += textureBase;
            scene_.materials.push_back(std::move(m));
        }
        added.nodes = std::move(model.nodes);
        shared = meshFiles_.emplace(key, std::move(added)).first;
    }
    const int meshBase = shared->second.meshBase, materialBase = shared->second.materialBase;
    const std::vector<ImportedModel::Node>& nodes = shared->second.nodes;
    std::vector<int> sceneIndex(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const ImportedModel::Node& in = nodes[i];
        Node node;
        node.name = in.name;
        node.parent = in.parent >= 0 ? sceneIndex[static_cast<std::size_t>(in.parent)] : parent;
        node.translation = in.translation;
        node.rotation = in.rotation;
        node.scale = in.scale;
        node.castsShadows = owner.castsShadows && in.castsShadows;
        node.receivesShadows = owner.receivesShadows && in.receivesShadows;
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
            p.castsShadows = node.castsShadows;
            p.receivesShadows = node.receivesShadows;
            scene_.nodes.push_back(p);
            nodeSources_.push_back(source);
        }
    }
}

void SceneBuilder::checkFinite() const {
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

} // namespace shadowlab::scenefile
