#include "render/GpuScene.h"

#include "core/Adjacency.h"
#include "core/MeshLevels.h"
#include "geometry/MeshTwins.h"
#include "geometry/Plane.h"
#include "core/TriangleOrder.h"
#include "gl/Calls.h"

#include <shadowlab/Error.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace shadowlab {

namespace {
// Meshes with at least this many triangles are drawn in spatial order.
constexpr std::size_t kSpatialOrderTriangles = 1024;

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};
// Attributes 0 position, 1 normal, 2 uv (scene.vert) from `vertices`, indices from `indices`.
void describeVertices(const gl::VertexArray& array, const gl::Buffer& vertices, const gl::Buffer& indices) {
    const GLuint vao = array.id();
    gl::vertexArrayVertexBuffer(vao, 0, vertices.id(), 0, sizeof(Vertex));
    gl::vertexArrayElementBuffer(vao, indices.id());
    const GLuint offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv)};
    const GLint sizes[] = {3, 3, 2};
    for (GLuint a = 0; a < 3; ++a) {
        gl::enableVertexArrayAttrib(vao, a);
        gl::vertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        gl::vertexArrayAttribBinding(vao, a, 0);
    }
}
} // namespace

GpuScene::GpuScene(const Scene& scene) {
    for (const Mesh& mesh : scene.meshes) {
        GpuMesh gpu;
        // A dense mesh's triangles in spatial order over its vertices
        // renumbered as they are first used, for the vertex stage's cache
        // (core/TriangleOrder.h: the same triangles, the same image).
        DrawOrder order;
        if (mesh.triangleCount() >= kSpatialOrderTriangles) {
            order = spatialDrawOrder(mesh.positions, mesh.indices);
            gpu.remap = order.remap;
        } else {
            order.indices = mesh.indices;
        }
        std::vector<Vertex> vertices(mesh.positions.size());
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            Vertex& v = vertices[gpu.remap.empty() ? i : gpu.remap[i]];
            v.position = mesh.positions[i];
            v.normal = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
            v.uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
        }
        gl::namedBufferStorage(gpu.vertices.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(1, vertices.size()) * sizeof(Vertex)),
                             vertices.empty() ? nullptr : vertices.data(), 0);
        const std::vector<std::uint32_t>& ordered = order.indices;
        gl::namedBufferStorage(gpu.indices.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(1, ordered.size()) * 4),
                             ordered.empty() ? nullptr : ordered.data(), 0);
        describeVertices(gpu.vao, gpu.vertices, gpu.indices);
        gpu.indexCount = static_cast<GLsizei>(ordered.size());
        for (const glm::vec3& p : mesh.positions) gpu.bounds.add(p);
        gpu.plane = meshPlane(mesh);
        gpu.convex = convexPlanes(mesh);
        gpu.winding = closedWinding(mesh.positions, mesh.indices);
        meshes_.push_back(std::move(gpu));
    }
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    for (const ImageRGBA8& image : scene.textures) {
        const std::size_t i = textures_.size();
        // Name where the texture came from (file and JSON path) when the scene says.
        const std::string source = i < scene.textureSources.size() ? scene.textureSources[i] + ": " : std::string();
        if (image.width < 1 || image.height < 1 || image.width > maxSize || image.height > maxSize)
            throw Error(source + "texture " + std::to_string(i) + " (" + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + "): expected 1.." + std::to_string(maxSize) +
                        " texels per side (this GPU's limit)");
        gl::Texture texture(GL_TEXTURE_2D);
        const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
        gl::textureStorage2D(texture.id(), levels, GL_SRGB8_ALPHA8, image.width, image.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        // Scene images are stored top row first; GL's t = 0 is the first row
        // uploaded, which matches glTF's uv convention (v = 0 at the top).
        gl::textureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
        gl::generateTextureMipmap(texture.id());
        gl::textureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        gl::textureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl::textureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        gl::textureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
        textures_.push_back(std::move(texture));
    }
}

const gl::Buffer& GpuScene::adjacencyIndices(int mesh, const Mesh& source) {
    GpuMesh& m = meshes_[static_cast<std::size_t>(mesh)];
    if (!m.adjacency) {
        std::vector<std::uint32_t> indices = shadowlab::adjacencyIndices(source.positions, source.indices);
        for (std::uint32_t& i : indices)
            if (!m.remap.empty()) i = m.remap[i];  // the buffer's vertex numbers
        m.adjacency = gl::Buffer();
        gl::namedBufferStorage(m.adjacency.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(1, indices.size()) * 4),
                             indices.empty() ? nullptr : indices.data(), 0);
        // A second vertex array: same vertices, the adjacency indices.
        m.adjacencyArray = gl::VertexArray();
        describeVertices(m.adjacencyArray, m.vertices, m.adjacency);
    }
    return m.adjacency;
}

void GpuScene::drawAdjacency(int mesh, const Mesh& source) {
    adjacencyIndices(mesh, source);
    const GpuMesh& m = meshes_[static_cast<std::size_t>(mesh)];
    glBindVertexArray(m.adjacencyArray.id());
    glDrawElements(GL_TRIANGLES_ADJACENCY, m.indexCount * 2, GL_UNSIGNED_INT, nullptr);
}

const std::vector<DetailLevel>& GpuScene::levels(int mesh, const Scene& scene) {
    GpuMesh& m = meshes_[static_cast<std::size_t>(mesh)];
    if (m.levelsBuilt) return m.levels;
    m.levelsBuilt = true;
    const Mesh& source = scene.meshes[static_cast<std::size_t>(mesh)];
    // A mesh too small for levels has none to build or share.
    if (source.triangleCount() < MeshLevelOptions{}.minTriangles) return m.levels;
    // A mesh identical to one whose levels are built (a file's mesh loaded
    // for several nodes) shares them (geometry/MeshTwins.h: by a hash).
    const int same = levelTwins_.findOrAdd(mesh, scene.meshes);
    if (same >= 0) {
        // Its index buffer numbers the vertices as this mesh's buffer does
        // (the same positions and indices make the same remap): copied on
        // the GPU.
        const GpuMesh& twin = meshes_[static_cast<std::size_t>(same)];
        m.levels = twin.levels;
        m.levelFirst = twin.levelFirst;
        if (!m.levels.empty()) {
            const auto bytes = static_cast<GLsizeiptr>((static_cast<std::size_t>(m.levelFirst.back()) + m.levels.back().triangles * 3) * 4);
            m.levelIndices = gl::Buffer();
            gl::namedBufferStorage(m.levelIndices.id(), bytes, nullptr, 0);
            gl::copyNamedBufferSubData(twin.levelIndices.id(), m.levelIndices.id(), 0, 0, bytes);
        }
    } else {
        // The levels one after another, in the buffer's numbering (m.remap's).
        std::vector<MeshLevel> built = meshLevels(source.positions, source.indices);
        std::size_t total = 0;
        for (const MeshLevel& level : built) total += level.indices.size();
        std::vector<std::uint32_t> data;
        data.reserve(total);
        for (MeshLevel& level : built) {
            m.levelFirst.push_back(static_cast<GLsizei>(data.size()));
            m.levels.push_back({level.error, level.indices.size() / 3});
            for (const std::uint32_t i : level.indices) data.push_back(m.remap.empty() ? i : m.remap[i]);
            level.indices = {};
        }
        if (!data.empty()) {
            m.levelIndices = gl::Buffer();
            gl::namedBufferStorage(m.levelIndices.id(), static_cast<GLsizeiptr>(data.size() * 4), data.data(), 0);
        }
    }
    if (!m.levels.empty()) {
        m.levelArray = gl::VertexArray();
        describeVertices(m.levelArray, m.vertices, m.levelIndices);
    }
    return m.levels;
}

void GpuScene::drawLevel(int mesh, int level) const {
    if (level <= 0) return draw(mesh);
    const GpuMesh& m = meshes_[static_cast<std::size_t>(mesh)];
    const auto k = static_cast<std::size_t>(level - 1);
    glBindVertexArray(m.levelArray.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m.levels[k].triangles * 3), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(m.levelFirst[k]) * 4u));
}

void GpuScene::draw(int mesh) const {
    const GpuMesh& m = meshes_[static_cast<std::size_t>(mesh)];
    glBindVertexArray(m.vao.id());
    glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
}

} // namespace shadowlab
