// Coarser levels of a dense mesh by quadric-ordered half-edge collapses
// (MeshLevels.h; the collapser: EdgeCollapser.h).
#include "core/MeshLevels.h"

#include "core/EdgeCollapser.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

using detail::Collapser;
using detail::squaredDistance;

float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return static_cast<float>(std::sqrt(squaredDistance(p, a, b, c)));
}

std::vector<MeshLevel> meshLevels(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices, const MeshLevelOptions& options,
                                  MeshLevelWork* work) {
    std::vector<MeshLevel> levels;
    if (indices.size() / 3 < options.minTriangles) return levels;
    const double reduction = std::clamp(options.reduction, 0.1, 0.9);
    MeshLevelWork counted;
    Collapser collapser(positions, indices, work ? *work : counted);
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

} // namespace shadowlab
