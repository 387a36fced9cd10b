// Triangle adjacency (GL_TRIANGLES_ADJACENCY order) on shapes whose
// neighbours are known, without a GPU.
#include "core/Adjacency.h"

#include <shadowlab/Shapes.h>

#include <gtest/gtest.h>

using namespace shadowlab;

TEST(Adjacency, EveryEdgeOfAClosedBoxFindsTheTriangleAcrossIt) {
    // The box splits its vertices per face (normals), so only welding by
    // position can find the neighbours.
    const Mesh box = shapes::box(glm::vec3(1.0f));
    const auto adj = adjacencyIndices(box.positions, box.indices);
    ASSERT_EQ(adj.size(), box.indices.size() * 2);
    EXPECT_EQ(openEdges(box.positions, box.indices), 0u);
    for (std::size_t t = 0; t < box.triangleCount(); ++t) {
        const std::uint32_t* tri = &box.indices[3 * t];
        for (int e = 0; e < 3; ++e) {
            EXPECT_EQ(adj[6 * t + 2 * e], tri[e]);  // the triangle's own vertices at even slots
            const glm::vec3 a = box.positions[tri[e]], b = box.positions[tri[(e + 1) % 3]];
            const glm::vec3 opposite = box.positions[adj[6 * t + 2 * e + 1]];
            const glm::vec3 own = box.positions[tri[(e + 2) % 3]];
            // The neighbour's far vertex is not on the edge and (for a box)
            // not the triangle's own opposite vertex.
            EXPECT_GT(glm::length(glm::cross(b - a, opposite - a)), 1e-6f);
            EXPECT_NE(opposite, own);
        }
    }
}

TEST(Adjacency, AnOpenEdgeGetsTheTrianglesOwnOppositeVertex) {
    // Two triangles sharing the diagonal of a unit square: 4 open edges.
    const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    const std::vector<std::uint32_t> idx{0, 2, 1, 0, 3, 2};
    const auto adj = adjacencyIndices(p, idx);
    EXPECT_EQ(openEdges(p, idx), 4u);
    // Triangle 0 = (0, 2, 1): edge 0-2 is the diagonal, across it vertex 3;
    // edges 2-1 and 1-0 are open: their own opposite vertices 0 and 2.
    // Triangle 1 = (0, 3, 2): edges 0-3 and 3-2 are open (own opposite
    // vertices 2 and 0); across the diagonal 2-0 lies vertex 1.
    EXPECT_EQ(adj, (std::vector<std::uint32_t>{0, 3, 2, 0, 1, 2, 0, 2, 3, 0, 2, 1}));
}

TEST(Adjacency, RoundShapesAreClosedAcrossTheirSeams) {
    // Their uv seams duplicate vertices; the positions must coincide exactly.
    EXPECT_EQ(openEdges(shapes::torus(1.0f, 0.3f, 16, 8).positions, shapes::torus(1.0f, 0.3f, 16, 8).indices), 0u);
    const Mesh sphere = shapes::sphere(1.0f, 12, 7);
    EXPECT_EQ(openEdges(sphere.positions, sphere.indices), 0u);
    const Mesh cylinder = shapes::cylinder(0.5f, 1.0f, 10);
    EXPECT_EQ(openEdges(cylinder.positions, cylinder.indices), 0u);
    const Mesh cone = shapes::cone(0.5f, 1.0f, 10);
    EXPECT_EQ(openEdges(cone.positions, cone.indices), 0u);
}
