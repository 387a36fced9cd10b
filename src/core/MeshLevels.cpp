// Coarser levels of a dense mesh by quadric-ordered half-edge collapses
// (MeshLevels.h; the collapser: EdgeCollapser.h).
#include "core/MeshLevels.h"

#include "core/EdgeCollapser.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>

namespace shadowlab {

using detail::Collapser;
using detail::kNone;
using detail::squaredDistance;

float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return static_cast<float>(std::sqrt(squaredDistance(p, a, b, c)));
}

namespace {

// The levels of one mesh, on this thread.
std::vector<MeshLevel> levelsOf(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, const MeshLevelOptions& options,
                                MeshLevelWork& work) {
    std::vector<MeshLevel> levels;
    const double reduction = std::clamp(options.reduction, 0.1, 0.9);
    Collapser collapser(positions, indices, work);
    std::size_t before = collapser.live();
    while (true) {
        const auto target = static_cast<std::size_t>(static_cast<double>(before) * reduction);
        if (target < options.fewestTriangles) break;
        // Nor below as many triangles as vertices that never move: a disc
        // whose border stays keeps that many less two, and the limit on the
        // triangles around a vertex keeps more. Such a level fails (the rule
        // below) after its costliest collapses, each one re-measuring the
        // hundreds of vertices its coarse triangles hold.
        if (target < collapser.locked()) break;
        const bool reached = collapser.reduceTo(target);

        // A level only where it saves at least a quarter of the one before.
        if (static_cast<double>(collapser.live()) > 0.75 * static_cast<double>(before)) break;
        levels.push_back(collapser.level());
        collapser.setSlack(levels.back().error);
        collapser.compact();
        collapser.regroup();
        before = collapser.live();
        if (!reached) break;
    }
    return levels;
}

// Half of a mesh's triangles as a mesh of its own: its vertices (`from`,
// each one's number in the whole mesh) and its triangles over them.
struct Half {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices, from;
    std::vector<MeshLevel> levels;
    MeshLevelWork work;
};

// The triangles split in two by their centres along the mesh's longest
// side, at the median (ties by triangle number: the same halves every run).
std::array<Half, 2> halves(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    const std::size_t triangles = indices.size() / 3;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const std::uint32_t i : indices) lo = glm::min(lo, positions[i]), hi = glm::max(hi, positions[i]);
    const glm::vec3 side = hi - lo;
    const int axis = side.x >= side.y && side.x >= side.z ? 0 : side.y >= side.z ? 1 : 2;
    std::vector<std::pair<float, std::uint32_t>> keys(triangles);
    for (std::uint32_t t = 0; t < triangles; ++t)
        keys[t] = {positions[indices[3 * t]][axis] + positions[indices[3 * t + 1]][axis] + positions[indices[3 * t + 2]][axis], t};
    std::nth_element(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(triangles / 2), keys.end());
    std::vector<std::uint8_t> side2(triangles, 0);
    for (std::size_t k = triangles / 2; k < triangles; ++k) side2[keys[k].second] = 1;
    std::array<Half, 2> out;
    std::vector<std::uint32_t> number(positions.size());
    for (int h = 0; h < 2; ++h) {
        Half& half = out[static_cast<std::size_t>(h)];
        std::fill(number.begin(), number.end(), kNone);
        for (std::uint32_t t = 0; t < triangles; ++t) {
            if (side2[t] != h) continue;
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = indices[3 * t + static_cast<std::uint32_t>(c)];
                if (number[v] == kNone) {
                    number[v] = static_cast<std::uint32_t>(half.from.size());
                    half.from.push_back(v);
                    half.positions.push_back(positions[v]);
                }
                half.indices.push_back(number[v]);
            }
        }
    }
    return out;
}

// The halves' levels as the whole mesh's: level k of each (a half with
// fewer levels giving its last, or its own triangles), while a level saves
// a quarter of the one before.
std::vector<MeshLevel> joined(const std::array<Half, 2>& parts, std::size_t triangles) {
    std::vector<MeshLevel> out;
    const std::size_t most = std::max(parts[0].levels.size(), parts[1].levels.size());
    std::size_t before = triangles;
    for (std::size_t k = 0; k < most; ++k) {
        MeshLevel level;
        for (const Half& half : parts) {
            const std::vector<std::uint32_t>* indices = &half.indices;
            if (!half.levels.empty()) {
                const MeshLevel& own = half.levels[std::min(k, half.levels.size() - 1)];
                indices = &own.indices;
                level.error = std::max(level.error, own.error);
            }
            for (const std::uint32_t i : *indices) level.indices.push_back(half.from[i]);
        }
        if (static_cast<double>(level.indices.size() / 3) > 0.75 * static_cast<double>(before)) break;
        before = level.indices.size() / 3;
        out.push_back(std::move(level));
    }
    return out;
}

} // namespace

std::vector<MeshLevel> meshLevels(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, const MeshLevelOptions& options,
                                  MeshLevelWork* work) {
    const std::size_t triangles = indices.size() / 3;
    if (triangles < options.minTriangles) return {};
    MeshLevelWork counted;
    MeshLevelWork& total = work ? *work : counted;
    if (options.splitTriangles == 0 || triangles < options.splitTriangles) return levelsOf(positions, indices, options, total);
    // Two halves on two threads, each the same every run; the cut between
    // them is an open edge of each, so its vertices never move.
    std::array<Half, 2> parts = halves(positions, indices);
    MeshLevelOptions each = options;
    each.fewestTriangles = std::max<std::size_t>(options.fewestTriangles / 2, 1);
    std::exception_ptr failed;
    std::thread other([&] {
        try {
            parts[1].levels = levelsOf(parts[1].positions, parts[1].indices, each, parts[1].work);
        } catch (...) {
            failed = std::current_exception();
        }
    });
    try {
        parts[0].levels = levelsOf(parts[0].positions, parts[0].indices, each, parts[0].work);
    } catch (...) {
        other.join();
        throw;
    }
    other.join();
    if (failed) std::rethrow_exception(failed);
    for (const Half& half : parts) {
        total.distanceTests += half.work.distanceTests;
        total.costs += half.work.costs;
        total.starVisits += half.work.starVisits;
    }
    return joined(parts, triangles);
}

} // namespace shadowlab
