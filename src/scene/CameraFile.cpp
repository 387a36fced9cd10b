// The `camera` block of a scene file: position, target, up, field of view,
// near and far planes, and `camera.path`, the eye and target moving along
// keyframes. Every key, and every point between two keys, must give the
// camera a view direction.
#include "scene/SceneParts.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::scenefile {

namespace {

// Why a camera at `position` looking at `target` with `up` has no view
// direction, or "" when it has one.
std::string viewProblem(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 forward = target - position;
    if (!std::isfinite(glm::length(forward))) return "camera position and target are too far apart (their distance overflows a float)";
    if (glm::length(forward) < 1e-9f) return "camera position and target coincide";
    if (glm::length(glm::cross(glm::normalize(forward), up)) < 1e-6f) return "camera up is parallel to the view direction";
    return "";
}

// The distance from the origin to the segment [a, b], in double.
double closestToOrigin(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = b - a;
    const double dd = glm::dot(d, d);
    const double s = dd > 0.0 ? std::clamp(-glm::dot(a, d) / dd, 0.0, 1.0) : 0.0;
    return glm::length(a + s * d);
}

// `camera.path`: the eye and target moving along keyframes (CameraPath in
// Scene.h). Every key, and every point between two keys, must give the
// camera a view direction, as a static camera's position and target must.
CameraPath readCameraPath(const Reader& r, const glm::vec3& up) {
    r.requireObject();
    if (!r.has("type")) r.fail("missing key 'type' (keyframes)");
    const std::string type = r.child("type").string();
    if (type != "keyframes") r.child("type").fail("unknown path type '" + type + "' (a camera path has keyframes only)");
    r.checkKeys({"type", "times", "positions", "targets", "loop"});
    CameraPath path;
    path.times = readKeyTimes(r);
    path.positions = readKeyPoints(r, "positions", "position", path.times.size());
    path.targets = readKeyPoints(r, "targets", "target", path.times.size());
    path.loop = r.boolean("loop", path.loop);
    const Reader targets = r.child("targets");
    for (std::size_t i = 0; i < path.times.size(); ++i) {
        const std::string problem = viewProblem(path.positions[i], path.targets[i], up);
        if (!problem.empty()) targets.element(i).fail("key " + std::to_string(i) + ": " + problem);
    }
    // Between keys the view direction is the linear blend of the keys' own
    // (eye and target move linearly): it vanishes where that blend passes
    // the origin, and turns parallel to up where its cross product with up
    // does. That is measured against the longer key's length (|blend| is at
    // most that), so it is never looser than the per-key check above.
    for (std::size_t i = 1; i < path.times.size(); ++i) {
        const glm::dvec3 a(path.targets[i - 1] - path.positions[i - 1]), b(path.targets[i] - path.positions[i]), u(up);
        const double longer = std::max(glm::length(a), glm::length(b));
        const std::string between = "between keys " + std::to_string(i - 1) + " and " + std::to_string(i) + " the camera ";
        if (closestToOrigin(a, b) < 1e-9)
            targets.element(i).fail(between + "passes through its target (add a key in between)");
        if (closestToOrigin(glm::cross(a, u), glm::cross(b, u)) < 1e-6 * longer)
            targets.element(i).fail(between + "looks along camera up (add a key in between, or change up)");
    }
    return path;
}

} // namespace

void readCamera(const Reader& r, Camera& cam) {
    r.checkKeys({"position", "target", "up", "fovY", "orthoHeight", "near", "far", "path"});
    cam.position = r.vec3("position", cam.position);
    cam.target = r.vec3("target", cam.target);
    cam.up = r.direction("up", cam.up);
    cam.fovYDeg = r.positive("fovY", cam.fovYDeg);
    if (cam.fovYDeg >= 180.0f) r.child("fovY").fail("expected degrees in (0, 180), got " + Reader::fmt(cam.fovYDeg));
    cam.orthoHeight = r.nonNegative("orthoHeight", cam.orthoHeight);
    cam.nearPlane = r.positive("near", cam.nearPlane);
    cam.farPlane = r.positive("far", cam.farPlane);
    if (cam.farPlane <= cam.nearPlane)
        (r.has("far") ? r.child("far") : r).fail("expected far > near (" + Reader::fmt(cam.nearPlane) + ")");
    if (const std::string problem = viewProblem(cam.position, cam.target, cam.up); !problem.empty()) r.fail(problem);
    if (r.has("path")) cam.path = readCameraPath(r.child("path"), cam.up);
}

} // namespace shadowlab::scenefile
