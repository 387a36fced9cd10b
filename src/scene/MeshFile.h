#pragma once
// Loading triangle meshes from files: Wavefront OBJ and glTF 2.0 (.gltf/.glb).
// Private to the library; the scene loader turns an ImportedModel into nodes.
#include <shadowlab/Scene.h>

#include <filesystem>
#include <string>
#include <string_view>

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
        bool castsShadows = true;    ///< glTF: the node's extras.shadowlab.castsShadows (GltfExport.h); default true
        bool receivesShadows = true; ///< glTF: the node's extras.shadowlab.receivesShadows; default true
    };
    std::vector<Mesh> meshes;
    std::vector<Material> materials;   ///< baseColorTexture indexes `textures`
    std::vector<ImageRGBA8> textures;
    std::vector<std::string> textureSources; ///< per texture, for messages: "image 0 ('name')"
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

/// The same from bytes in memory (the fuzz targets call these): `name`
/// names the file in errors, `baseDir` resolves a glTF's external URIs.
ImportedModel parseObj(std::string_view text, const std::string& name);
ImportedModel parseGltf(const std::string& bytes, const std::string& name, const std::filesystem::path& baseDir, bool binary);

/// Limits on what a mesh file may ask for, so a hostile count cannot
/// exhaust memory: elements per glTF accessor (a 16M-vertex mesh is already
/// 200 MB of positions), and decoded image size (64 Mpixel = 256 MB as RGBA8,
/// e.g. 8192x8192; at most 65536 per side).
constexpr std::size_t kMaxAccessorElements = std::size_t(1) << 24;
constexpr std::size_t kMaxImagePixels = std::size_t(1) << 26;
constexpr int kMaxImageSide = 65536;
/// Largest external file (glTF buffer or image URI) read: 1 GiB.
constexpr std::uintmax_t kMaxExternalFileBytes = std::uintmax_t(1) << 30;

namespace meshfile {
// Shared by the OBJ and glTF loaders.
std::string displayName(const std::filesystem::path& path);
/// Throws "<file>: file not found" (or not a regular file) before parsing.
void requireRegularFile(const std::filesystem::path& path);
std::string readWholeFile(const std::filesystem::path& path);
std::string lowercaseExtension(const std::filesystem::path& path);
/// Area-weighted vertex normals (see MeshFile.cpp).
std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);
} // namespace meshfile

} // namespace shadowlab
