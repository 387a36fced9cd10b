#include <shadowlab/Scene.h>

#include <shadowlab/Error.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

glm::mat4 Camera::viewFromWorld() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::clipFromView(float aspect) const {
    if (orthoHeight > 0.0f) {
        const float h = 0.5f * orthoHeight, w = h * aspect;
        return glm::ortho(-w, w, -h, h, nearPlane, farPlane);
    }
    return glm::perspective(glm::radians(fovYDeg), aspect, nearPlane, farPlane);
}

glm::mat4 Camera::clipFromViewInfiniteFar(float aspect) const {
    if (orthoHeight > 0.0f) return clipFromView(aspect);  // no far plane at infinity: Renderer refuses volumes with it
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

glm::vec3 lightCameraUp(const glm::vec3& axis) {
    return std::abs(axis.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

Camera cameraFromLight(const Scene& scene, const Light& light) {
    if (light.type == LightType::Point) throw Error("light '" + light.name + "': a point light has no single view (it has six)");
    const glm::vec3 axis = glm::normalize(light.direction);
    auto [lo, hi] = scene.worldBounds();
    if (!(lo.x <= hi.x)) lo = hi = glm::vec3(0.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    Camera cam;
    cam.up = lightCameraUp(axis);
    if (light.type == LightType::Spot) {
        cam.position = light.position;
        cam.fovYDeg = std::min(2.0f * light.outerConeDeg, 170.0f);
        const float distance = glm::length(centre - light.position);
        cam.farPlane = distance + radius;
        cam.nearPlane = std::max(cam.farPlane * 1e-4f, 1e-3f);
    } else {
        // From outside the bounds, a narrow view that just contains them.
        const float distance = 4.0f * radius;
        cam.position = centre - axis * distance;
        cam.fovYDeg = glm::degrees(2.0f * std::asin(std::min(radius / distance, 1.0f)));
        cam.nearPlane = distance - radius;
        cam.farPlane = distance + radius;
    }
    cam.target = cam.position + axis;
    return cam;
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
