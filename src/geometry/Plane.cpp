#include "geometry/Plane.h"

#include <cmath>

namespace shadowlab {

std::optional<glm::vec4> meshPlane(const Mesh& mesh) {
    // The normal of the largest triangle, then every vertex checked against it.
    glm::vec3 normal(0.0f);
    float largest = 0.0f;
    glm::vec3 origin(0.0f);
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) bounds.add(p);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= mesh.positions.size() || b >= mesh.positions.size() || c >= mesh.positions.size()) return std::nullopt;
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        const float area = glm::length(n);
        if (area > largest) {
            largest = area;
            normal = n / area;
            origin = mesh.positions[a];
        }
    }
    if (!(largest > 0.0f) || bounds.empty()) return std::nullopt;
    const float tolerance = 1e-5f * glm::length(bounds.size());
    for (const glm::vec3& p : mesh.positions)
        if (!(std::fabs(glm::dot(normal, p - origin)) <= tolerance)) return std::nullopt;
    return glm::vec4(normal, -glm::dot(normal, origin));
}

std::vector<glm::vec4> convexPlanes(const Mesh& mesh, std::size_t maxTriangles) {
    std::vector<glm::vec4> planes;
    if (mesh.triangleCount() == 0 || mesh.triangleCount() > maxTriangles || meshPlane(mesh)) return planes;
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) bounds.add(p);
    const float tolerance = 1e-5f * glm::length(bounds.size());
    const glm::vec3 centre = bounds.centre();
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= mesh.positions.size() || b >= mesh.positions.size() || c >= mesh.positions.size()) return {};
        glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        const float len = glm::length(n);
        if (!(len > 0.0f)) continue;  // degenerate: no plane of its own
        n /= len;
        // Outwards: away from the bounds' centre (inside a convex mesh).
        if (glm::dot(n, mesh.positions[a] - centre) < 0.0f) n = -n;
        const glm::vec4 plane(n, -glm::dot(n, mesh.positions[a]));
        bool known = false;
        for (const glm::vec4& q : planes)
            if (glm::dot(glm::vec3(q), n) > 1.0f - 1e-6f && std::fabs(q.w - plane.w) <= tolerance) known = true;
        if (known) continue;
        for (const glm::vec3& p : mesh.positions)
            if (!(glm::dot(n, p) + plane.w <= tolerance)) return {};
        planes.push_back(plane);
    }
    return planes.size() >= 4 ? planes : std::vector<glm::vec4>{};
}

bool strictlyInside(const std::vector<glm::vec4>& planes, const glm::vec3& point, float margin) {
    if (planes.empty()) return false;
    for (const glm::vec4& p : planes)
        if (!(glm::dot(p, glm::vec4(point, 1.0f)) < -margin)) return false;
    return true;
}

bool boxInside(const std::vector<glm::vec4>& planes, const Bounds& box, float margin) {
    if (planes.empty() || box.empty()) return false;
    for (const glm::vec4& p : planes)
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
            if (!(glm::dot(p, glm::vec4(corner, 1.0f)) <= margin)) return false;
        }
    return true;
}

glm::vec4 transformPlane(const glm::vec4& plane, const glm::mat4& worldFromObject) {
    // Planes transform by the inverse transpose; renormalised.
    const glm::vec4 p = glm::transpose(glm::inverse(worldFromObject)) * plane;
    const float len = glm::length(glm::vec3(p));
    return len > 0.0f ? p / len : p;
}

bool reachesBehind(const glm::vec4& plane, const glm::vec4& towardsLight, const Bounds& box, float margin) {
    if (box.empty()) return false;
    // Orient the plane so that the light is on its positive side.
    const float lightSide = towardsLight.w != 0.0f ? glm::dot(plane, glm::vec4(glm::vec3(towardsLight), 1.0f))
                                                   : glm::dot(glm::vec3(plane), glm::vec3(towardsLight));
    if (lightSide == 0.0f) return false;  // the light in the plane (or grazing it): no shadow
    const glm::vec4 oriented = lightSide > 0.0f ? plane : -plane;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
        if (glm::dot(oriented, glm::vec4(corner, 1.0f)) < -margin) return true;
    }
    return false;
}

} // namespace shadowlab
