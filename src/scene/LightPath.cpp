// Animated lights: a light's position along its path at a time (Scene.h).
// The scene file's `lights[i].path` (docs/scene-format.md); the lecture's
// moving point light (lecture 001, "Omnidirectional Shadow Maps": lightPos.z
// = sin(t * 0.5) * 3) is a sine path with amplitude [0, 0, 3] and angular
// frequency 0.5.
#include <shadowlab/Scene.h>

#include <shadowlab/Error.h>

#include <algorithm>
#include <cmath>
#include <string>

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

} // namespace

glm::vec3 LightPath::positionAt(const glm::vec3& base, double seconds) const {
    requireFinite(seconds, "LightPath::positionAt");
    if (type == Type::Sine) {
        const double s = std::sin(angularFrequency * seconds + phase);
        return {static_cast<float>(base.x + amplitude.x * s), static_cast<float>(base.y + amplitude.y * s),
                static_cast<float>(base.z + amplitude.z * s)};
    }
    if (times.empty() || times.size() != positions.size())
        throw Error("LightPath::positionAt: a keyframe path needs at least one key and as many positions as times (got " +
                    std::to_string(times.size()) + " times, " + std::to_string(positions.size()) + " positions)");
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
    if (t <= first) return positions.front();
    if (t >= last) return positions.back();
    // The segment [times[i-1], times[i]) holding t; times are strictly increasing.
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    const double f = (t - times[i - 1]) / (times[i] - times[i - 1]);
    return lerp(positions[i - 1], positions[i], f);
}

Light lightAtTime(const Light& light, double seconds) {
    requireFinite(seconds, "lightAtTime");
    Light out = light;
    if (!light.path) return out;
    out.position = light.path->positionAt(light.position, seconds);
    out.path.reset();  // static now: evaluating again must not move it twice
    return out;
}

Scene sceneAtTime(const Scene& scene, double seconds) {
    requireFinite(seconds, "sceneAtTime");
    Scene out = scene;
    for (Light& light : out.lights) light = lightAtTime(light, seconds);
    return out;
}

} // namespace shadowlab
