// The texels a box may cover in a map (techniques/map/fit/Cameras.h:
// projectedRect): a box past an int's range in the map's texels, or one
// whose projection is no number, gives the whole map, never an overflow
// (issue 59: a point light's cube face over a plane of size 1e20 reached
// `INT_MIN - 1`, a signed overflow under UBSan, and an empty rectangle).
#include "techniques/map/fit/Cameras.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

using namespace shadowlab;

TEST(ProjectedRect, AHugeBoxCoversTheWholeMapWithoutOverflow) {
    const glm::mat4 clip = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f) * glm::lookAt(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    Bounds plane;
    plane.lo = {-1e20f, 0.0f, -1e20f};
    plane.hi = {1e20f, 0.0f, 1e20f};
    const map::TexelRect r = map::projectedRect(clip, plane, 256);
    EXPECT_EQ(r.x0, 0);
    EXPECT_EQ(r.y0, 0);
    EXPECT_EQ(r.x1, 256);
    EXPECT_EQ(r.y1, 256);
    // Past a float's range: the extent overflows to infinity.
    Bounds huge;
    huge.lo = glm::vec3(-3e38f, -1.0f, -3e38f);
    huge.hi = glm::vec3(3e38f, 0.0f, 3e38f);
    const map::TexelRect h = map::projectedRect(clip, huge, 256);
    EXPECT_FALSE(h.empty());
    EXPECT_EQ(h.x1, 256);
    // And a small box keeps its own few texels.
    Bounds box;
    box.lo = {-0.5f, 0.0f, -0.5f};
    box.hi = {0.5f, 1.0f, 0.5f};
    const map::TexelRect b = map::projectedRect(clip, box, 256);
    EXPECT_GT(b.x0, 64);
    EXPECT_LT(b.x1, 192);
}
