// Triangles in Morton order of their centroids (TriangleOrder.h).
#include "core/TriangleOrder.h"

#include "core/FloatBits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace shadowlab {

namespace {
// x's low 10 bits spread to every third bit.
std::uint32_t spread(std::uint32_t x) {
    x &= 0x3ffu;
    x = (x | (x << 16)) & 0x030000ffu;
    x = (x | (x << 8)) & 0x0300f00fu;
    x = (x | (x << 4)) & 0x030c30c3u;
    x = (x | (x << 2)) & 0x09249249u;
    return x;
}
// Triangle t's corners as bits, turned to start at its least corner (the
// same triangle whichever corner its indices start at, its winding kept);
// a zero of either sign is +0, as == compares them.
std::array<std::uint32_t, 9> triangleCorners(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, std::uint32_t t) {
    std::array<std::array<std::uint32_t, 3>, 3> c{};
    for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) {
            c[static_cast<std::size_t>(k)][static_cast<std::size_t>(a)] = equalityBits(positions[indices[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(k)]][a]);
        }
    const std::size_t first = static_cast<std::size_t>(std::min_element(c.begin(), c.end()) - c.begin());
    std::array<std::uint32_t, 9> out{};
    for (std::size_t k = 0; k < 3; ++k) std::copy(c[(first + k) % 3].begin(), c[(first + k) % 3].end(), out.begin() + static_cast<std::ptrdiff_t>(3 * k));
    return out;
}
} // namespace

std::vector<std::uint32_t> spatialTriangleOrder(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    const std::size_t triangles = indices.size() / 3;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const std::uint32_t i : indices) {
        lo = glm::min(lo, positions[i]);
        hi = glm::max(hi, positions[i]);
    }
    // In double: a mesh spanning +-3e38 has an extent (and centroid sums)
    // past a float's range, which made the key a NaN cast to an integer.
    const glm::dvec3 low(lo), extent = glm::max(glm::dvec3(hi) - low, glm::dvec3(1e-30));
    std::vector<std::uint32_t> key(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 centre =
            (glm::dvec3(positions[indices[3 * t]]) + glm::dvec3(positions[indices[3 * t + 1]]) + glm::dvec3(positions[indices[3 * t + 2]])) / 3.0;
        glm::dvec3 unit = (centre - low) / extent;
        for (int a = 0; a < 3; ++a) unit[a] = std::isfinite(unit[a]) ? std::clamp(unit[a], 0.0, 1.0) * 1023.0 : 0.0;
        key[t] = spread(static_cast<std::uint32_t>(unit.x)) | (spread(static_cast<std::uint32_t>(unit.y)) << 1) |
                 (spread(static_cast<std::uint32_t>(unit.z)) << 2);
    }
    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    // Repeats share a centroid, so a key: within each run of one key, the
    // triangles sorted by their corners (a copy of that run) show them
    // side by side; each after its first in draw order is left out.
    std::vector<char> repeat(triangles, 0);
    std::vector<std::uint32_t> run;
    for (std::size_t begin = 0, end = 0; begin < triangles; begin = end) {
        for (end = begin + 1; end < triangles && key[order[end]] == key[order[begin]];) ++end;
        if (end - begin < 2) continue;
        run.assign(order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(end));
        const auto corners = [&](std::uint32_t t) { return triangleCorners(positions, indices, t); };
        // Stable: among repeats, the first in draw order comes first and is kept.
        std::stable_sort(run.begin(), run.end(), [&](std::uint32_t a, std::uint32_t b) { return corners(a) < corners(b); });
        for (std::size_t k = 1; k < run.size(); ++k)
            if (corners(run[k]) == corners(run[k - 1])) repeat[run[k]] = 1;
    }
    std::vector<std::uint32_t> out;
    out.reserve(triangles * 3);
    for (const std::uint32_t t : order)
        if (!repeat[t]) out.insert(out.end(), {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]});
    return out;
}

DrawOrder spatialDrawOrder(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    constexpr std::uint32_t kUnused = 0xffffffffu;
    DrawOrder out;
    out.indices = spatialTriangleOrder(positions, indices);
    out.remap.assign(positions.size(), kUnused);
    std::uint32_t next = 0;
    for (std::uint32_t& i : out.indices) {
        if (out.remap[i] == kUnused) out.remap[i] = next++;
        i = out.remap[i];
    }
    for (std::uint32_t& r : out.remap)
        if (r == kUnused) r = next++;
    return out;
}

} // namespace shadowlab
