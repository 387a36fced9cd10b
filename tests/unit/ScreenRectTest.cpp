// Rectangles of pixels (core/ScreenRect.h): what a box covers on the
// screen, and the base pass's shadowed rectangles merged into few.
#include "core/ScreenRect.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace shadowlab;

namespace {
// A 45-degree camera at the origin looking down -z, 100x100 pixels.
glm::mat4 camera() { return glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f); }
} // namespace

TEST(ScreenRectTest, ABoxInFrontCoversItsImageAPixelWider) {
    // A unit box at distance 10 centred on the view: x and y from -0.05 to
    // 0.05 of the frame's half width, pixels 47.5 to 52.5; a pixel wider
    // and rounded out: 46 to 54.
    Bounds box;
    box.add(glm::vec3(-0.5f, -0.5f, -10.5f));
    box.add(glm::vec3(0.5f, 0.5f, -9.5f));
    const PixelRect r = screenRectOf(box, camera(), glm::ivec2(100, 100));
    // Its nearer face (distance 9.5) is the larger: 0.5 / 9.5 of the half width, 2.63 pixels from the centre.
    EXPECT_EQ(r, PixelRect(46, 46, 54, 54));
}

TEST(ScreenRectTest, ABoxReachingBehindTheViewerCoversTheWholeFrame) {
    Bounds box;
    box.add(glm::vec3(-0.5f, -0.5f, -1.0f));
    box.add(glm::vec3(0.5f, 0.5f, 1.0f));  // around the eye
    EXPECT_EQ(screenRectOf(box, camera(), glm::ivec2(100, 80)), PixelRect(0, 0, 100, 80));
    EXPECT_TRUE(isEmpty(screenRectOf(Bounds{}, camera(), glm::ivec2(100, 80)))) << "an empty box covers nothing";
}

TEST(ScreenRectTest, ABoxBesideTheFrameIsClampedToIt) {
    Bounds box;
    box.add(glm::vec3(20.0f, -0.5f, -10.5f));  // far right, outside the 90-degree view
    box.add(glm::vec3(21.0f, 0.5f, -9.5f));
    const PixelRect r = screenRectOf(box, camera(), glm::ivec2(100, 100));
    EXPECT_TRUE(isEmpty(r)) << r.x << " " << r.y << " " << r.z << " " << r.w;
}

TEST(ScreenRectTest, OverlappingRectanglesMergeWhenTheirRectangleAddsLittle) {
    // Two halves of one square: their rectangle adds nothing.
    EXPECT_EQ(mergedRects({{0, 0, 10, 20}, {10, 0, 20, 20}}, 8), std::vector<PixelRect>{PixelRect(0, 0, 20, 20)});
    // One inside the other.
    EXPECT_EQ(mergedRects({{0, 0, 20, 20}, {5, 5, 10, 10}}, 8), std::vector<PixelRect>{PixelRect(0, 0, 20, 20)});
    // Two far apart stay two, and so do two crossing thin ones (their
    // rectangle, 100x100, would add nine tenths to their 1900 pixels).
    EXPECT_EQ(mergedRects({{0, 0, 10, 10}, {50, 50, 60, 60}}, 8).size(), 2u);
    EXPECT_EQ(mergedRects({{0, 45, 100, 55}, {45, 0, 55, 100}}, 8).size(), 2u);
    // Empty ones are dropped.
    EXPECT_TRUE(mergedRects({{5, 5, 5, 9}, {3, 3, 2, 2}}, 8).empty());
}

TEST(ScreenRectTest, AtMostTheAskedNumberRemainTheCheapestMergedFirst) {
    // Four small squares: two close together in a corner, two far apart.
    const std::vector<PixelRect> four = {{0, 0, 10, 10}, {12, 0, 22, 10}, {200, 200, 210, 210}, {0, 300, 10, 310}};
    const std::vector<PixelRect> three = mergedRects(four, 3);
    ASSERT_EQ(three.size(), 3u);
    EXPECT_EQ(three[0], PixelRect(0, 0, 22, 10)) << "the two neighbours, 20 pixels added, merge first";
    double covered = 0.0;
    for (const PixelRect& r : three) covered += area(r);
    EXPECT_EQ(covered, 220.0 + 100.0 + 100.0);
    // Every input pixel stays inside some output rectangle, however few.
    for (std::size_t most : {1u, 2u, 3u})
        for (const PixelRect& in : four) {
            bool inside = false;
            for (const PixelRect& out : mergedRects(four, most)) inside = inside || intersection(in, out) == in;
            EXPECT_TRUE(inside) << "at most " << most;
        }
}

TEST(ScreenRectTest, ManyRectanglesBecomeTheOneAroundThemAll) {
    std::vector<PixelRect> many;
    for (int i = 0; i <= static_cast<int>(kMergeAtMost); ++i) many.push_back({3 * i, 0, 3 * i + 1, 1});
    EXPECT_EQ(mergedRects(many, 8), std::vector<PixelRect>{PixelRect(0, 0, 3 * static_cast<int>(kMergeAtMost) + 1, 1)});
}
