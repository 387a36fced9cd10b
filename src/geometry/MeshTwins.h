#pragma once
// Finding an earlier mesh identical to this one (the same indices and
// positions, as == compares them), by a hash of both: a scene of n meshes
// hashes each once and compares two in full only where their hashes match,
// not every pair (GpuScene::levels shares a mesh's levels with its twins).
// GPU-free.
#include <shadowlab/Scene.h>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace shadowlab {

/// FNV-1a over a mesh's index count, indices and position bits: meshes that
/// compare equal hash equal (a zero of either sign hashed as +0).
std::uint64_t meshHash(const Mesh& mesh);

class MeshTwins {
public:
    /// The number of a mesh added before with the indices and positions of
    /// meshes[number]; or -1, and meshes[number] is added. `meshes` is the
    /// same list every call.
    int findOrAdd(int number, const std::vector<Mesh>& meshes);
    /// Meshes compared in full so far (only where hashes matched).
    std::size_t comparisons() const { return comparisons_; }

private:
    std::unordered_map<std::uint64_t, std::vector<int>> byHash_;
    std::size_t comparisons_ = 0;
};

} // namespace shadowlab
