// The shadow atlas's packing (core/AtlasLayout.h): every tile inside the
// atlas, no two overlapping, the sizes asked for when they fit, and when
// they do not, the largest halved first and nothing below the least side.
#include "core/AtlasLayout.h"

#include "SceneErrorCase.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <random>

using namespace shadowlab;

namespace {

// Texels covered by more than one tile, or outside the atlas: both must be 0.
struct Coverage {
    std::size_t overlapping = 0, outside = 0;
};

Coverage coverage(const AtlasLayout& layout, const std::vector<AtlasRequest>& requests, int size) {
    std::vector<std::uint8_t> used(static_cast<std::size_t>(size) * size, 0);
    Coverage c;
    for (std::size_t i = 0; i < requests.size(); ++i)
        for (const glm::ivec2& o : layout.placed[i].origins)
            for (int y = o.y; y < o.y + layout.placed[i].side; ++y)
                for (int x = o.x; x < o.x + layout.placed[i].side; ++x) {
                    if (x < 0 || y < 0 || x >= size || y >= size) {
                        ++c.outside;
                        continue;
                    }
                    if (used[static_cast<std::size_t>(y) * size + x]++) ++c.overlapping;
                }
    return c;
}

} // namespace

TEST(AtlasLayout, RandomRequestsNeitherOverlapNorLeave) {
    std::mt19937 rng(7);
    for (int round = 0; round < 40; ++round) {
        std::vector<AtlasRequest> requests;
        const int lights = 1 + static_cast<int>(rng() % 60);
        for (int i = 0; i < lights; ++i) requests.push_back({rng() % 2 ? 6 : 1, 8 << (rng() % 7)});
        const int size = 1024;
        const AtlasLayout layout = packAtlas(requests, size, 8);
        ASSERT_TRUE(layout.fits);
        const Coverage c = coverage(layout, requests, size);
        EXPECT_EQ(c.overlapping, 0u) << "round " << round;
        EXPECT_EQ(c.outside, 0u) << "round " << round;
        double area = 0.0;
        for (std::size_t i = 0; i < requests.size(); ++i) area += requests[i].tiles * double(layout.placed[i].side) * layout.placed[i].side;
        EXPECT_LE(area, double(size) * size);
        EXPECT_EQ(area, layout.texelsUsed);
    }
}

// Sides that are not powers of two (a map.size of 768 or 17 reached the
// packer as tile sides before 2026-12-07): each is taken as the power of
// two below it, and no two tiles overlap or leave the atlas. Before, six
// faces of 768 in a 4096 atlas overlapped (the Z-order cell of a 768^2
// tile is not a square), and 768s with their halves in many-lights at
// 1920x1080 ran past the 8192^2 atlas.
TEST(AtlasLayout, SidesThatAreNotPowersOfTwoNeitherOverlapNorLeave) {
    const std::vector<AtlasRequest> cube{{1, 768}, {1, 768}, {1, 768}, {1, 768}, {1, 768}, {1, 768}};
    const AtlasLayout six = packAtlas(cube, 4096, 32);
    ASSERT_TRUE(six.fits);
    const Coverage c6 = coverage(six, cube, 4096);
    EXPECT_EQ(c6.overlapping, 0u);
    EXPECT_EQ(c6.outside, 0u);
    for (const AtlasPlacement& p : six.placed) {
        EXPECT_EQ(p.side, 512);
        EXPECT_FALSE(p.shrunk());  // rounding is not shrinking: nothing to note
    }
    std::mt19937 rng(11);
    for (int round = 0; round < 40; ++round) {
        std::vector<AtlasRequest> requests;
        const int lights = 1 + static_cast<int>(rng() % 80);
        for (int i = 0; i < lights; ++i) requests.push_back({rng() % 2 ? 6 : 1, 17 + static_cast<int>(rng() % 1000)});
        const int size = 2048;
        const AtlasLayout layout = packAtlas(requests, size, 24, 0.0);
        ASSERT_TRUE(layout.fits) << "round " << round;
        const Coverage c = coverage(layout, requests, size);
        EXPECT_EQ(c.overlapping, 0u) << "round " << round;
        EXPECT_EQ(c.outside, 0u) << "round " << round;
        for (const AtlasPlacement& p : layout.placed) EXPECT_EQ(p.side & (p.side - 1), 0) << "round " << round << ": side " << p.side;
    }
}

TEST(AtlasLayout, KeepsTheSizesAskedForWhenTheyFit) {
    const std::vector<AtlasRequest> requests{{6, 256}, {1, 512}, {1, 64}, {6, 128}};
    const AtlasLayout layout = packAtlas(requests, 1024, 16);
    for (std::size_t i = 0; i < requests.size(); ++i) {
        EXPECT_EQ(layout.placed[i].side, requests[i].side);
        EXPECT_FALSE(layout.placed[i].shrunk());
    }
}

TEST(AtlasLayout, ShrinksTheLargestFirstAndStopsAtTheLeast) {
    // 2 x 512^2 + 4 x 128^2 = 589824 > 512^2 = 262144: the 512s halve to
    // 256 (196608 in all, fits); the 128s keep their size.
    const std::vector<AtlasRequest> requests{{1, 512}, {1, 512}, {4, 128}};
    const AtlasLayout layout = packAtlas(requests, 512, 32);
    ASSERT_TRUE(layout.fits);
    EXPECT_EQ(layout.placed[0].side, 256);
    EXPECT_TRUE(layout.placed[0].shrunk());
    EXPECT_EQ(layout.placed[2].side, 128);
    EXPECT_FALSE(layout.placed[2].shrunk());
    // 300 tiles of at least 32^2 cannot fit 256^2 (64 such tiles).
    const AtlasLayout full = packAtlas({{300, 64}}, 256, 32);
    EXPECT_FALSE(full.fits);
}

// A texel budget under the atlas's area: the largest tiles halve until the
// tiles take at most the budget; tiles already at the least side past the
// budget still fit the atlas, and the layout says it is over the budget.
TEST(AtlasLayout, ShrinksToTheBudgetAndFitsPastItAtTheLeast) {
    // 4 x 256^2 + 8 x 64^2 = 294912 texels in a 1024^2 atlas, a budget of
    // 100000: the 256s halve to 128 (98304 in all).
    const std::vector<AtlasRequest> requests{{4, 256}, {8, 64}};
    const AtlasLayout layout = packAtlas(requests, 1024, 32, 100000.0);
    ASSERT_TRUE(layout.fits);
    EXPECT_FALSE(layout.overBudget);
    EXPECT_EQ(layout.placed[0].side, 128);
    EXPECT_EQ(layout.placed[1].side, 64);
    EXPECT_LE(layout.texelsUsed, 100000.0);
    EXPECT_EQ(coverage(layout, requests, 1024).overlapping, 0u);
    // The same with no budget (0): the sizes asked for.
    EXPECT_EQ(packAtlas(requests, 1024, 32, 0.0).placed[0].side, 256);
    // No more given up than the budget asks: four 512^2 tiles (1048576
    // texels) in a budget of 900000: the first alone halves (851968).
    const AtlasLayout one = packAtlas({{1, 512}, {1, 512}, {1, 512}, {1, 512}}, 2048, 32, 900000.0);
    EXPECT_EQ(one.placed[0].side, 256);
    for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(one.placed[i].side, 512) << "tile " << i;
    // 200 tiles of 32^2 (204800 texels) past a budget of 100000: at the least side, over the budget, in the atlas.
    const AtlasLayout least = packAtlas({{200, 64}}, 1024, 32, 100000.0);
    ASSERT_TRUE(least.fits);
    EXPECT_TRUE(least.overBudget);
    EXPECT_EQ(least.placed[0].side, 32);
}

TEST(AtlasLayout, TileSideFollowsTheScreen) {
    EXPECT_EQ(tileSideFor(100.0f, 1.0f, 32, 1024), 128);
    EXPECT_EQ(tileSideFor(128.0f, 1.0f, 32, 1024), 128);
    EXPECT_EQ(tileSideFor(3.0f, 1.0f, 32, 1024), 32);
    EXPECT_EQ(tileSideFor(5000.0f, 1.0f, 32, 1024), 1024);
    EXPECT_EQ(tileSideFor(100.0f, 0.25f, 8, 1024), 32);
}

// A side kept while the want stays within [0.45, 1.1] of it: a light
// moving a little keeps its tiles (and the atlas its packing).
TEST(AtlasLayout, TileSideKeepsItsSideWithinTheBand) {
    EXPECT_EQ(tileSideKeeping(100.0f, 1.0f, 32, 1024, 0), 128);      // none before: tileSideFor's
    EXPECT_EQ(tileSideKeeping(130.0f, 1.0f, 32, 1024, 128), 128);    // 1.02x: kept (tileSideFor: 256)
    EXPECT_EQ(tileSideKeeping(141.0f, 1.0f, 32, 1024, 128), 256);    // 1.10x: past the band
    EXPECT_EQ(tileSideKeeping(60.0f, 1.0f, 32, 1024, 128), 128);     // 0.47x: kept (tileSideFor: 64)
    EXPECT_EQ(tileSideKeeping(57.0f, 1.0f, 32, 1024, 128), 64);      // 0.45x: below the band
    EXPECT_EQ(tileSideKeeping(250.0f, 1.0f, 32, 128, 256), 128);     // a side past maxSide is not kept
    EXPECT_EQ(tileSideKeeping(10.0f, 1.0f, 64, 1024, 32), 64);       // nor one under minSide
}

// What a point light's cube face sees of its reach, cut to the receivers:
// every point of the sphere in the face's pyramid and in the receivers'
// box lies in the face's box (20 lights, 4000 points each, fixed seed),
// and above a floor the face looking down sees a square as wide as the
// light is high, not the sphere's width.
TEST(AtlasLayout, ACubeFaceReachHoldsWhatTheFaceSees) {
    std::mt19937 rng(5);
    const auto unit = [&] { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); };
    Bounds receivers;
    receivers.lo = {-6.0f, 0.0f, -4.0f};
    receivers.hi = {6.0f, 3.0f, 4.0f};
    int checked = 0;
    for (int k = 0; k < 20; ++k) {
        const glm::vec3 light(unit() * 14.0f - 7.0f, unit() * 4.0f - 0.5f, unit() * 10.0f - 5.0f);
        const float range = 0.5f + 6.0f * unit();
        std::array<Bounds, 6> boxes;
        for (int f = 0; f < 6; ++f) boxes[static_cast<std::size_t>(f)] = cubeFaceReach(light, range, f, receivers);
        for (int n = 0; n < 4000; ++n) {
            const glm::vec3 d = glm::vec3(unit(), unit(), unit()) * 2.0f - 1.0f;
            if (glm::length(d) > 1.0f) continue;
            const glm::vec3 p = light + d * range;
            if (glm::any(glm::lessThan(p, receivers.lo)) || glm::any(glm::greaterThan(p, receivers.hi))) continue;
            // The face a cube map picks for direction d (as shadow_atlas.glsl's atlasFace).
            const glm::vec3 a = glm::abs(d);
            const int face = a.x >= a.y && a.x >= a.z ? (d.x > 0.0f ? 0 : 1) : a.y >= a.z ? (d.y > 0.0f ? 2 : 3) : (d.z > 0.0f ? 4 : 5);
            const Bounds& b = boxes[static_cast<std::size_t>(face)];
            ASSERT_FALSE(b.empty()) << "light " << k << " face " << face;
            ASSERT_TRUE(glm::all(glm::greaterThanEqual(p, b.lo - 1e-5f)) && glm::all(glm::lessThanEqual(p, b.hi + 1e-5f)))
                << "light " << k << " face " << face << " point " << p.x << ", " << p.y << ", " << p.z;
            ++checked;
        }
    }
    EXPECT_GT(checked, 10000);  // measured: 12666
    // A lamp 2.5 m over a floor, reaching 5 m: its face down sees the floor
    // within 2.5 m each way; a face to the side reaches 5 m out and 3.54 m across.
    Bounds floor;
    floor.lo = {-20.0f, 0.0f, -20.0f};
    floor.hi = {20.0f, 0.0f, 20.0f};
    const Bounds down = cubeFaceReach({0.0f, 2.5f, 0.0f}, 5.0f, 3, floor);
    EXPECT_NEAR(down.lo.x, -2.5f, 1e-5f);
    EXPECT_NEAR(down.hi.z, 2.5f, 1e-5f);
    const Bounds side = cubeFaceReach({0.0f, 2.5f, 0.0f}, 5.0f, 0, floor);
    EXPECT_NEAR(side.hi.x, 5.0f, 1e-5f);
    EXPECT_NEAR(side.hi.z, 3.5355f, 1e-3f);
    EXPECT_TRUE(cubeFaceReach({0.0f, 2.5f, 0.0f}, 5.0f, 2, floor).empty());  // the face up sees no floor
}

// A box's extent on screen: its rectangle's larger side in pixels, cut to
// the frame; 0 outside it; none with a corner behind the eye.
TEST(AtlasLayout, ScreenExtentOfABox) {
    const glm::mat4 clip = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);  // looking down -z
    Bounds box;
    box.lo = {-1.0f, -0.5f, -11.0f};
    box.hi = {1.0f, 0.5f, -10.0f};
    const std::optional<float> e = screenExtentOf(box, clip, {400, 400});
    ASSERT_TRUE(e.has_value());
    EXPECT_NEAR(*e, 40.0f, 1e-3f);  // 2 m across at 10 m, 90 degrees over 400 pixels: 2 / 20 x 400
    Bounds aside = box;
    aside.lo.x += 30.0f;
    aside.hi.x += 30.0f;
    EXPECT_EQ(screenExtentOf(aside, clip, {400, 400}), std::optional<float>(0.0f));
    Bounds behind = box;
    behind.hi.z = 1.0f;
    EXPECT_FALSE(screenExtentOf(behind, clip, {400, 400}).has_value());
}

// The scene file's `shadowAtlas` and the map's `atlas` option: each bad
// value a one-line error naming the file (or the --set flag) and the path.
namespace {
std::string withAtlas(const std::string& atlas, const std::string& light = R"({"type": "spot", "position": [0, 2, 0]})") {
    return R"({"lights": [)" + light + R"(], "shadowAtlas": )" + atlas + "}";
}
const std::string kAtlasSpot = R"({"type": "spot", "position": [0, 2, 0], "shadow": {"technique": "map", "map": {"atlas": true}}})";
} // namespace

class ShadowAtlasErrors : public ::testing::TestWithParam<SceneErrorCase> {};

TEST_P(ShadowAtlasErrors, NameFilePathAndExpectation) { expectSceneError(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    All, ShadowAtlasErrors,
    ::testing::Values(
        SceneErrorCase{"NotAnObject", withAtlas("4096"), {}, "scene.json: shadowAtlas: expected an object, got a number"},
        SceneErrorCase{"UnknownKey", withAtlas(R"({"sise": 4096})"), {}, "shadowAtlas.sise: unknown key"},
        SceneErrorCase{"SizeNotPowerOfTwo", withAtlas(R"({"size": 3000})"), {}, "shadowAtlas.size: expected a power of two, got 3000"},
        SceneErrorCase{"SizeTooLarge", withAtlas(R"({"size": 32768})"), {}, "shadowAtlas.size: expected an integer in 256..16384, got 32768"},
        SceneErrorCase{"SizeSet", withAtlas("{}"), {"shadowAtlas.size=100"}, "--set shadowAtlas.size=100: shadowAtlas.size: expected an integer in 256..16384"},
        SceneErrorCase{"TexelsPerPixel", withAtlas(R"({"texelsPerPixel": 0})"), {}, "shadowAtlas.texelsPerPixel: expected 0.0625..16, got 0"},
        SceneErrorCase{"MaxTileOverSize", withAtlas(R"({"size": 512, "maxTile": 1024})"), {}, "shadowAtlas.maxTile: expected an integer in 8..512, got 1024"},
        SceneErrorCase{"MinTileOverMax", withAtlas(R"({"minTile": 2048})"), {}, "shadowAtlas.minTile: expected an integer in 8..1024, got 2048"},
        SceneErrorCase{"MinTileNotPowerOfTwo", withAtlas(R"({"minTile": 48})"), {}, "shadowAtlas.minTile: expected a power of two, got 48"},
        SceneErrorCase{"UpdateBudget", withAtlas(R"({"updateBudget": -1})"), {}, "shadowAtlas.updateBudget: expected an integer in 0..65536, got -1"},
        SceneErrorCase{"BudgetPerPixel", withAtlas(R"({"budgetPerPixel": -1})"), {}, "shadowAtlas.budgetPerPixel: expected 0..4096 texels a pixel of the frame, got -1"},
        SceneErrorCase{"BudgetPerPixelSet", withAtlas("{}"), {"shadowAtlas.budgetPerPixel=5000"},
                       "--set shadowAtlas.budgetPerPixel=5000: shadowAtlas.budgetPerPixel: expected 0..4096 texels a pixel of the frame, got 5000"},
        SceneErrorCase{"AtlasOnADirectionalLight", withAtlas("{}", R"({"type": "directional", "shadow": {"technique": "map", "map": {"atlas": true}}})"), {},
                       "scene.json: lights[0].shadow.map.atlas: map: atlas is for spot and point lights"},
        SceneErrorCase{"AtlasWithPcf", withAtlas("{}", kAtlasSpot), {"lights[0].shadow.map.filter=grid"},
                       "--set lights[0].shadow.map.filter=grid: lights[0].shadow.map.filter: map: filter \"grid\": an atlas tile is looked up with one tap; use filter \"none\" or \"hardware\" with atlas"},
        SceneErrorCase{"AtlasWithRgba8", withAtlas("{}", kAtlasSpot), {"lights[0].shadow.map.format=rgba8"}, "lights[0].shadow.map.format: map: format: the atlas is depth32f"},
        SceneErrorCase{"AtlasWithMoments", withAtlas("{}", kAtlasSpot), {"lights[0].shadow.map.representation=vsm"}, "lights[0].shadow.map.representation: map: representation: the atlas holds depth"}),
    sceneErrorCaseName);
