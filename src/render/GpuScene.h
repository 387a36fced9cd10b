#pragma once
// The scene's meshes and textures on the GPU.
#include "core/Bounds.h"
#include "gl/Object.h"

#include <shadowlab/Scene.h>

#include <optional>
#include <vector>

namespace shadowlab {

struct GpuMesh {
    gl::Buffer vertices;   ///< interleaved position, normal, uv
    gl::Buffer indices;
    gl::VertexArray vao;
    GLsizei indexCount = 0;
    Bounds bounds;                 ///< object space
    std::optional<glm::vec4> plane; ///< object space, when the mesh is planar (core/Plane.h)
    std::vector<glm::vec4> convex;  ///< object space, the planes of a convex mesh (core/Plane.h); empty otherwise
    int winding = 0;                ///< closed: +1, counter-clockwise sides out; -1, in; open: 0 (core/Adjacency.h: closedWinding)
    gl::Buffer adjacency{gl::NoCreate}; ///< GL_TRIANGLES_ADJACENCY indices, built on first use
    gl::VertexArray adjacencyArray{gl::NoCreate};
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
};

} // namespace shadowlab
