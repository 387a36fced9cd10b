// Animation: a light's position and the camera's eye and target along their
// paths at a time (Scene.h). The scene file's `lights[i].path` and
// `camera.path` (docs/scene-format.md); the lecture's moving point light
// (Lawonn's lecture, "Omnidirectional Shadow Maps": lightPos.z = sin(t * 0.5) * 3)
// is a sine path with amplitude [0, 0, 3] and angular frequency 0.5.
#include <shadowlab/Scene.h>

#include <shadowlab/Error.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace shadowlab {

namespace {

void requireFinite(double seconds, const char* function) {
    if (!std::isfinite(seconds)) throw Error(std::string(function) + ": the time must be a finite number of seconds");
}

glm::vec3 lerp(const glm::vec3& a, const glm::vec3& b, double f) {
    // In double: keys far apart (1e38) must not overflow in b - a.
    const auto mix = [f](float x, float y) { return static_cast<float>(static_cast<double>(x) + (static_cast<double>(y) - x) * f); };
    return {mix(a.x, b.x), mix(a.y, b.y), mix(a.z, b.z)};
}

// Where `seconds` falls on a keyframe path: the keys before and after it and
// the weight of the one after (0 on the first key). Light and camera
// keyframes share it, so both clamp and loop alike.
struct KeySpan {
    std::size_t from = 0, to = 0;
    double weight = 0.0;
};

KeySpan keySpan(const std::vector<double>& times, bool loop, double seconds) {
    const double first = times.front(), last = times.back();
    double t = seconds;
    if (loop && last > first) {
        // Wrap into [first, last): the period is last - first, and the key at
        // `last` is where the next period's first key takes over.
        const double period = last - first;
        t = std::fmod(t - first, period);
        if (t < 0.0) t += period;
        t += first;
    }
    if (t <= first) return {0, 0, 0.0};
    if (t >= last) return {times.size() - 1, times.size() - 1, 0.0};
    // The segment [times[i-1], times[i]) holding t; times are strictly increasing.
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    return {i - 1, i, (t - times[i - 1]) / (times[i] - times[i - 1])};
}

// A keyframe path's keys must match its times; the scene file checks this,
// a path built in code is checked here.
void requireKeys(std::size_t times, std::size_t keys, const char* function, const char* what) {
    if (times == 0 || times != keys)
        throw Error(std::string(function) + ": a keyframe path needs at least one key and as many " + what + " as times (got " +
                    std::to_string(times) + " times, " + std::to_string(keys) + " " + what + ")");
}

} // namespace

glm::vec3 LightPath::positionAt(const glm::vec3& base, double seconds) const {
    requireFinite(seconds, "LightPath::positionAt");
    if (type == Type::Sine) {
        const double s = std::sin(angularFrequency * seconds + phase);
        return {static_cast<float>(base.x + amplitude.x * s), static_cast<float>(base.y + amplitude.y * s),
                static_cast<float>(base.z + amplitude.z * s)};
    }
    requireKeys(times.size(), positions.size(), "LightPath::positionAt", "positions");
    const KeySpan k = keySpan(times, loop, seconds);
    return lerp(positions[k.from], positions[k.to], k.weight);
}

std::pair<glm::vec3, glm::vec3> CameraPath::poseAt(double seconds) const {
    requireFinite(seconds, "CameraPath::poseAt");
    requireKeys(times.size(), positions.size(), "CameraPath::poseAt", "positions");
    requireKeys(times.size(), targets.size(), "CameraPath::poseAt", "targets");
    const KeySpan k = keySpan(times, loop, seconds);
    return {lerp(positions[k.from], positions[k.to], k.weight), lerp(targets[k.from], targets[k.to], k.weight)};
}

Light lightAtTime(const Light& light, double seconds) {
    requireFinite(seconds, "lightAtTime");
    Light out = light;
    if (!light.path) return out;
    out.position = light.path->positionAt(light.position, seconds);
    out.path.reset();  // static now: evaluating again must not move it twice
    return out;
}

Camera cameraAtTime(const Camera& camera, double seconds) {
    requireFinite(seconds, "cameraAtTime");
    Camera out = camera;
    if (!camera.path) return out;
    std::tie(out.position, out.target) = camera.path->poseAt(seconds);
    out.path.reset();  // static now, as lightAtTime leaves a light
    return out;
}

Scene sceneAtTime(const Scene& scene, double seconds) {
    requireFinite(seconds, "sceneAtTime");
    Scene out = scene;
    for (Light& light : out.lights) light = lightAtTime(light, seconds);
    out.camera = cameraAtTime(scene.camera, seconds);
    return out;
}

} // namespace shadowlab
