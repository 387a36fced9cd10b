// A glTF model's node graph made shadowlab's (GltfImporter.h).
#include "scene/GltfImporter.h"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace shadowlab::gltf {

using namespace meshfile;

ImportedModel GltfImporter::run() {
    for (std::size_t i = 0; i < gltf_.materials.size(); ++i) out_.materials.push_back(material(gltf_.materials[i], i));

    // Roots: the default scene, else scene 0, else every node no one references.
    std::vector<int> roots;
    if (!gltf_.scenes.empty()) {
        const int scene = gltf_.defaultScene >= 0 && gltf_.defaultScene < static_cast<int>(gltf_.scenes.size()) ? gltf_.defaultScene : 0;
        roots = gltf_.scenes[scene].nodes;
    } else {
        std::vector<bool> isChild(gltf_.nodes.size(), false);
        for (const tinygltf::Node& n : gltf_.nodes)
            for (int c : n.children)
                if (c >= 0 && c < static_cast<int>(isChild.size())) isChild[c] = true;
        for (std::size_t i = 0; i < gltf_.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
        if (roots.empty() && !gltf_.nodes.empty()) fail("node hierarchy has no root node (cycle)");
    }
    checkParents();
    visited_.assign(gltf_.nodes.size(), false);
    // Depth-first with an explicit stack (a node chain 20,000 long must
    // not overflow the call stack); parents are emitted before children.
    std::vector<std::pair<int, int>> stack; // (glTF node, parent in out_.nodes)
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.emplace_back(*r, -1);
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        const int self = addNode(index, parent);
        const std::vector<int>& children = gltf_.nodes[static_cast<std::size_t>(index)].children;
        for (auto c = children.rbegin(); c != children.rend(); ++c) stack.emplace_back(*c, self);
    }
    checkFiniteWorld();

    std::size_t triangles = 0;
    for (const Mesh& m : out_.meshes) triangles += m.triangleCount();
    if (triangles == 0) throw Error(file_ + ": no triangles");
    return std::move(out_);
}

std::string GltfImporter::nodeName(int index) const {
    const std::string& name = gltf_.nodes[static_cast<std::size_t>(index)].name;
    return "node " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

void GltfImporter::checkParents() const {
    std::vector<int> parentOf(gltf_.nodes.size(), -1);
    for (std::size_t i = 0; i < gltf_.nodes.size(); ++i) {
        for (int c : gltf_.nodes[i].children) {
            if (c < 0 || c >= static_cast<int>(gltf_.nodes.size()))
                fail("node index " + std::to_string(c) + " out of range (a child of " + nodeName(static_cast<int>(i)) + ")");
            if (c == static_cast<int>(i)) fail(nodeName(c) + " is its own child (cycle)");
            if (parentOf[static_cast<std::size_t>(c)] >= 0)
                fail(nodeName(c) + " has two parents (nodes " + std::to_string(parentOf[static_cast<std::size_t>(c)]) + " and " +
                     std::to_string(i) + ")");
            parentOf[static_cast<std::size_t>(c)] = static_cast<int>(i);
        }
    }
    // With one parent each, a cycle is a parent chain that returns to a
    // node on the chain being walked: mark chains, each node once (O(n)).
    enum : char { Unseen, OnChain, Done };
    std::vector<char> state(gltf_.nodes.size(), Unseen);
    std::vector<int> chain;
    for (std::size_t start = 0; start < gltf_.nodes.size(); ++start) {
        chain.clear();
        for (int n = static_cast<int>(start); n >= 0 && state[static_cast<std::size_t>(n)] != Done; n = parentOf[static_cast<std::size_t>(n)]) {
            if (state[static_cast<std::size_t>(n)] == OnChain) fail(nodeName(n) + " is referenced more than once (a cycle: it is its own ancestor)");
            state[static_cast<std::size_t>(n)] = OnChain;
            chain.push_back(n);
        }
        for (int n : chain) state[static_cast<std::size_t>(n)] = Done;
    }
}

void GltfImporter::checkFiniteWorld() const {
    std::vector<glm::mat4> world(out_.nodes.size());
    for (std::size_t i = 0; i < out_.nodes.size(); ++i) {
        const ImportedModel::Node& n = out_.nodes[i];
        const glm::mat4 local = glm::translate(glm::mat4(1.0f), n.translation) * glm::mat4_cast(n.rotation) *
                                glm::scale(glm::mat4(1.0f), n.scale);
        world[i] = n.parent >= 0 ? world[static_cast<std::size_t>(n.parent)] * local : local;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(world[i][c][r])) fail(nodeName(sourceIndex_[i]) + ": transform is not finite after composing its parents'");
    }
}

bool GltfImporter::allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v) && std::fabs(v) <= 3.0e38; });
}

int GltfImporter::addNode(int index, int parent) {
    if (index < 0 || index >= static_cast<int>(gltf_.nodes.size())) fail("node index " + std::to_string(index) + " out of range");
    if (visited_[static_cast<std::size_t>(index)]) fail(nodeName(index) + " is referenced more than once (cycle or shared node)");
    visited_[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& src = gltf_.nodes[static_cast<std::size_t>(index)];
    if (!allFinite(src.matrix) || !allFinite(src.translation) || !allFinite(src.rotation) || !allFinite(src.scale))
        fail(nodeName(index) + ": transform values must be finite numbers of magnitude <= 3e38");

    ImportedModel::Node node;
    node.name = src.name;
    node.parent = parent;
    if (src.matrix.size() == 16) {
        glm::mat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(src.matrix[static_cast<std::size_t>(c * 4 + r)]); // column-major
        glm::vec3 skew;
        glm::vec4 perspective;
        if (!glm::decompose(m, node.scale, node.rotation, node.translation, skew, perspective))
            fail("node " + std::to_string(index) + " ('" + src.name + "'): matrix cannot be decomposed");
    } else {
        if (src.translation.size() == 3)
            node.translation = glm::vec3(static_cast<float>(src.translation[0]), static_cast<float>(src.translation[1]), static_cast<float>(src.translation[2]));
        if (src.rotation.size() == 4) // glTF stores x, y, z, w; glm::quat's constructor takes w first
            node.rotation = glm::normalize(glm::quat(static_cast<float>(src.rotation[3]), static_cast<float>(src.rotation[0]),
                                                     static_cast<float>(src.rotation[1]), static_cast<float>(src.rotation[2])));
        if (src.scale.size() == 3)
            node.scale = glm::vec3(static_cast<float>(src.scale[0]), static_cast<float>(src.scale[1]), static_cast<float>(src.scale[2]));
    }
    // A file shadowlab wrote (GltfExport.h): the node's castsShadows and receivesShadows.
    if (src.extras.IsObject() && src.extras.Has("shadowlab")) {
        const tinygltf::Value& own = src.extras.Get("shadowlab");
        if (!own.IsObject()) fail(nodeName(index) + ": extras.shadowlab: expected an object");
        for (const auto& [key, flag] : {std::pair{"castsShadows", &node.castsShadows}, std::pair{"receivesShadows", &node.receivesShadows}}) {
            if (!own.Has(key)) continue;
            if (!own.Get(key).IsBool()) fail(nodeName(index) + ": extras.shadowlab." + key + ": expected true or false");
            *flag = own.Get(key).Get<bool>();
        }
    }
    if (src.mesh >= 0) {
        if (src.mesh >= static_cast<int>(gltf_.meshes.size())) fail("node " + std::to_string(index) + ": mesh index out of range");
        const tinygltf::Mesh& mesh = gltf_.meshes[src.mesh];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const int imported = primitiveMesh(src.mesh, static_cast<int>(p));
            if (imported < 0) continue;
            int mat = mesh.primitives[p].material;
            if (mat >= static_cast<int>(out_.materials.size())) fail("mesh '" + mesh.name + "': material index " + std::to_string(mat) + " out of range");
            node.primitives.push_back({imported, mat < 0 ? -1 : mat});
        }
    }
    const int self = static_cast<int>(out_.nodes.size());
    out_.nodes.push_back(std::move(node));
    sourceIndex_.push_back(index);
    return self;
}

} // namespace shadowlab::gltf
