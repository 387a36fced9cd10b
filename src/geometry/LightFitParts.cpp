// The pieces the light cameras' fits share (LightFitParts.h).
#include "geometry/LightFitParts.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadowlab::fitparts {

Bounds all(const FitInput& in) {
    Bounds b;
    for (const Bounds& item : in.itemBounds) b.add(item);
    return b;
}

Bounds visibleReceivers(const FitInput& in, const glm::mat4& to) {
    Bounds b;
    for (std::size_t i = 0; i < in.items.size(); ++i)
        if (in.items[i].receivesShadows && mayIntersect(in.cameraClipFromWorld, in.itemBounds[i]))
            b.add(in.itemBounds[i].transformed(to));
    return b;
}

float diagonalOf(const Bounds& scene) { return scene.empty() ? 1.0f : std::max(glm::length(scene.size()), 1e-3f); }

glm::mat4 lightViewOf(const glm::vec3& direction, const Bounds& scene, float diagonal, const glm::vec3* up) {
    const glm::vec3 centre = scene.empty() ? glm::vec3(0.0f) : scene.centre();
    return glm::lookAt(centre - direction * diagonal, centre, up ? *up : lightCameraUp(direction));
}

LightCamera directionalView(const glm::vec3& direction, const FitInput& in, const Bounds& scene, float diagonal, const glm::vec3* up) {
    LightCamera cam;
    cam.viewFromWorld = lightViewOf(direction, scene, diagonal, up);
    cam.casts = castersThatMatter(glm::vec4(-direction, 0.0f), cam.viewFromWorld, in);
    return cam;
}


float nearestInPyramid(const Bounds& box, const glm::mat4& view, float tanX, float tanY) {
    if (box.distanceTo(glm::vec3(glm::inverse(view)[3])) <= 0.0f) return 0.0f;  // the apex is inside
    std::array<glm::vec3, 8> corner;
    for (int c = 0; c < 8; ++c) corner[static_cast<std::size_t>(c)] = glm::vec3(view * glm::vec4(box.corner(c), 1.0f));
    static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    // Inside where side(p, k) <= 0: +-x or +-y against tanHalf (-z).
    const auto side = [tanX, tanY](const glm::vec3& p, int k) { return k < 2 ? (k == 0 ? p.x : -p.x) + tanX * p.z : (k == 2 ? p.y : -p.y) + tanY * p.z; };
    float nearest = std::numeric_limits<float>::infinity();
    std::vector<glm::vec3> polygon, clipped;
    for (const auto& face : kFaces) {
        polygon.assign({corner[static_cast<std::size_t>(face[0])], corner[static_cast<std::size_t>(face[1])], corner[static_cast<std::size_t>(face[2])],
                        corner[static_cast<std::size_t>(face[3])]});
        for (int k = 0; k < 4 && !polygon.empty(); ++k) {  // Sutherland-Hodgman against side k
            clipped.clear();
            for (std::size_t v = 0; v < polygon.size(); ++v) {
                const glm::vec3 &a = polygon[v], &b = polygon[(v + 1) % polygon.size()];
                const float fa = side(a, k), fb = side(b, k);
                if (fa <= 0.0f) clipped.push_back(a);
                if ((fa < 0.0f) != (fb < 0.0f) && fa != fb) clipped.push_back(a + (b - a) * (fa / (fa - fb)));
            }
            polygon.swap(clipped);
        }
        for (const glm::vec3& p : polygon)
            if (p.z < 0.0f) nearest = std::min(nearest, -p.z);
    }
    return nearest;
}

} // namespace shadowlab::fitparts
