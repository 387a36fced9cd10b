#pragma once
// The scene's meshes and textures on the GPU.
#include "core/Bounds.h"
#include "core/MeshLevels.h"
#include "geometry/MeshTwins.h"
#include "core/TriangleOrder.h"
#include "gl/Object.h"

#include <shadowlab/Scene.h>

#include <optional>
#include <vector>

namespace shadowlab {

struct GpuMesh {
    gl::Buffer vertices;   ///< interleaved position, normal, uv (in remap's order)
    gl::Buffer indices;
    gl::VertexArray vao;
    GLsizei indexCount = 0;
    /// A dense mesh's vertices are numbered in the buffers as its triangles,
    /// in spatial order, first use them (core/TriangleOrder.h): per vertex of
    /// Scene::meshes[mesh], its number here; empty: the scene's own numbers.
    std::vector<std::uint32_t> remap;
    Bounds bounds;                 ///< object space
    std::optional<glm::vec4> plane; ///< object space, when the mesh is planar (geometry/Plane.h)
    std::vector<glm::vec4> convex;  ///< object space, the planes of a convex mesh (geometry/Plane.h); empty otherwise
    int winding = 0;                ///< closed: +1, counter-clockwise sides out; -1, in; open: 0 (core/Adjacency.h: closedWinding)
    gl::Buffer adjacency{gl::NoCreate}; ///< GL_TRIANGLES_ADJACENCY indices, built on first use
    gl::VertexArray adjacencyArray{gl::NoCreate};
    /// Coarser levels for depth passes (core/MeshLevels.h), built on first use:
    /// their indices one after another in `levelIndices` (in remap's
    /// numbering; an identical mesh copies it), drawn through `levelArray`.
    bool levelsBuilt = false;
    std::vector<DetailLevel> levels;
    std::vector<GLsizei> levelFirst; ///< each level's first index in levelIndices
    gl::Buffer levelIndices{gl::NoCreate};
    gl::VertexArray levelArray{gl::NoCreate};
};

class GpuScene {
public:
    explicit GpuScene(const Scene& scene);
    /// Binds the mesh's vertex array and draws its triangles.
    void draw(int mesh) const;
    /// Draws the mesh as GL_TRIANGLES_ADJACENCY (builds the indices on
    /// first use from `source`, the uploaded Scene::meshes[mesh]).
    void drawAdjacency(int mesh, const Mesh& source);
    /// The mesh's GL_TRIANGLES_ADJACENCY index buffer (built on first use).
    const gl::Buffer& adjacencyIndices(int mesh, const Mesh& source);
    /// The coarser levels of Scene::meshes[mesh] for depth passes, finest
    /// first (core/MeshLevels.h: none for a small mesh), built on first use,
    /// or taken from an earlier mesh of `scene` with the same positions and
    /// indices (a file's mesh loaded for several nodes).
    const std::vector<DetailLevel>& levels(int mesh, const Scene& scene);
    /// Draws level `level` of the mesh (0: the mesh itself; k: levels()[k - 1], built by then).
    void drawLevel(int mesh, int level) const;
    /// Object-space bounds of Scene::meshes[mesh].
    const Bounds& bounds(int mesh) const { return meshes_[static_cast<std::size_t>(mesh)].bounds; }
    /// Object-space plane of Scene::meshes[mesh] when it is planar.
    const std::optional<glm::vec4>& plane(int mesh) const { return meshes_[static_cast<std::size_t>(mesh)].plane; }
    /// Object-space planes of Scene::meshes[mesh] when it is convex (small meshes only), else empty.
    const std::vector<glm::vec4>& convex(int mesh) const { return meshes_[static_cast<std::size_t>(mesh)].convex; }
    /// Which way Scene::meshes[mesh] winds when it is closed (closedWinding: +1, -1), 0 when it is not.
    int winding(int mesh) const { return meshes_[static_cast<std::size_t>(mesh)].winding; }
    /// The texture for Scene::textures[i].
    const gl::Texture& texture(int i) const { return textures_[static_cast<std::size_t>(i)]; }
    std::size_t meshCount() const { return meshes_.size(); }

private:
    std::vector<GpuMesh> meshes_;
    std::vector<gl::Texture> textures_;
    MeshTwins levelTwins_; ///< the meshes that built their own levels (levels())
};

} // namespace shadowlab
