#include "core/Adjacency.h"

#include "core/FloatBits.h"
#include "core/LargePages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace shadowlab {

namespace {

std::uint64_t edgeKey(std::uint32_t from, std::uint32_t to) { return (std::uint64_t(from) << 32) | to; }

struct EdgeUse {
    std::uint32_t opposite = 0; // original index of the vertex opposite the edge
    int count = 0;              // triangles using this directed edge
};

// Directed edges (by welded ids) of every triangle, with their opposite vertex.
std::unordered_map<std::uint64_t, EdgeUse> directedEdges(const std::vector<std::uint32_t>& id, const std::vector<std::uint32_t>& indices) {
    std::unordered_map<std::uint64_t, EdgeUse> edges;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = indices[t + e], b = indices[t + (e + 1) % 3], c = indices[t + (e + 2) % 3];
            EdgeUse& use = edges[edgeKey(id[a], id[b])];
            use.opposite = c;
            ++use.count;
        }
    return edges;
}

} // namespace

std::vector<std::uint32_t> weldByPosition(const std::vector<glm::vec3>& positions) {
    // The vertices sorted by position (the bits of x, y, z, a zero of either
    // sign as +0), then by number: equal positions come out together, the
    // first of them first. A sort, not a hash map: a million vertices in a
    // tenth of the time. A position with a NaN equals none, not even itself.
    struct Keyed {
        std::array<std::uint32_t, 3> bits;
        std::uint32_t index;
        bool operator<(const Keyed& o) const {
            for (std::size_t c = 0; c < 3; ++c)
                if (bits[c] != o.bits[c]) return bits[c] < o.bits[c];
            return index < o.index;
        }
    };
    std::vector<Keyed, LargePages<Keyed>> keyed(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        Keyed& k = keyed[i];
        for (int c = 0; c < 3; ++c) k.bits[static_cast<std::size_t>(c)] = equalityBits(positions[i][c]);
        k.index = static_cast<std::uint32_t>(i);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> id(positions.size());
    for (std::size_t i = 0, run = 0; i < keyed.size(); ++i) {
        const glm::vec3& p = positions[keyed[i].index];
        const bool nan = std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z);
        if (i == 0 || nan || keyed[i].bits != keyed[i - 1].bits) run = i;
        id[keyed[i].index] = nan ? keyed[i].index : keyed[run].index;
    }
    return id;
}

std::vector<std::uint32_t> adjacencyIndices(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    const std::vector<std::uint32_t> id = weldByPosition(positions);
    const auto edges = directedEdges(id, indices);
    std::vector<std::uint32_t> out;
    out.reserve(indices.size() * 2);
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = indices[t + e], b = indices[t + (e + 1) % 3], c = indices[t + (e + 2) % 3];
            // The neighbour walks the edge the other way round.
            const auto twin = edges.find(edgeKey(id[b], id[a]));
            const bool manifold = twin != edges.end() && twin->second.count == 1 && edges.at(edgeKey(id[a], id[b])).count == 1;
            out.push_back(a);
            out.push_back(manifold ? twin->second.opposite : c);
        }
    return out;
}

std::size_t openEdges(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    const std::vector<std::uint32_t> id = weldByPosition(positions);
    const auto edges = directedEdges(id, indices);
    std::size_t open = 0;
    for (const auto& [key, use] : edges) {
        const auto from = static_cast<std::uint32_t>(key >> 32), to = static_cast<std::uint32_t>(key);
        const auto twin = edges.find(edgeKey(to, from));
        if (use.count != 1 || twin == edges.end() || twin->second.count != 1) ++open;
    }
    return open;
}

int closedWinding(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    if (indices.size() < 3 || indices.size() % 3 != 0) return 0;
    for (const std::uint32_t i : indices)
        if (i >= positions.size()) return 0;
    if (openEdges(positions, indices) != 0) return 0;
    // Six times the signed volume, about the bounds' centre (for precision).
    glm::dvec3 lo(positions[indices[0]]), hi = lo;
    for (const std::uint32_t i : indices) {
        lo = glm::min(lo, glm::dvec3(positions[i]));
        hi = glm::max(hi, glm::dvec3(positions[i]));
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a = glm::dvec3(positions[indices[t]]) - centre, b = glm::dvec3(positions[indices[t + 1]]) - centre,
                         c = glm::dvec3(positions[indices[t + 2]]) - centre;
        volume += glm::dot(a, glm::cross(b, c));
    }
    // Enclosing next to nothing against its bounds' cube: no inside to speak of.
    const double diagonal = glm::length(hi - lo);
    if (!(std::abs(volume) > 1e-9 * diagonal * diagonal * diagonal)) return 0;
    return volume > 0.0 ? 1 : -1;
}

} // namespace shadowlab
