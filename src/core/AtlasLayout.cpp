#include "core/AtlasLayout.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace shadowlab {

namespace {

// The texel at Z-order index i: x from the even bits, y from the odd ones.
glm::ivec2 mortonPoint(std::uint64_t i) {
    glm::ivec2 p(0);
    for (int bit = 0; bit < 32; ++bit) {
        p.x |= static_cast<int>((i >> (2 * bit)) & 1u) << bit;
        p.y |= static_cast<int>((i >> (2 * bit + 1)) & 1u) << bit;
    }
    return p;
}

} // namespace

AtlasLayout packAtlas(const std::vector<AtlasRequest>& requests, int size, int minSide, double budget) {
    AtlasLayout out;
    std::vector<int> side(requests.size());
    // Z-order placement keeps power-of-two squares whole and aligned, and
    // only them: any other side is taken as the power of two below it
    // (a 768 tile took its Z-order cell of 768^2 texels, and the next tile
    // began inside it).
    const auto asked = [&](std::size_t i) { return static_cast<int>(std::bit_floor(static_cast<unsigned>(std::max(requests[i].side, 1)))); };
    minSide = static_cast<int>(std::bit_floor(static_cast<unsigned>(std::max(minSide, 1))));
    for (std::size_t i = 0; i < requests.size(); ++i) side[i] = asked(i);
    const auto area = [&] {
        double a = 0.0;
        for (std::size_t i = 0; i < requests.size(); ++i) a += static_cast<double>(requests[i].tiles) * side[i] * side[i];
        return a;
    };
    const double atlas = static_cast<double>(size) * size;
    const double capacity = budget > 0.0 ? std::min(budget, atlas) : atlas;
    double used = area();
    while (used > capacity) {
        int largest = 0;
        for (std::size_t i = 0; i < side.size(); ++i)
            if (side[i] > minSide && requests[i].tiles > 0) largest = std::max(largest, side[i]);
        if (largest == 0) {
            out.overBudget = true;
            if (used <= atlas) break;  // over the budget, within the atlas
            out.fits = false;
            out.texelsUsed = used;
            return out;
        }
        // One request at a time (a light's tile, or one face), in order:
        // no more texels given up than the budget asks.
        for (std::size_t i = 0; i < side.size() && used > capacity; ++i) {
            if (side[i] != largest || requests[i].tiles <= 0) continue;
            used -= static_cast<double>(requests[i].tiles) * 0.75 * side[i] * side[i];
            side[i] /= 2;
        }
    }
    out.texelsUsed = used;
    // Every tile, largest first (then in request order), along the Z-order curve.
    struct Tile {
        std::size_t request;
        int index;
    };
    std::vector<Tile> tiles;
    for (std::size_t i = 0; i < requests.size(); ++i)
        for (int t = 0; t < requests[i].tiles; ++t) tiles.push_back({i, t});
    std::stable_sort(tiles.begin(), tiles.end(), [&](const Tile& a, const Tile& b) { return side[a.request] > side[b.request]; });
    out.placed.resize(requests.size());
    for (std::size_t i = 0; i < requests.size(); ++i) {
        out.placed[i].side = side[i];
        out.placed[i].shrunkFrom = asked(i);
        out.placed[i].origins.resize(static_cast<std::size_t>(std::max(requests[i].tiles, 0)));
    }
    std::uint64_t next = 0;
    for (const Tile& t : tiles) {
        const auto s = static_cast<std::uint64_t>(side[t.request]);
        const glm::ivec2 origin = mortonPoint(next);
        // Within the atlas by construction (power-of-two squares whose area
        // fits a power-of-two atlas, largest first); said again so that a
        // broken invariant is an error here, not a draw past the texture.
        if (origin.x + side[t.request] > size || origin.y + side[t.request] > size) {
            out = AtlasLayout{};
            out.fits = false;
            out.texelsUsed = used;
            return out;
        }
        out.placed[t.request].origins[static_cast<std::size_t>(t.index)] = origin;
        next += s * s;
    }
    return out;
}

int tileSideFor(float extentPixels, float texelsPerPixel, int minSide, int maxSide) {
    const float want = std::max(extentPixels * texelsPerPixel, 1.0f);
    int side = minSide;
    while (side < maxSide && static_cast<float>(side) < want) side *= 2;
    return std::min(side, maxSide);
}

int tileSideKeeping(float extentPixels, float texelsPerPixel, int minSide, int maxSide, int previous) {
    const int fresh = tileSideFor(extentPixels, texelsPerPixel, minSide, maxSide);
    if (previous < minSide || previous > maxSide || fresh == previous) return fresh;
    const float want = std::max(extentPixels * texelsPerPixel, 1.0f), kept = static_cast<float>(previous);
    return want >= kShrinkBelow * kept && want <= kGrowAbove * kept ? previous : fresh;
}

Bounds cubeFaceReach(const glm::vec3& position, float range, int face, const Bounds& receivers) {
    const int axis = face / 2;
    const bool positive = face % 2 == 0;
    Bounds box;
    box.lo = position - glm::vec3(range);
    box.hi = position + glm::vec3(range);
    if (positive)
        box.lo[axis] = position[axis];
    else
        box.hi[axis] = position[axis];
    box = box.cutTo(receivers);
    if (box.empty()) return box;
    // Off the axis by at most the distance along it (90 degrees across), and
    // by at most range / sqrt(2) (where that distance meets the sphere).
    const float along = positive ? box.hi[axis] - position[axis] : position[axis] - box.lo[axis];
    const float across = std::min(along, range * 0.70710678f);
    for (int u = 0; u < 3; ++u) {
        if (u == axis) continue;
        box.lo[u] = std::max(box.lo[u], position[u] - across);
        box.hi[u] = std::min(box.hi[u], position[u] + across);
    }
    return box;
}

std::optional<float> screenExtentOf(const Bounds& box, const glm::mat4& clipFromWorld, glm::ivec2 viewport) {
    if (box.empty()) return 0.0f;
    glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 q = clipFromWorld * glm::vec4(box.corner(c), 1.0f);
        if (!(q.w > 1e-6f)) return std::nullopt;
        lo = glm::min(lo, glm::vec2(q) / q.w);
        hi = glm::max(hi, glm::vec2(q) / q.w);
    }
    lo = glm::max(lo, glm::vec2(-1.0f));
    hi = glm::min(hi, glm::vec2(1.0f));
    if (!(lo.x < hi.x && lo.y < hi.y)) return 0.0f;
    const glm::vec2 pixels = (hi - lo) * 0.5f * glm::vec2(viewport);
    return std::max(pixels.x, pixels.y);
}

} // namespace shadowlab
