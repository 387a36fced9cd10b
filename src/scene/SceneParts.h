#pragma once
// The parts of a scene file, each read from a Reader (SceneJson.h) in its
// own file: the camera (CameraFile.cpp); the lights, their paths and shadow
// options (LightFile.cpp); textures and materials (MaterialFile.cpp); shapes
// (ShapeFile.cpp); the nodes and their meshes (NodeFile.cpp). SceneFile.cpp
// reads a whole file through them. Private to the scene loader.
#include "scene/MeshFile.h"
#include "scene/SceneJson.h"

#include <shadowlab/Scene.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace shadowlab::scenefile {

/// `camera` into `cam`, whose values are the defaults (CameraFile.cpp).
void readCamera(const Reader& r, Camera& cam);

/// One of `lights` (LightFile.cpp).
Light readLight(const Reader& r);
/// The lights of `lightGrid` (LightGridFile.cpp), `lightsBefore` lights being in `lights`.
std::vector<Light> readLightGrid(const Reader& r, std::size_t lightsBefore);
/// The scene's `shadowAtlas` block (ShadowAtlasFile.cpp).
ShadowAtlasSettings readShadowAtlas(const Reader& r);

/// An image file named at `r`, as RGBA8 (MaterialFile.cpp).
ImageRGBA8 loadTexture(const Reader& r, const std::filesystem::path& file);

/// Triangles the procedural shapes and mesh files of one scene may hold in
/// all (2^24, about 2 GB with their GPU copy and the reference's BVH): a
/// scene file of a few kB must not ask for 70 GB through 400 finely divided
/// spheres. A mesh file named by several nodes counts once (it is shared).
constexpr std::size_t kMaxShapeTriangles = std::size_t(1) << 24;

/// A node's `shape`: a procedural mesh (ShapeFile.cpp). `trianglesLeft`:
/// what the scene's shapes may still make (kMaxShapeTriangles at first),
/// less this one's; a shape past it is refused (after it is made: one
/// shape is at most 2 x 1024 x 1024 triangles).
Mesh readShape(const Reader& r, std::size_t& trianglesLeft);

/// Builds the scene's materials and nodes: materials first, as nodes name
/// them. Materials are read in MaterialFile.cpp, nodes in NodeFile.cpp.
class SceneBuilder {
public:
    SceneBuilder(Scene& scene, const ParseContext& ctx) : scene_(scene), ctx_(ctx) {}

    void readMaterials(const Reader& r);
    void readNodes(const Reader& r, int parent);

    /// Every world transform and every transformed vertex must be finite:
    /// translations near 3e38 in a parent and a child, or a large scale on a
    /// large mesh, overflow only once composed.
    void checkFinite() const;

private:
    int material(const Reader& r) const;
    void readNode(const Reader& r, int parent);
    int addMesh(Mesh mesh);
    void importMesh(const Reader& r, int parent, int materialOverride, const Node& owner);

    Scene& scene_;
    const ParseContext& ctx_;
    std::map<std::string, int> materialIndex_;
    std::vector<std::string> nodeSources_; ///< JSON path (and mesh file node) per scene_.nodes entry
    std::size_t shapeTrianglesLeft_ = kMaxShapeTriangles;  ///< readShape's budget, and the mesh files'
    /// Mesh files read so far, by their canonical path: a file named by
    /// several nodes is read and its meshes, materials and textures added
    /// once (300 nodes naming one 69k-triangle OBJ made 300 copies, 6.6 GB);
    /// each node gets its own nodes over them.
    struct SharedFile {
        int meshBase = 0, materialBase = 0;
        std::vector<ImportedModel::Node> nodes;
    };
    std::map<std::string, SharedFile> meshFiles_;
};

} // namespace shadowlab::scenefile
