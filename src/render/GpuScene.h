#pragma once
// The scene's meshes and textures on the GPU.
#include "gl/Object.h"

#include <shadowlab/Scene.h>

#include <vector>

namespace shadowlab {

struct GpuMesh {
    gl::Buffer vertices;   ///< interleaved position, normal, uv
    gl::Buffer indices;
    gl::VertexArray vao;
    GLsizei indexCount = 0;
};

class GpuScene {
public:
    explicit GpuScene(const Scene& scene);
    /// Binds the mesh's vertex array and draws its triangles.
    void draw(int mesh) const;
    /// The texture for Scene::textures[i].
    const gl::Texture& texture(int i) const { return textures_[static_cast<std::size_t>(i)]; }
    std::size_t meshCount() const { return meshes_.size(); }

private:
    std::vector<GpuMesh> meshes_;
    std::vector<gl::Texture> textures_;
};

} // namespace shadowlab
