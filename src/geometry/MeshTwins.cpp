// An earlier identical mesh by a hash of indices and positions (MeshTwins.h).
#include "geometry/MeshTwins.h"

#include "core/FloatBits.h"

namespace shadowlab {

std::uint64_t meshHash(const Mesh& mesh) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    const auto add = [&h](std::uint32_t word) { h = (h ^ word) * 0x100000001b3ull; };
    add(static_cast<std::uint32_t>(mesh.indices.size()));
    for (const std::uint32_t i : mesh.indices) add(i);
    for (const glm::vec3& p : mesh.positions)
        for (int k = 0; k < 3; ++k) add(equalityBits(p[k]));
    return h;
}

int MeshTwins::findOrAdd(int number, const std::vector<Mesh>& meshes) {
    const Mesh& mesh = meshes[static_cast<std::size_t>(number)];
    std::vector<int>& sameHash = byHash_[meshHash(mesh)];
    for (const int other : sameHash) {
        ++comparisons_;
        const Mesh& twin = meshes[static_cast<std::size_t>(other)];
        if (twin.indices == mesh.indices && twin.positions == mesh.positions) return other;
    }
    sameHash.push_back(number);
    return -1;
}

} // namespace shadowlab
