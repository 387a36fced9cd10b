#include <shadowlab/Scene.h>

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

namespace shadowlab {

glm::mat4 Camera::viewFromWorld() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::clipFromView(float aspect) const {
    return glm::perspective(glm::radians(fovYDeg), aspect, nearPlane, farPlane);
}

glm::mat4 Camera::clipFromViewInfiniteFar(float aspect) const {
    // glm::perspective with f -> inf: m[2][2] = -(f+n)/(f-n) -> -1,
    // m[3][2] = -2fn/(f-n) -> -2n (OpenGL depth range [-1, 1]).
    glm::mat4 m = clipFromView(aspect);
    m[2][2] = -1.0f;
    m[3][2] = -2.0f * nearPlane;
    return m;
}

glm::mat4 Node::parentFromLocal() const {
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

std::vector<DrawItem> Scene::drawItems() const {
    std::vector<glm::mat4> worldFromNode(nodes.size());
    std::vector<DrawItem> items;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Node& node = nodes[i];
        const glm::mat4 local = node.parentFromLocal();
        // Parents come before their children, so the parent's matrix is ready.
        worldFromNode[i] = node.parent >= 0 ? worldFromNode[static_cast<std::size_t>(node.parent)] * local : local;
        if (node.mesh < 0) continue;
        items.push_back({node.mesh, node.material, static_cast<int>(i), worldFromNode[i], node.castsShadows,
                         node.receivesShadows});
    }
    return items;
}

std::pair<glm::vec3, glm::vec3> Scene::worldBounds() const {
    constexpr float inf = std::numeric_limits<float>::infinity();
    glm::vec3 lo(inf), hi(-inf);
    for (const DrawItem& item : drawItems()) {
        for (const glm::vec3& p : meshes[static_cast<std::size_t>(item.mesh)].positions) {
            const glm::vec3 w = glm::vec3(item.worldFromObject * glm::vec4(p, 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    }
    return {lo, hi};
}

const char* toString(LightType t) {
    switch (t) {
    case LightType::Directional: return "directional";
    case LightType::Spot: return "spot";
    case LightType::Point: return "point";
    }
    return "?";
}

} // namespace shadowlab
