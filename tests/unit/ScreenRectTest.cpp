// Rectangles of pixels (core/ScreenRect.h): what a box covers on the
// screen, and the base pass's shadowed rectangles merged into few.
#include "core/ScreenRect.h"
#include "geometry/ShadowRegion.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

// A caster in pieces (geometry/ShadowRegion.h: piecesSeenFrom): sides at most
// half its distance from the light, at most `most` a side, filling the box
// exactly (each cut the same float on both sides, nothing between them).
TEST(ShadowRegionTest, APieceOfACasterIsAtMostHalfItsDistanceWide) {
    Bounds sheet;
    sheet.add(glm::vec3(-8.0f, 1.98f, -8.0f));
    sheet.add(glm::vec3(0.0f, 2.0f, 8.0f));
    const glm::vec3 lamp(0.0f, 6.0f, 0.0f);  // 4 above the sheet's edge: pieces 2 wide at most
    const std::vector<Bounds> pieces = piecesSeenFrom(sheet, lamp, 8);
    ASSERT_EQ(pieces.size(), 4u * 1u * 8u);
    double volume = 0.0;
    // 1e-5: a float's rounding of the cuts (sides of 2 in a box of 16).
    for (const Bounds& p : pieces) {
        EXPECT_LE(p.hi.x - p.lo.x, 2.0f + 1e-5f);
        EXPECT_LE(p.hi.z - p.lo.z, 2.0f + 1e-5f);
        EXPECT_EQ(p.lo.y, sheet.lo.y);
        EXPECT_EQ(p.hi.y, sheet.hi.y);
        volume += double(p.size().x) * p.size().y * p.size().z;
        // Each face inside the sheet is another piece's face, exactly.
        for (int a = 0; a < 3; ++a) {
            if (p.hi[a] == sheet.hi[a]) continue;
            const bool shared = std::any_of(pieces.begin(), pieces.end(), [&](const Bounds& q) { return q.lo[a] == p.hi[a]; });
            EXPECT_TRUE(shared) << "a gap after a piece along axis " << a;
        }
    }
    // 1e-3 of 2.56: 32 pieces' float sides, each within a few ulps.
    EXPECT_NEAR(volume, double(sheet.size().x) * sheet.size().y * sheet.size().z, 1e-3);
    EXPECT_EQ(piecesSeenFrom(sheet, lamp, 2).size(), 2u * 2u) << "at most two a side";
    EXPECT_EQ(piecesSeenFrom(sheet, glm::vec3(-4.0f, 2.0f, 0.0f)).size(), 1u) << "a light inside: the whole box";
    EXPECT_TRUE(piecesSeenFrom(Bounds{}, lamp).empty());
}

// The taps' reach over receivers from `nearest` to `farthest` from the
// light (TapReach::within): a world radius counts most on the nearest, a
// pcss search and penumbra on the farthest, size (1 / nearest caster - 1 / d).
TEST(ShadowRegionTest, TheTapsReachBoundsEveryDistanceBetween) {
    const TapReach radial{0.01f, 0.5f, 0.0f, 1.0f}, pcss{0.01f, 0.0f, 0.5f, 4.0f};
    EXPECT_FLOAT_EQ(radial.within(2.0f, 20.0f), 0.01f + 0.25f);
    EXPECT_FLOAT_EQ(pcss.within(6.0f, 20.0f), 0.01f + 0.5f * (0.25f - 0.05f));
    for (float d = 6.0f; d <= 20.0f; d += 0.5f) {
        EXPECT_LE(radial.at(d), radial.within(6.0f, 20.0f));
        EXPECT_LE(pcss.at(d), pcss.within(6.0f, 20.0f));
    }
    EXPECT_FLOAT_EQ(pcss.within(6.0f, std::numeric_limits<float>::infinity()), 0.01f + 0.5f * 0.25f);
    EXPECT_FLOAT_EQ(pcss.within(2.0f, 3.0f), 0.01f) << "receivers nearer than the nearest caster: nothing of pcss";
    EXPECT_TRUE(std::isinf(pcss.within(0.0f, 1.0f)));
}
