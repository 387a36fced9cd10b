// Technique "map": the opaque casters in one batch (passes/CasterBatch.h).
#include "techniques/map/passes/CasterBatch.h"

#include "gl/Calls.h"
#include "techniques/map/Cache.h"

#include <cstring>

namespace shadowlab::map {

namespace {

bool opaque(const Scene& scene, const DrawItem& item) {
    return item.material < 0 || !scene.materials[static_cast<std::size_t>(item.material)].alphaTested();
}

} // namespace

std::uint64_t casterInputs(const FrameInfo& frame) {
    Hash h;
    h.value(frame.sceneUpload);
    for (const DrawItem& item : frame.items) {
        h.value(item.mesh).value(item.material).value(static_cast<std::uint8_t>(item.castsShadows ? 1 : 0));
        h.value(item.worldFromObject);
    }
    return h.h;
}

void MapCasterBatch::update(const FrameInfo& frame) {
    const std::uint64_t inputs = casterInputs(frame);
    if (built_ && inputs == builtFor_) return;
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    first_.assign(frame.items.size(), 0);
    count_.assign(frame.items.size(), 0);
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        const DrawItem& item = frame.items[i];
        if (!item.castsShadows || item.mesh < 0 || !opaque(frame.scene, item)) continue;
        const Mesh& mesh = frame.scene.meshes[static_cast<std::size_t>(item.mesh)];
        const auto base = static_cast<std::uint32_t>(positions.size());
        for (const glm::vec3& p : mesh.positions) positions.push_back(glm::vec3(item.worldFromObject * glm::vec4(p, 1.0f)));
        first_[i] = static_cast<std::uint32_t>(indices.size());
        count_[i] = static_cast<std::uint32_t>(mesh.indices.size());
        for (std::uint32_t index : mesh.indices) indices.push_back(base + index);
    }
    vertices_ = gl::Buffer();
    gl::namedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(positions.size(), 1) * sizeof(glm::vec3)),
                         positions.empty() ? nullptr : positions.data(), 0);
    indices_ = gl::Buffer();
    gl::namedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(indices.size(), 1) * sizeof(std::uint32_t)),
                         indices.empty() ? nullptr : indices.data(), 0);
    vao_ = gl::VertexArray();
    gl::vertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(glm::vec3));
    gl::vertexArrayElementBuffer(vao_.id(), indices_.id());
    gl::enableVertexArrayAttrib(vao_.id(), 0);
    gl::vertexArrayAttribFormat(vao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    gl::vertexArrayAttribBinding(vao_.id(), 0, 0);
    builtFor_ = inputs;
    built_ = true;
}

std::size_t MapCasterBatch::draw(const gl::Program& program, const std::vector<std::size_t>& wanted) {
    counts_.clear();
    offsets_.clear();
    std::size_t triangles = 0;
    for (std::size_t i : wanted) {
        if (!holds(i)) continue;
        // Neighbouring items, one range: fewer draws for the rasteriser to set up.
        const auto offset = static_cast<std::size_t>(first_[i]) * sizeof(std::uint32_t);
        if (!offsets_.empty() && reinterpret_cast<std::size_t>(offsets_.back()) + static_cast<std::size_t>(counts_.back()) * sizeof(std::uint32_t) == offset)
            counts_.back() += static_cast<GLsizei>(count_[i]);
        else {
            counts_.push_back(static_cast<GLsizei>(count_[i]));
            offsets_.push_back(reinterpret_cast<const void*>(offset));
        }
        triangles += count_[i] / 3;
    }
    if (counts_.empty()) return 0;
    program.use();
    glBindVertexArray(vao_.id());
    gl::multiDrawElements(GL_TRIANGLES, counts_.data(), GL_UNSIGNED_INT, offsets_.data(), static_cast<GLsizei>(counts_.size()));
    glBindVertexArray(0);
    return triangles;
}

} // namespace shadowlab::map
