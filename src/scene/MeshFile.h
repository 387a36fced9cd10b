#pragma once
// Loading triangle meshes from files: Wavefront OBJ and glTF 2.0 (.gltf/.glb).
// Private to the library; the scene loader turns an ImportedModel into nodes.
#include <shadowlab/Scene.h>

#include <filesystem>

namespace shadowlab {

/// What a mesh file holds, in the file's own coordinates (glTF: metres, +Y up).
struct ImportedModel {
    struct Primitive {
        int mesh = -1;     ///< index into meshes
        int material = -1; ///< index into materials, -1 = none given by the file
    };
    struct Node {
        std::string name;
        int parent = -1;   ///< index into nodes, parents before children
        glm::vec3 translation{0.0f};
        glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
        glm::vec3 scale{1.0f};
        std::vector<Primitive> primitives;
    };
    std::vector<Mesh> meshes;
    std::vector<Material> materials;   ///< baseColorTexture indexes `textures`
    std::vector<ImageRGBA8> textures;
    std::vector<Node> nodes;
};

/// Loads .obj, .gltf or .glb by extension (case-insensitive). Throws
/// shadowlab::Error naming the file for: a missing or unreadable file, an
/// unknown extension, content that is not what the extension says (a .glb
/// without the glTF magic, malformed JSON, an OBJ with bad numbers or
/// out-of-range indices), non-finite coordinates, and a file with no triangles.
/// Missing normals are computed (area-weighted vertex normals for glTF,
/// OBJ faces without `vn` get flat face normals).
ImportedModel loadMeshFile(const std::filesystem::path& path);

ImportedModel loadObj(const std::filesystem::path& path);
ImportedModel loadGltf(const std::filesystem::path& path);

} // namespace shadowlab
