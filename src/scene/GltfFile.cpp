// Loading glTF 2.0 (.gltf, .glb) through tinygltf (see MeshFile.h).
//
// Every index, offset, stride and count read from the file is checked in
// overflow-safe arithmetic before any byte is read; the node graph is walked
// with an explicit stack, so a deep hierarchy cannot overflow the call stack.
#include "scene/GltfSchema.h"
#include "scene/MeshFile.h"

#include <shadowlab/Text.h>

#include <shadowlab/Error.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>

namespace shadowlab {

namespace fs = std::filesystem;
using namespace meshfile;

namespace {

/// tinygltf's error text as one line: newlines become "; " and embedded
/// base64 payloads (tinygltf quotes whole data URIs) are shortened.
std::string oneLine(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    // nlohmann's "[json.exception.parse_error.101] " prefix says nothing to a user.
    if (const auto pos = s.find("[json.exception."); pos != std::string::npos) {
        const auto end = s.find("] ", pos);
        if (end != std::string::npos) s.erase(pos, end + 2 - pos);
    }
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '\r') continue;
        if (c != '\n' && (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)) {
            out += '?';  // bytes quoted from a binary file must not break the line
        } else if (c == '\n') {
            out += "; ";
        } else if (c == ',' && out.size() >= 6 && out.compare(out.size() - 6, 6, "base64") == 0) {
            std::size_t end = i + 1;
            while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '+' || s[end] == '/' || s[end] == '='))
                ++end;
            out += ',';
            out.append(s, i + 1, std::min<std::size_t>(end - i - 1, 16));
            if (end - i - 1 > 16) out += "...";
            i = end - 1;
        } else {
            out += c;
        }
    }
    return out;
}

const char* componentTypeName(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_INT: return "int";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "double";
    default: return "unknown";
    }
}

class GltfImporter {
public:
    GltfImporter(std::string file, const tinygltf::Model& gltf) : file_(std::move(file)), gltf_(gltf) {}

    ImportedModel run() {
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

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(text::escapeControl(file_ + ": " + what)); }

    std::string nodeName(int index) const {
        const std::string& name = gltf_.nodes[static_cast<std::size_t>(index)].name;
        return "node " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
    }

    /// A glTF node graph is a forest (glTF 2.0, section 3.5.3): every child
    /// index in range, no node its own child, no node with two parents.
    void checkParents() const {
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

    /// Every node's composed transform must be finite (a translation of
    /// 1e300 becomes infinity as a float; 1e38 * 1e38 overflows).
    void checkFiniteWorld() const {
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

    static bool allFinite(const std::vector<double>& values) {
        return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v) && std::fabs(v) <= 3.0e38; });
    }

    /// Appends node `index` to out_.nodes; returns its index there.
    int addNode(int index, int parent) {
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

    /// Imports (once) primitive p of glTF mesh m; -1 if it has no triangles.
    int primitiveMesh(int m, int p) {
        const auto key = std::make_pair(m, p);
        if (auto it = meshCache_.find(key); it != meshCache_.end()) return it->second;
        const tinygltf::Mesh& src = gltf_.meshes[m];
        const tinygltf::Primitive& prim = src.primitives[static_cast<std::size_t>(p)];
        int result = -1;
        if (prim.mode == -1 || prim.mode == TINYGLTF_MODE_TRIANGLES) { // other modes are skipped
            Mesh mesh = readPrimitive(src, prim, p);
            if (mesh.triangleCount() > 0) {
                result = static_cast<int>(out_.meshes.size());
                out_.meshes.push_back(std::move(mesh));
            }
        }
        meshCache_[key] = result;
        return result;
    }

    Mesh readPrimitive(const tinygltf::Mesh& src, const tinygltf::Primitive& prim, int p) {
        const std::string where = "mesh '" + src.name + "' primitive " + std::to_string(p);
        Mesh mesh;
        mesh.name = src.primitives.size() > 1 ? src.name + "#" + std::to_string(p) : src.name;

        const auto attribute = [&](const char* name) {
            const auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int posAccessor = attribute("POSITION");
        if (posAccessor < 0) fail(where + ": no POSITION attribute");
        mesh.positions = readVectors<3>(posAccessor, "POSITION");
        const std::size_t count = mesh.positions.size();

        if (prim.indices >= 0) {
            mesh.indices = readIndices(prim.indices, count);
        } else {
            mesh.indices.resize(count);
            for (std::size_t i = 0; i < count; ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
        }
        if (mesh.indices.size() % 3 != 0)
            fail(where + ": " + std::to_string(mesh.indices.size()) + " indices is not a multiple of 3");

        if (const int a = attribute("TEXCOORD_0"); a >= 0) {
            mesh.uvs = readVectors<2>(a, "TEXCOORD_0");
            if (mesh.uvs.size() != count) fail(where + ": TEXCOORD_0 count differs from POSITION count");
        }
        if (const int a = attribute("NORMAL"); a >= 0) {
            mesh.normals = readVectors<3>(a, "NORMAL");
            if (mesh.normals.size() != count) fail(where + ": NORMAL count differs from POSITION count");
            // Renormalise; zero-length normals are replaced by computed ones.
            std::vector<glm::vec3> computed;
            for (glm::vec3& n : mesh.normals) {
                const float len = glm::length(n);
                if (len > 0.0f) {
                    n /= len;
                } else {
                    if (computed.empty()) computed = smoothNormals(mesh.positions, mesh.indices);
                    n = computed[static_cast<std::size_t>(&n - mesh.normals.data())];
                }
            }
        } else {
            mesh.normals = smoothNormals(mesh.positions, mesh.indices);
        }
        return mesh;
    }

    /// Checks that accessor elements of `elementSize` bytes lie inside their
    /// buffer; returns the first byte and the stride (0 if no buffer view).
    std::pair<const unsigned char*, std::size_t> locate(const tinygltf::Accessor& acc, int index, const std::string& what,
                                                        std::size_t elementSize) const {
        (void)index;
        if (acc.sparse.isSparse) fail(what + ": sparse accessors are not supported");
        if (acc.count > kMaxAccessorElements)
            fail(what + ": count " + std::to_string(acc.count) + " exceeds the limit of " + std::to_string(kMaxAccessorElements) + " elements");
        if (acc.bufferView < 0) return {nullptr, 0}; // all zeros by the spec
        if (acc.bufferView >= static_cast<int>(gltf_.bufferViews.size())) fail(what + ": bufferView out of range");
        const tinygltf::BufferView& view = gltf_.bufferViews[acc.bufferView];
        if (view.buffer < 0 || view.buffer >= static_cast<int>(gltf_.buffers.size())) fail(what + ": buffer out of range");
        const tinygltf::Buffer& buffer = gltf_.buffers[view.buffer];
        if (view.byteStride != 0 && view.byteStride < elementSize)
            fail(what + ": bufferView " + std::to_string(acc.bufferView) + " byteStride " + std::to_string(view.byteStride) +
                 " is smaller than an element (" + std::to_string(elementSize) + " bytes)");
        const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
        // Each comparison subtracts only what is known to be smaller, so no
        // offset near 2^64 can wrap around and pass.
        const std::size_t size = buffer.data.size();
        if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
            fail(what + ": bufferView " + std::to_string(acc.bufferView) + " (byteOffset " + std::to_string(view.byteOffset) +
                 ", byteLength " + std::to_string(view.byteLength) + ") lies past the end of its buffer (" + std::to_string(size) + " bytes)");
        const bool fits = acc.byteOffset <= view.byteLength &&
                          (acc.count == 0 || (elementSize <= view.byteLength - acc.byteOffset &&
                                              acc.count - 1 <= (view.byteLength - acc.byteOffset - elementSize) / stride));
        if (!fits)
            fail(what + ": byteOffset " + std::to_string(acc.byteOffset) + " and count " + std::to_string(acc.count) +
                 " read past the end of bufferView " + std::to_string(acc.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
        return {buffer.data.data() + view.byteOffset + acc.byteOffset, stride};
    }

    template <int N>
    std::vector<glm::vec<N, float>> readVectors(int index, const char* semantic) const {
        const std::string what = "accessor " + std::to_string(index) + " (" + semantic + ")";
        if (index < 0 || index >= static_cast<int>(gltf_.accessors.size())) fail(what + ": accessor index out of range");
        const tinygltf::Accessor& acc = gltf_.accessors[index];
        const int expectedType = N == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
        if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || acc.normalized || acc.type != expectedType)
            fail(what + ": expected float VEC" + std::to_string(N) + ", got " + (acc.normalized ? "normalized " : "") +
                 componentTypeName(acc.componentType) + " with " + std::to_string(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type))) +
                 " components (quantized/normalized attributes are not supported)");
        const auto [data, stride] = locate(acc, index, what, N * sizeof(float));
        std::vector<glm::vec<N, float>> values(acc.count, glm::vec<N, float>(0.0f));
        if (!data) return values;
        for (std::size_t i = 0; i < acc.count; ++i) {
            std::memcpy(glm::value_ptr(values[i]), data + i * stride, N * sizeof(float)); // unaligned-safe
            for (int k = 0; k < N; ++k)
                if (!std::isfinite(values[i][k])) fail(what + ": non-finite value in element " + std::to_string(i));
        }
        return values;
    }

    std::vector<std::uint32_t> readIndices(int index, std::size_t vertexCount) const {
        const std::string what = "accessor " + std::to_string(index) + " (indices)";
        if (index >= static_cast<int>(gltf_.accessors.size())) fail(what + ": accessor index out of range");
        const tinygltf::Accessor& acc = gltf_.accessors[index];
        std::size_t size = 0;
        switch (acc.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
        default: fail(what + ": expected unsigned byte/short/int indices, got " + componentTypeName(acc.componentType));
        }
        if (acc.type != TINYGLTF_TYPE_SCALAR) fail(what + ": expected SCALAR indices");
        const auto [data, stride] = locate(acc, index, what, size);
        std::vector<std::uint32_t> indices(acc.count, 0u);
        for (std::size_t i = 0; data && i < acc.count; ++i) {
            const unsigned char* e = data + i * stride;
            if (size == 1) {
                indices[i] = e[0];
            } else if (size == 2) {
                std::uint16_t v;
                std::memcpy(&v, e, 2);
                indices[i] = v;
            } else {
                std::memcpy(&indices[i], e, 4);
            }
        }
        for (std::uint32_t i : indices)
            if (i >= vertexCount) fail(what + ": index " + std::to_string(i) + " out of range (" + std::to_string(vertexCount) + " vertices)");
        return indices;
    }

    // A material as the glTF 2.0 spec allows it, no value clamped: the scene
    // JSON refuses the same values (MaterialFile.cpp).
    Material material(const tinygltf::Material& src, std::size_t index) {
        Material m;
        m.name = src.name;
        const std::string at = "materials[" + std::to_string(index) + "]";
        const auto& pbr = src.pbrMetallicRoughness;
        for (std::size_t c = 0; c < pbr.baseColorFactor.size(); ++c)
            if (!(pbr.baseColorFactor[c] >= 0.0 && pbr.baseColorFactor[c] <= 1.0))
                fail(at + ".pbrMetallicRoughness.baseColorFactor[" + std::to_string(c) + "]: expected a number in 0..1, got " +
                     text::numberText(pbr.baseColorFactor[c]));
        if (pbr.baseColorFactor.size() >= 3)
            m.baseColor = glm::vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
                                    static_cast<float>(pbr.baseColorFactor[2]));
        if (pbr.baseColorFactor.size() >= 4) m.alpha = static_cast<float>(pbr.baseColorFactor[3]);
        // glTF's alphaMode ("OPAQUE" when absent) and alphaCutoff (0.5 by default, >= 0).
        if (src.alphaMode != "OPAQUE" && src.alphaMode != "MASK" && src.alphaMode != "BLEND" && !src.alphaMode.empty())
            fail(at + ".alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\", got \"" + src.alphaMode + "\"");
        m.alphaMode = src.alphaMode == "MASK" ? AlphaMode::Mask : src.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
        if (!(src.alphaCutoff >= 0.0 && src.alphaCutoff <= 1.0))
            fail(at + ".alphaCutoff: expected a number in 0..1, got " + text::numberText(src.alphaCutoff));
        m.alphaCutoff = static_cast<float>(src.alphaCutoff);
        const int tex = pbr.baseColorTexture.index;
        if (tex >= 0 && tex < static_cast<int>(gltf_.textures.size())) {
            const int source = gltf_.textures[tex].source;
            if (source >= 0) m.baseColorTexture = image(source); // -1 e.g. for extension-only (KTX2) sources
        }
        return m;
    }

    /// Converts (once) image `index` to RGBA8 and returns its index in out_.textures.
    int image(int index) {
        if (auto it = imageCache_.find(index); it != imageCache_.end()) return it->second;
        if (index >= static_cast<int>(gltf_.images.size())) fail("image index " + std::to_string(index) + " out of range");
        const tinygltf::Image& src = gltf_.images[index];
        const std::string uri = src.uri.rfind("data:", 0) == 0 ? "data URI" : src.uri; // a data URI is megabytes of base64
        const std::string what = "image " + std::to_string(index) + " ('" + (src.name.empty() ? uri : src.name) + "')";
        const int channels = src.component, bytesPerChannel = src.bits == 16 ? 2 : 1;
        if (src.width <= 0 || src.height <= 0 || channels < 1 || channels > 4 || (src.bits != 8 && src.bits != 16))
            fail(what + ": no decoded pixel data");
        if (src.width > kMaxImageSide || src.height > kMaxImageSide)
            fail(what + ": " + std::to_string(src.width) + "x" + std::to_string(src.height) + " exceeds the limit of " +
                 std::to_string(kMaxImageSide) + " pixels per side");
        const std::size_t pixels = static_cast<std::size_t>(src.width) * static_cast<std::size_t>(src.height);
        if (pixels > kMaxImagePixels) fail(what + ": " + std::to_string(pixels) + " pixels exceeds the limit of " + std::to_string(kMaxImagePixels));
        if (src.image.size() / static_cast<std::size_t>(channels * bytesPerChannel) < pixels) fail(what + ": truncated pixel data");

        ImageRGBA8 img;
        img.width = src.width;
        img.height = src.height;
        img.pixels.resize(pixels * 4);
        const auto channel = [&](std::size_t pixel, int c) -> std::uint8_t {
            const std::size_t at = (pixel * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)) * static_cast<std::size_t>(bytesPerChannel);
            if (bytesPerChannel == 1) return src.image[at];
            std::uint16_t v;
            std::memcpy(&v, &src.image[at], 2);                  // stb returns native-endian uint16
            return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u); // round to nearest 8-bit value
        };
        for (std::size_t i = 0; i < pixels; ++i) {
            std::uint8_t* d = &img.pixels[i * 4];
            if (channels <= 2) { // grey (+ alpha)
                d[0] = d[1] = d[2] = channel(i, 0);
                d[3] = channels == 2 ? channel(i, 1) : 255;
            } else {
                d[0] = channel(i, 0);
                d[1] = channel(i, 1);
                d[2] = channel(i, 2);
                d[3] = channels == 4 ? channel(i, 3) : 255;
            }
        }
        const int result = static_cast<int>(out_.textures.size());
        out_.textures.push_back(std::move(img));
        out_.textureSources.push_back(what);
        imageCache_[index] = result;
        return result;
    }

    std::string file_;
    const tinygltf::Model& gltf_;
    ImportedModel out_;
    std::vector<bool> visited_;
    std::vector<int> sourceIndex_; ///< glTF node index of each out_.nodes entry
    std::map<std::pair<int, int>, int> meshCache_;
    std::map<int, int> imageCache_;
};

} // namespace

namespace {

/// tinygltf's image loader, after a look at the header: an image past
/// kMaxImageSide or kMaxImagePixels is refused before it is decoded, so a
/// small PNG declaring 60000x60000 pixels cannot exhaust memory.
bool loadImageChecked(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int reqWidth, int reqHeight,
                      const unsigned char* bytes, int size, void* user) {
    int w = 0, h = 0, channels = 0;
    if (stbi_info_from_memory(bytes, size, &w, &h, &channels) &&
        (w > kMaxImageSide || h > kMaxImageSide || static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > kMaxImagePixels)) {
        if (err)
            *err += "image " + std::to_string(index) + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " +
                    std::to_string(kMaxImageSide) + " pixels per side and " + std::to_string(kMaxImagePixels) + " pixels\n";
        return false;
    }
    return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size, user);
}

/// tinygltf's file access for external URIs, limited to regular files: its
/// own reader takes a directory's size as 2^63 - 1 and allocates that.
bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return fs::exists(path, ec); // a directory exists; reading it is the error
}

bool readWholeFileChecked(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        if (err) *err += "'" + path + "' is not a regular file\n";
        return false;
    }
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec || size > kMaxExternalFileBytes) {
        if (err) *err += "'" + path + "': " + (ec ? ec.message() : "larger than " + std::to_string(kMaxExternalFileBytes) + " bytes") + "\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(static_cast<std::size_t>(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        if (err) *err += "'" + path + "': read error\n";
        return false;
    }
    return true;
}

std::uint32_t readLittleEndian32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<std::uint8_t>(bytes[at + static_cast<std::size_t>(k)]);
    return v;
}

/// The JSON text of a .gltf, or the JSON chunk of a .glb (glTF 2.0, section 4.4), for the depth check.
std::string_view jsonPart(const std::string& bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20) return {};
    const std::size_t length = readLittleEndian32(bytes, 12);
    return std::string_view(bytes).substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

} // namespace

ImportedModel loadGltf(const fs::path& path) {
    const bool binary = lowercaseExtension(path) == ".glb";
    const fs::path dir = path.parent_path();
    return parseGltf(readWholeFile(path), displayName(path), dir.empty() ? fs::path(".") : dir, binary);
}

ImportedModel parseGltf(const std::string& bytes, const std::string& file, const fs::path& baseDir, bool binary) {
    if (binary) {
        if (bytes.size() < 4 || std::memcmp(bytes.data(), "glTF", 4) != 0)
            throw Error(file + ": not a binary glTF file (missing 'glTF' magic)");
        if (bytes.size() >= 8) {
            std::uint32_t version = 0;
            std::memcpy(&version, bytes.data() + 4, 4);  // little-endian, as the format and this machine are
            if (version != 2) throw Error(file + ": binary glTF version " + std::to_string(version) + " (expected 2)");
        }
    } else {
        const std::size_t first = bytes.find_first_not_of(" \t\r\n\f\v");
        if (first == std::string::npos || bytes[first] != '{') throw Error(file + ": not a glTF JSON file (expected '{' at the start)");
    }
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) throw Error(file + ": larger than 4 GB");
    if (text::jsonDepth(jsonPart(bytes, binary)) > text::kMaxJsonDepth)
        throw Error(file + ": JSON nested deeper than " + std::to_string(text::kMaxJsonDepth) + " levels");
    checkGltfTypes(jsonPart(bytes, binary), file);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&loadImageChecked, nullptr);
    loader.SetFsCallbacks({&fileExists, &tinygltf::ExpandFilePath, &readWholeFileChecked, &tinygltf::WriteWholeFile, nullptr});
    tinygltf::Model model;
    std::string err, warn;
    const auto length = static_cast<unsigned int>(bytes.size());
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), length,
                                                  baseDir.string())
                    : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), length, baseDir.string());
    } catch (const std::exception& e) {
        // tinygltf can throw from inside its loader (found by fuzzing: a
        // buffer of byteLength 0 beside a BIN chunk reaches vector::at on
        // an empty vector); every such failure is this file's named error.
        throw Error(text::escapeControl(file + ": not a valid glTF file (the glTF loader failed: " + oneLine(e.what()) + ")"));
    }
    if (!ok) throw Error(text::escapeControl(file + ": " + (err.empty() ? std::string("failed to load glTF") : oneLine(err))));
    return GltfImporter(file, model).run();
}

} // namespace shadowlab
