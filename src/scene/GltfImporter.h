#pragma once
// A parsed glTF model made shadowlab's (ImportedModel): its node graph
// checked and walked, its primitives' vertices and indices read with every
// offset checked, its materials and images (GltfImporter.cpp: the nodes;
// GltfData.cpp: primitives, materials, images). Internal to scene.
#include "scene/MeshFile.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::gltf {

class GltfImporter {
public:
    GltfImporter(std::string file, const tinygltf::Model& gltf) : file_(std::move(file)), gltf_(gltf) {}

    ImportedModel run();

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(text::escapeControl(file_ + ": " + what)); }

    std::string nodeName(int index) const;

    /// A glTF node graph is a forest (glTF 2.0, section 3.5.3): every child
    /// index in range, no node its own child, no node with two parents.
    void checkParents() const;

    /// Every node's composed transform must be finite (a translation of
    /// 1e300 becomes infinity as a float; 1e38 * 1e38 overflows).
    void checkFiniteWorld() const;

    static bool allFinite(const std::vector<double>& values);

    /// Appends node `index` to out_.nodes; returns its index there.
    int addNode(int index, int parent);

    /// Imports (once) primitive p of glTF mesh m; -1 if it has no triangles.
    int primitiveMesh(int m, int p);

    Mesh readPrimitive(const tinygltf::Mesh& src, const tinygltf::Primitive& prim, int p);

    /// Checks that accessor elements of `elementSize` bytes lie inside their
    /// buffer; returns the first byte and the stride (0 if no buffer view).
    std::pair<const unsigned char*, std::size_t> locate(const tinygltf::Accessor& acc, int index, const std::string& what, std::size_t elementSize) const;

    template <int N>
    std::vector<glm::vec<N, float>> readVectors(int index, const char* semantic) const;

    std::vector<std::uint32_t> readIndices(int index, std::size_t vertexCount) const;

    // A material as the glTF 2.0 spec allows it, no value clamped: the scene
    // JSON refuses the same values (MaterialFile.cpp).
    Material material(const tinygltf::Material& src, std::size_t index);

    /// A material's extras.shadowlab (a file shadowlab wrote, GltfExport.h):
    /// its Blinn-Phong ambient, diffuse, specular and shininess.
    void blinnPhongExtras(const tinygltf::Value& extras, const std::string& at, Material& m) const;

    /// Converts (once) image `index` to RGBA8 and returns its index in out_.textures.
    int image(int index);

    std::string file_;
    const tinygltf::Model& gltf_;
    ImportedModel out_;
    std::vector<bool> visited_;
    std::vector<int> sourceIndex_; ///< glTF node index of each out_.nodes entry
    std::map<std::pair<int, int>, int> meshCache_;
    std::map<int, int> imageCache_;
};

} // namespace shadowlab::gltf
