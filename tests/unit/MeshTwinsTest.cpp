// Finding an earlier identical mesh (geometry/MeshTwins.h) by a hash, without
// comparing every pair of meshes: counted comparisons, not time.
#include "geometry/MeshTwins.h"

#include <shadowlab/Shapes.h>

#include <gtest/gtest.h>

using namespace shadowlab;

// 20,000 boxes, each moved somewhere else in its positions: the same
// indices, different positions, the case that compared every pair before
// (indices equal, positions compared up to their first difference). None
// is another's twin and none is compared in full: their hashes differ.
TEST(MeshTwins, ManyMeshesWithTheSameIndicesAreNotComparedPairwise) {
    std::vector<Mesh> meshes;
    for (int i = 0; i < 20000; ++i) {
        Mesh box = shapes::box(glm::vec3(1.0f));
        for (glm::vec3& p : box.positions) p += glm::vec3(static_cast<float>(i % 200), 0.0f, static_cast<float>(i / 200));
        meshes.push_back(std::move(box));
    }
    MeshTwins twins;
    for (int i = 0; i < static_cast<int>(meshes.size()); ++i) EXPECT_EQ(twins.findOrAdd(i, meshes), -1);
    EXPECT_EQ(twins.comparisons(), 0u);
}

// Copies of one mesh find the first, each with one comparison; a mesh
// differing in one index or one position finds none.
TEST(MeshTwins, CopiesFindTheFirstAndNothingElseDoes) {
    const Mesh sphere = shapes::sphere(1.0f, 16, 8);
    std::vector<Mesh> meshes(1000, sphere);
    Mesh moved = sphere;
    moved.positions[7].x += 1e-3f;
    Mesh rewound = sphere;
    std::swap(rewound.indices[0], rewound.indices[1]);
    meshes.push_back(moved);
    meshes.push_back(rewound);
    MeshTwins twins;
    EXPECT_EQ(twins.findOrAdd(0, meshes), -1);
    for (int i = 1; i < 1000; ++i) EXPECT_EQ(twins.findOrAdd(i, meshes), 0);
    EXPECT_EQ(twins.comparisons(), 999u);
    EXPECT_EQ(twins.findOrAdd(1000, meshes), -1);
    EXPECT_EQ(twins.findOrAdd(1001, meshes), -1);
}

// Twins are what == says: a zero of either sign is one position.
TEST(MeshTwins, AZeroOfEitherSignIsOnePosition) {
    std::vector<Mesh> meshes(2, shapes::box(glm::vec3(1.0f)));
    meshes[0].positions[0] = glm::vec3(0.0f, 0.5f, 0.5f);
    meshes[1].positions[0] = glm::vec3(-0.0f, 0.5f, 0.5f);
    MeshTwins twins;
    EXPECT_EQ(twins.findOrAdd(0, meshes), -1);
    EXPECT_EQ(twins.findOrAdd(1, meshes), 0);
}
