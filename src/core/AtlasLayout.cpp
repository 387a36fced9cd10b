#include "core/AtlasLayout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

AtlasLayout packAtlas(const std::vector<AtlasRequest>& requests, int size, int minSide) {
    AtlasLayout out;
    std::vector<int> side(requests.size());
    for (std::size_t i = 0; i < requests.size(); ++i) side[i] = std::max(requests[i].side, 1);
    const auto area = [&] {
        double a = 0.0;
        for (std::size_t i = 0; i < requests.size(); ++i) a += static_cast<double>(requests[i].tiles) * side[i] * side[i];
        return a;
    };
    const double capacity = static_cast<double>(size) * size;
    double used = area();
    while (used > capacity) {
        int largest = 0;
        for (std::size_t i = 0; i < side.size(); ++i)
            if (side[i] > minSide && requests[i].tiles > 0) largest = std::max(largest, side[i]);
        if (largest == 0) {
            out.fits = false;
            out.texelsUsed = used;
            return out;
        }
        for (int& s : side)
            if (s == largest) s /= 2;
        used = area();
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
        out.placed[i].shrunkFrom = std::max(requests[i].side, 1);
        out.placed[i].origins.resize(static_cast<std::size_t>(std::max(requests[i].tiles, 0)));
    }
    std::uint64_t next = 0;
    for (const Tile& t : tiles) {
        const auto s = static_cast<std::uint64_t>(side[t.request]);
        out.placed[t.request].origins[static_cast<std::size_t>(t.index)] = mortonPoint(next);
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

} // namespace shadowlab
