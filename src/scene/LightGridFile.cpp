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

// k's digits in `base` mirrored about the point: 0.d0 d1 d2... (the van der
// Corput sequence; Halton's in two bases).
double radicalInverse(int k, int base) {
    double result = 0.0, scale = 1.0 / base;
    for (; k > 0; k /= base, scale /= base) result += scale * (k % base);
    return result;
}

glm::vec2 corner(const Reader& r, const char* key, glm::vec2 def) {
    if (!r.has(key)) return def;
    const Reader c = r.child(key);
    if (!c.value().is_array() || c.value().size() != 2) c.fail(std::string("expected [x, z], got ") + overrides::typeName(c.value()));
    return {c.element(0).number(), c.element(1).number()};
}

// lightGrid.count: at most the lights the scene has room for beside the
// `lightsBefore` in `lights` (its default too).
int gridCount(const Reader& r, std::size_t lightsBefore) {
    const int room = static_cast<int>(kMaxLights - std::min(lightsBefore, kMaxLights));
    if (r.has("count") && r.child("count").value().is_number() && r.child("count").value().get<double>() > room)
        r.child("count").fail("expected at most " + std::to_string(room) + " lights (at most " + std::to_string(kMaxLights) +
                              " in a scene, " + std::to_string(lightsBefore) + " in `lights`), got " + Reader::fmt(r.child("count").value().get<double>()));
    const int count = r.integer("count", 64, 0, room);
    // Unwritten, the default must fit too (64 grid lights beside 256 in `lights` made 320).
    if (!r.has("count") && count > room)
        r.fail("count: not given, and its default " + std::to_string(count) + " is more than the " + std::to_string(room) + " lights left (at most " +
               std::to_string(kMaxLights) + " in a scene, " + std::to_string(lightsBefore) + " in `lights`); give lightGrid.count");
    return count;
}

// lightGrid.min and max: a rectangle, its sides within a float's range.
void checkRectangle(const Reader& r, glm::vec2 lo, glm::vec2 hi) {
    // A bad rectangle is blamed on the corner a --set changed, not on the
    // file's other one (--set lightGrid.min=[24,12] was blamed on the file's max).
    const auto failCorner = [&](const std::string& why) {
        const bool minSet = r.has("min") && overrides::overrideAt(r.context().overrides, r.path() + ".min");
        const bool maxSet = r.has("max") && overrides::overrideAt(r.context().overrides, r.path() + ".max");
        const char* key = minSet && !maxSet ? "min" : "max";
        (r.has(key) ? r.child(key) : r).fail(why);
    };
    if (!(hi.x > lo.x && hi.y > lo.y)) failCorner("expected max > min in x and z");
    // Each corner within a float's range, their difference too (min -3e38, max
    // 3e38 made the lights' positions infinite, blamed on lightGrid.light.position).
    if (!std::isfinite(hi.x - lo.x) || !std::isfinite(hi.y - lo.y))
        failCorner(std::string("the rectangle's side max - min is past a float's range of 3e38 in ") + (std::isfinite(hi.x - lo.x) ? "z" : "x"));
}

// lightGrid.light: what every grid light starts from (range 4 unless given).
json lightTemplate(const Reader& r) {
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
    return base;
}

} // namespace

std::vector<Light> readLightGrid(const Reader& r, std::size_t lightsBefore) {
    r.requireObject();
    r.checkKeys({"count", "seed", "min", "max", "height", "spots", "light"});
    const int count = gridCount(r, lightsBefore);
    const int seed = r.integer("seed", 1, 0, 2147483647);
    const glm::vec2 lo = corner(r, "min", {-10.0f, -10.0f}), hi = corner(r, "max", {10.0f, 10.0f});
    checkRectangle(r, lo, hi);
    const float height = r.number("height", 2.0f);
    const float spots = r.has("spots") ? r.child("spots").number() : 0.5f;
    if (!(spots >= 0.0f && spots <= 1.0f)) r.child("spots").fail("expected a share in 0..1, got " + Reader::fmt(spots));
    const json base = lightTemplate(r);

    // Nested and even: light k at the k-th point of the Halton sequence in
    // bases 3 (along x) and 5 (along z), moved by a seeded offset (modulo
    // the rectangle). Light k's place, kind and colour depend on k and the
    // seed alone, so that a count's lights are the first of twice as many:
    // doubling the count adds lights between them, and every count covers
    // the rectangle about evenly (no cell of a grid left empty). Not base 2:
    // its first digit is k's parity, which alternates the kinds below, and
    // would put every spot in one half of the rectangle.
    std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
    const glm::vec2 extent = hi - lo;
    const double offsetU = unit(rng), offsetV = unit(rng), offsetHue = unit(rng);
    // Spots interleaved with the points (k is a spot when the rounded count
    // of spots among the first k + 1 grows), round(spots x n) of the first n.
    const auto spotsAmong = [&](int n) { return static_cast<int>(std::floor(static_cast<double>(spots) * n + 0.5)); };

    std::vector<Light> out;
    out.reserve(static_cast<std::size_t>(count));
    bool madeSpot = false, madePoint = false;
    // Light k of the grid (k past the count: a probe of the template, checked and dropped).
    const auto make = [&](int k, bool spot) {
        const double n = static_cast<double>(k);
        const float u = static_cast<float>(std::fmod(offsetU + radicalInverse(k, 3), 1.0));
        const float v = static_cast<float>(std::fmod(offsetV + radicalInverse(k, 5), 1.0));
        const float h = static_cast<float>(std::fmod(offsetHue + n * 0.6180339887498949, 1.0));
        json light = base;
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
        return readLight(Reader(r.context(), light, r.path() + ".light"));
    };
    for (int k = 0; k < count; ++k) {
        const bool spot = spotsAmong(k + 1) > spotsAmong(k);
        (spot ? madeSpot : madePoint) = true;
        out.push_back(make(k, spot));
    }
    // The template is checked as each kind it would make even when the
    // count (or the spots' share) makes none of it: a file that is fine at
    // count 0 and fails at count 1 hid its error (technique "bogus", size 7).
    if (!madeSpot) make(count, true);
    if (!madePoint) make(count, false);
    return out;
}

} // namespace shadowlab::scenefile
