// Coarser levels of dense meshes for depth passes (core/MeshLevels.h),
// without a GPU: fewer triangles, the stated error an upper bound of the
// distance measured from every vertex to the level's surface, and the
// surface still closed and turned the same way.
#include "core/Adjacency.h"
#include "core/MeshLevels.h"

#include <shadowlab/Shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadowlab;

namespace {
// The farthest any vertex of `mesh` lies from the level's triangles (every triangle tried).
float farthestVertex(const Mesh& mesh, const MeshLevel& level) {
    float farthest = 0.0f;
    for (const glm::vec3& p : mesh.positions) {
        float nearest = INFINITY;
        for (std::size_t t = 0; t + 2 < level.indices.size(); t += 3)
            nearest = std::min(nearest, pointTriangleDistance(p, mesh.positions[level.indices[t]], mesh.positions[level.indices[t + 1]],
                                                              mesh.positions[level.indices[t + 2]]));
        farthest = std::max(farthest, nearest);
    }
    return farthest;
}
} // namespace

TEST(MeshLevels, PointTriangleDistanceInEachRegion) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_FLOAT_EQ(pointTriangleDistance({0.25f, 0.25f, 2.0f}, a, b, c), 2.0f); // over the face
    EXPECT_FLOAT_EQ(pointTriangleDistance({-3.0f, -4.0f, 0.0f}, a, b, c), 5.0f); // past vertex a
    EXPECT_FLOAT_EQ(pointTriangleDistance({0.5f, -2.0f, 0.0f}, a, b, c), 2.0f);  // beside edge ab
    EXPECT_NEAR(pointTriangleDistance({1.0f, 1.0f, 0.0f}, a, b, c), std::sqrt(0.5f), 1e-6f); // beside edge bc
}

TEST(MeshLevels, ASphereHalvesPerLevelWithinItsStatedError) {
    const Mesh mesh = shapes::sphere(1.0f, 64, 32); // 4032 triangles, split vertices along its seam
    MeshLevelOptions options;
    options.minTriangles = 1000;
    options.fewestTriangles = 100;
    const std::vector<MeshLevel> levels = meshLevels(mesh.positions, mesh.indices, options);
    ASSERT_GE(levels.size(), 3u);
    std::size_t before = mesh.triangleCount();
    float error = 0.0f;
    for (const MeshLevel& level : levels) {
        const std::size_t triangles = level.indices.size() / 3;
        EXPECT_LE(triangles, before / 2 + 1);  // options.reduction 0.5
        EXPECT_GE(triangles, options.fewestTriangles);
        for (const std::uint32_t i : level.indices) ASSERT_LT(i, mesh.positions.size());
        // The stated error bounds the distance measured against every triangle (float rounding: 1e-5 of the radius).
        EXPECT_LE(farthestVertex(mesh, level), level.error + 1e-5f);
        EXPECT_GE(level.error, error);
        error = level.error;
        // Still closed, and its outsides still face out: a depth pass may leave its far sides out as before.
        EXPECT_EQ(openEdges(mesh.positions, level.indices), 0u);
        EXPECT_EQ(closedWinding(mesh.positions, level.indices), 1);
        before = triangles;
    }
    // Its vertices lie on the sphere and its chords sag inside it: at a
    // quarter of the triangles the sag stays a few hundredths of the radius.
    EXPECT_LT(levels[1].error, 0.05f);
    EXPECT_GT(levels.back().error, 0.0f);
}

TEST(MeshLevels, AFlatGridKeepsItsBorderAndLosesNothing) {
    // A 64 x 64 quad grid: its inside collapses at no error, its open border never moves.
    Mesh grid;
    const int n = 64;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) grid.positions.emplace_back(static_cast<float>(x) / n, 0.0f, static_cast<float>(y) / n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const auto i = static_cast<std::uint32_t>(y * (n + 1) + x);
            grid.indices.insert(grid.indices.end(), {i, i + n + 1, i + 1, i + 1, i + n + 1, i + n + 2});
        }
    MeshLevelOptions options;
    options.minTriangles = 1000;
    options.fewestTriangles = 300;
    const std::vector<MeshLevel> levels = meshLevels(grid.positions, grid.indices, options);
    ASSERT_FALSE(levels.empty());
    EXPECT_LE(levels.back().indices.size() / 3, 2u * grid.triangleCount() / 8); // at least three halvings
    for (const MeshLevel& level : levels) {
        EXPECT_NEAR(level.error, 0.0f, 1e-6f);
        // Every border vertex is still used: the outline is the same.
        std::vector<char> used(grid.positions.size(), 0);
        for (const std::uint32_t i : level.indices) used[i] = 1;
        for (int k = 0; k <= n; ++k) {
            EXPECT_TRUE(used[static_cast<std::size_t>(k)]);                 // first row
            EXPECT_TRUE(used[static_cast<std::size_t>(n * (n + 1) + k)]);   // last row
        }
        // Every triangle still faces up (the grid's triangles do: +y).
        for (std::size_t t = 0; t < level.indices.size(); t += 3) {
            const glm::vec3 a = grid.positions[level.indices[t]], b = grid.positions[level.indices[t + 1]], c = grid.positions[level.indices[t + 2]];
            EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
        }
    }
}

TEST(MeshLevels, SmallMeshesGetNone) {
    const Mesh mesh = shapes::sphere(1.0f, 16, 8);
    EXPECT_TRUE(meshLevels(mesh.positions, mesh.indices).empty()); // below minTriangles (4096)
}
