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

// Which way a closed mesh winds (closedWinding): the built-in solids wind
// counter-clockwise outside; turned inside out they wind in; anything open
// or enclosing nothing has no winding (a depth pass draws both its sides).
TEST(Adjacency, ClosedShapesWindOutAndOpenOnesNotAtAll) {
    const Mesh solids[] = {shapes::box(glm::vec3(1.0f, 0.02f, 2.0f)), shapes::sphere(1.0f, 12, 7), shapes::torus(1.0f, 0.3f, 16, 8),
                           shapes::cylinder(0.5f, 1.0f, 10), shapes::cone(0.5f, 1.0f, 10), shapes::pyramid(1.0f, 1.0f)};
    for (const Mesh& m : solids) {
        EXPECT_EQ(closedWinding(m.positions, m.indices), 1);
        std::vector<std::uint32_t> inside = m.indices;
        for (std::size_t t = 0; t + 2 < inside.size(); t += 3) std::swap(inside[t + 1], inside[t + 2]);
        EXPECT_EQ(closedWinding(m.positions, inside), -1) << "turned inside out";
    }
    // A box with one face (two triangles) left out is open.
    const Mesh box = shapes::box(glm::vec3(1.0f));
    std::vector<std::uint32_t> open(box.indices.begin() + 6, box.indices.end());
    EXPECT_EQ(closedWinding(box.positions, open), 0);
    // A square drawn from both sides: every edge walked both ways, no volume.
    const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    EXPECT_EQ(closedWinding(p, {0, 2, 1, 0, 3, 2, 0, 1, 2, 0, 2, 3}), 0);
    // A plane, nothing, and indices past the vertices.
    const Mesh plane = shapes::plane(2.0f, 2.0f);
    EXPECT_EQ(closedWinding(plane.positions, plane.indices), 0);
    EXPECT_EQ(closedWinding({}, {}), 0);
    EXPECT_EQ(closedWinding(p, {0, 1, 7}), 0);
}
