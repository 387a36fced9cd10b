// Triangles drawn in Morton order of their centroids (core/TriangleOrder.h):
// the same triangles, each wound as it was, with neighbours together.
#include "core/TriangleOrder.h"

#include <shadowlab/Shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>

using namespace shadowlab;

namespace {
using Triangle = std::array<std::uint32_t, 3>;
// Each triangle turned to start at its least index (its winding kept), sorted.
std::vector<Triangle> canonical(const std::vector<std::uint32_t>& indices) {
    std::vector<Triangle> out;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        Triangle tri{indices[t], indices[t + 1], indices[t + 2]};
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
        out.push_back(tri);
    }
    std::sort(out.begin(), out.end());
    return out;
}
// The mean distance between consecutive triangles' centroids.
float meanStep(const Mesh& mesh, const std::vector<std::uint32_t>& indices) {
    double sum = 0.0;
    glm::vec3 last(0.0f);
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3 c = (mesh.positions[indices[t]] + mesh.positions[indices[t + 1]] + mesh.positions[indices[t + 2]]) / 3.0f;
        if (t > 0) sum += glm::length(c - last);
        last = c;
    }
    return static_cast<float>(sum / static_cast<double>(indices.size() / 3 - 1));
}
} // namespace

TEST(TriangleOrder, TheSameTrianglesWithNeighboursTogether) {
    Mesh mesh = shapes::sphere(1.0f, 64, 32);
    // The triangles shuffled (a fixed seed): a file listing them in no spatial order.
    std::vector<std::uint32_t> order(mesh.triangleCount());
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    std::vector<std::uint32_t> shuffled;
    for (const std::uint32_t t : order) shuffled.insert(shuffled.end(), {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]});
    const std::vector<std::uint32_t> sorted = spatialTriangleOrder(mesh.positions, shuffled);
    EXPECT_EQ(canonical(sorted), canonical(shuffled));
    // Shuffled, consecutive triangles lie about a radius apart (measured 1.3);
    // in Morton order a few triangle sizes (measured 0.06).
    EXPECT_LT(meanStep(mesh, sorted), 0.1f * meanStep(mesh, shuffled));
}

TEST(TriangleOrder, VerticesRenumberedAsFirstUsed) {
    Mesh mesh = shapes::sphere(1.0f, 32, 16);
    mesh.positions.emplace_back(5.0f, 5.0f, 5.0f);  // a vertex no triangle uses
    const DrawOrder order = spatialDrawOrder(mesh.positions, mesh.indices);
    ASSERT_EQ(order.remap.size(), mesh.positions.size());
    // A permutation of the vertices...
    std::vector<std::uint32_t> back(order.remap.size(), 0xffffffffu);
    for (std::uint32_t old = 0; old < order.remap.size(); ++old) {
        ASSERT_LT(order.remap[old], back.size());
        ASSERT_EQ(back[order.remap[old]], 0xffffffffu) << "two vertices numbered " << order.remap[old];
        back[order.remap[old]] = old;
    }
    EXPECT_EQ(order.remap.back(), mesh.positions.size() - 1) << "the unused vertex comes last";
    // ...numbered as the triangles first use them...
    std::uint32_t next = 0;
    for (const std::uint32_t i : order.indices) {
        EXPECT_LE(i, next);
        if (i == next) ++next;
    }
    // ...and the same triangles, each wound as it was.
    std::vector<std::uint32_t> mapped;
    for (const std::uint32_t i : order.indices) mapped.push_back(back[i]);
    EXPECT_EQ(canonical(mapped), canonical(mesh.indices));
}

TEST(TriangleOrder, NoTrianglesNoneOut) {
    EXPECT_TRUE(spatialTriangleOrder({}, {}).empty());
    const std::vector<glm::vec3> one{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(spatialTriangleOrder(one, {0, 1, 2}), (std::vector<std::uint32_t>{0, 1, 2}));
}

// A mesh spanning +-3e38: its extent and its centroids' sums are past a
// float's range. The keys are taken in double, so the triangles still go
// in spatial order (issue 59: the key was a NaN cast to an integer, which
// UBSan's float-cast-overflow reports).
TEST(TriangleOrder, AMeshSpanningTheFloatRangeKeepsItsOrder) {
    const std::vector<glm::vec3> positions{{3e38f, 0, 0}, {3e38f, 1, 0}, {3e38f, 0, 1},    // far +x
                                           {0, 0, 0},     {0, 1, 0},     {0, 0, 1},        // the middle
                                           {-3e38f, 0, 0}, {-3e38f, 1, 0}, {-3e38f, 0, 1}};  // far -x
    const std::vector<std::uint32_t> indices{0, 1, 2, 3, 4, 5, 6, 7, 8};
    const std::vector<std::uint32_t> sorted = spatialTriangleOrder(positions, indices);
    ASSERT_EQ(sorted.size(), 9u);
    EXPECT_EQ(sorted[0], 6u) << "the -x triangle first";
    EXPECT_EQ(sorted[3], 3u) << "then the middle";
    EXPECT_EQ(sorted[6], 0u) << "then +x";
}

// A triangle repeated is drawn once, whether its copies share its indices,
// start at another corner, or name copies of its vertices; the same corners
// turning the other way are another triangle (its back), and a near copy
// (one corner moved by a float's step) is kept too. A million copies of
// one triangle come out as one: the fill a shadow pass would repeat.
TEST(TriangleOrder, ARepeatedTriangleIsDrawnOnce) {
    std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, 0, 0}, {0, std::nextafter(1.0f, 2.0f), 0}};
    std::vector<std::uint32_t> indices{0, 1, 2,  1, 2, 0,  3, 4, 5,  6, 1, 2,  0, 2, 1,  0, 1, 7,  2, 0, 1};
    const std::vector<std::uint32_t> once = spatialTriangleOrder(positions, indices);
    ASSERT_EQ(once.size(), 9u) << "kept: the first, its back (0 2 1), its near copy (0 1 7)";
    EXPECT_EQ((std::vector<std::uint32_t>(once.begin(), once.begin() + 3)), (std::vector<std::uint32_t>{0, 1, 2})) << "the first copy in the mesh's order is kept";
    const std::vector<Triangle> kept = canonical(once);
    EXPECT_EQ(kept, (std::vector<Triangle>{{0, 1, 2}, {0, 1, 7}, {0, 2, 1}}));

    std::vector<std::uint32_t> million;
    million.reserve(3'000'000);
    for (int i = 0; i < 1'000'000; ++i) million.insert(million.end(), {0, 1, 2});
    EXPECT_EQ(spatialTriangleOrder(positions, million).size(), 3u);
    // A sphere has no repeats: every triangle is kept.
    const Mesh sphere = shapes::sphere(1.0f, 64, 32);
    EXPECT_EQ(canonical(spatialTriangleOrder(sphere.positions, sphere.indices)), canonical(sphere.indices));
}
