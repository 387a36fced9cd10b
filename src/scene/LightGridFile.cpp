// The scene file's `lightGrid`: many lights generated from a seed, spread
// evenly over a floor rectangle (docs/scene-format.md). Each generated
// light is read as a `lights[i]` entry made of the grid's `light` template,
// so every check and error of a light applies, named at `lightGrid.light`.
#include "scene/SceneParts.h"

#include <shadowlab/SceneFile.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace shadowlab::scenefile {

using nlohmann::json;

namespace {

// Uniform in [0, 1) from the generator's next 24 bits: the same on every
// platform (std::mt19937's sequence is specified, its distributions are not).
float unit(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

// A saturated colour of hue h in [0, 1), brightest channel 1.
glm::vec3 hue(float h) {
    const glm::vec3 k = glm::abs(glm::fract(glm::vec3(h) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f);
    return glm::mix(glm::vec3(1.0f), glm::clamp(k - 1.0f, 0.0f, 1.0f), 0.6f);
}

glm::vec2 corner(const Reader& r, const char* key, glm::vec2 def) {
    if (!r.has(key)) return def;
    const Reader c = r.child(key);
    if (!c.value().is_array() || c.value().size() != 2) c.fail(std::string("expected [x, z], got ") + overrides::typeName(c.value()));
    return {c.element(0).number(), c.element(1).number()};
}

} // namespace

std::vector<Light> readLightGrid(const Reader& r, std::size_t lightsBefore) {
    r.requireObject();
    r.checkKeys({"count", "seed", "min", "max", "height", "spots", "light"});
    const int room = static_cast<int>(kMaxLights - std::min(lightsBefore, kMaxLights));
    if (r.has("count") && r.child("count").value().is_number() && r.child("count").value().get<double>() > room)
        r.child("count").fail("expected at most " + std::to_string(room) + " lights (at most " + std::to_string(kMaxLights) +
                              " in a scene, " + std::to_string(lightsBefore) + " in `lights`), got " + Reader::fmt(r.child("count").value().get<double>()));
    const int count = r.integer("count", 64, 0, room);
    const int seed = r.integer("seed", 1, 0, 2147483647);
    const glm::vec2 lo = corner(r, "min", {-10.0f, -10.0f}), hi = corner(r, "max", {10.0f, 10.0f});
    if (!(hi.x > lo.x && hi.y > lo.y)) (r.has("max") ? r.child("max") : r).fail("expected max > min in x and z");
    const float height = r.number("height", 2.0f);
    const float spots = r.has("spots") ? r.child("spots").number() : 0.5f;
    if (!(spots >= 0.0f && spots <= 1.0f)) r.child("spots").fail("expected a share in 0..1, got " + Reader::fmt(spots));
    json base = json::object();
    if (r.has("light")) {
        const Reader l = r.child("light");
        l.requireObject();
        l.checkKeys({"name", "color", "intensity", "range", "innerCone", "outerCone", "direction", "size", "shadow", "path"});
        // A sine path moves each light about its own place; keyframes would take them all to the same places.
        if (l.has("path") && l.child("path").value().is_object() && l.child("path").value().value("type", std::string()) != "sine")
            l.child("path").fail("expected a path of type \"sine\" (each light moves about its own place; keyframes would take every light to the same points)");
        base = l.value();
    }
    if (!base.contains("range")) base["range"] = 4.0;

    // Stratified: the rectangle in cells about as square as it allows, one
    // light in each of `count` cells picked in a seeded order, at a seeded
    // place inside its cell.
    std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
    const glm::vec2 extent = hi - lo;
    const int across = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<float>(count) * extent.x / extent.y))));
    const int down = std::max(1, (count + across - 1) / across);
    std::vector<int> cells(static_cast<std::size_t>(across * down));
    for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = static_cast<int>(i);
    for (std::size_t i = cells.size(); i > 1; --i) std::swap(cells[i - 1], cells[rng() % i]);
    const int spotCount = static_cast<int>(std::lround(spots * static_cast<float>(count)));

    std::vector<Light> out;
    out.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        const int cell = cells[static_cast<std::size_t>(k)];
        const float u = (static_cast<float>(cell % across) + unit(rng)) / static_cast<float>(across);
        const float v = (static_cast<float>(cell / across) + unit(rng)) / static_cast<float>(down);
        const float h = unit(rng);
        json light = base;
        const bool spot = k < spotCount;
        light["type"] = spot ? "spot" : "point";
        light["position"] = {lo.x + u * extent.x, height, lo.y + v * extent.y};
        if (!light.contains("name")) light["name"] = std::string(spot ? "spot " : "point ") + std::to_string(k);
        if (!light.contains("color")) {
            const glm::vec3 c = hue(h);
            light["color"] = {c.r, c.g, c.b};
        }
        if (spot && !light.contains("direction")) light["direction"] = {0.0, -1.0, 0.0};
        if (!spot) {
            light.erase("direction");
            light.erase("innerCone");
            light.erase("outerCone");
        }
        out.push_back(readLight(Reader(r.context(), light, r.path() + ".light")));
    }
    return out;
}

} // namespace shadowlab::scenefile
