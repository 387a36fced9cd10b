// The scene file's `lightGrid`: lights generated from a seed, spread evenly
// over a floor rectangle, each read as a `lights[i]` entry made of the
// grid's `light` template; and every error path of the block.
#include <shadowlab/SceneFile.h>

#include "SceneErrorCase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

std::string withGrid(const std::string& grid, const std::string& lights = "[]") {
    return R"({"lights": )" + lights + R"(, "lightGrid": )" + grid + "}";
}

Scene parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return parseScene(text, "scene.json", fs::temp_directory_path(), overrides);
}

} // namespace

// 37 lights over [-10, 30] x [-5, 5] at height 3: every one inside the
// rectangle at that height, the given share of spots (pointing down, with
// the template's cone), the rest points (no cone), the template's range,
// intensity and shadow on each; after the scene's own `lights`.
TEST(LightGrid, PlacesCountLightsOverTheRectangle) {
    const Scene s = parse(withGrid(R"({"count": 37, "seed": 5, "min": [-10, -5], "max": [30, 5], "height": 3, "spots": 0.25,
        "light": {"range": 6, "intensity": 0.5, "outerCone": 40, "shadow": {"technique": "none"}}})",
                                   R"([{"type": "directional"}])"));
    ASSERT_EQ(s.lights.size(), 38u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    int spots = 0;
    float left = 1e9f, right = -1e9f;
    for (std::size_t i = 1; i < s.lights.size(); ++i) {
        const Light& l = s.lights[i];
        EXPECT_GE(l.position.x, -10.0f);
        EXPECT_LE(l.position.x, 30.0f);
        EXPECT_GE(l.position.z, -5.0f);
        EXPECT_LE(l.position.z, 5.0f);
        EXPECT_EQ(l.position.y, 3.0f);
        EXPECT_EQ(l.range, 6.0f);
        EXPECT_EQ(l.intensity, 0.5f);
        EXPECT_EQ(l.shadow.technique, "none");
        left = std::min(left, l.position.x);
        right = std::max(right, l.position.x);
        if (l.type == LightType::Spot) {
            ++spots;
            EXPECT_EQ(l.outerConeDeg, 40.0f);
            EXPECT_EQ(l.direction, glm::vec3(0.0f, -1.0f, 0.0f));
        } else {
            EXPECT_EQ(l.type, LightType::Point);
        }
    }
    EXPECT_EQ(spots, 9);  // round(0.25 * 37)
    // Spread over the whole rectangle, not bunched: the lights reach
    // within 5 m of both ends of its 40 m.
    EXPECT_LT(left, -5.0f);
    EXPECT_GT(right, 25.0f);
}

// Nested: a count's lights are the first lights of any larger count (the
// same places, kinds and colours), so doubling the count adds lights and
// moves none. And even at every count from 16 on: cut the rectangle into
// count / 4 cells, 8 across and as many down as fit, and no cell is empty
// or holds more than twice its share (4 lights). Each of the seeds 1..5.
TEST(LightGrid, EveryCountIsTheFirstLightsOfALargerOneAndCoversTheFloor) {
    for (int seed = 1; seed <= 5; ++seed) {
        const std::string text = withGrid(R"({"count": 256, "seed": )" + std::to_string(seed) + R"(, "min": [-24, -12], "max": [24, 12]})");
        const Scene all = parse(text);
        for (int count : {16, 32, 64, 128}) {
            const Scene some = parse(text, {"lightGrid.count=" + std::to_string(count)});
            ASSERT_EQ(some.lights.size(), static_cast<std::size_t>(count));
            for (std::size_t i = 0; i < some.lights.size(); ++i) {
                EXPECT_EQ(some.lights[i].position, all.lights[i].position) << "seed " << seed << " count " << count << " light " << i;
                EXPECT_EQ(some.lights[i].type, all.lights[i].type);
                EXPECT_EQ(some.lights[i].color, all.lights[i].color);
            }
            int spots = 0;
            for (const Light& l : some.lights) spots += l.type == LightType::Spot ? 1 : 0;
            EXPECT_EQ(spots, count / 2) << "seed " << seed << " count " << count;  // the default share, 0.5
            const int across = 8, down = count / 4 / across == 0 ? 1 : count / 4 / across;
            std::vector<int> cells(static_cast<std::size_t>(across * down), 0);
            for (const Light& l : some.lights) {
                const int x = std::min(static_cast<int>((l.position.x + 24.0f) / 48.0f * static_cast<float>(across)), across - 1);
                const int y = std::min(static_cast<int>((l.position.z + 12.0f) / 24.0f * static_cast<float>(down)), down - 1);
                ++cells[static_cast<std::size_t>(y * across + x)];
            }
            const double share = static_cast<double>(count) / static_cast<double>(cells.size());
            for (std::size_t c = 0; c < cells.size(); ++c) {
                EXPECT_GE(cells[c], 1) << "seed " << seed << " count " << count << ": cell " << c << " empty";
                EXPECT_LE(cells[c], 2.0 * share) << "seed " << seed << " count " << count << ": cell " << c;
            }
        }
    }
}

// The same seed gives the same lights (positions and colours), another
// seed others; `--set lightGrid.count` (and so bench --vary) changes the
// count, and a count of 0 gives none.
TEST(LightGrid, TheSeedDecidesAndTheCountCanBeSet) {
    const std::string text = withGrid(R"({"count": 16, "seed": 3})");
    const Scene a = parse(text), b = parse(text), c = parse(text, {"lightGrid.seed=4"});
    ASSERT_EQ(a.lights.size(), 16u);
    bool differs = false;
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].position, b.lights[i].position);
        EXPECT_EQ(a.lights[i].color, b.lights[i].color);
        differs = differs || a.lights[i].position != c.lights[i].position;
    }
    EXPECT_TRUE(differs);
    EXPECT_EQ(parse(text, {"lightGrid.count=256"}).lights.size(), 256u);
    EXPECT_EQ(parse(text, {"lightGrid.count=0"}).lights.size(), 0u);
    // The documented seeds, both ends (2147483647 was refused as out of range).
    EXPECT_EQ(parse(text, {"lightGrid.seed=2147483647"}).lights.size(), 16u);
    EXPECT_EQ(parse(text, {"lightGrid.seed=0"}).lights.size(), 16u);
}

class LightGridErrors : public ::testing::TestWithParam<SceneErrorCase> {};

TEST_P(LightGridErrors, NameFilePathAndExpectation) { expectSceneError(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    All, LightGridErrors,
    ::testing::Values(
        SceneErrorCase{"NotAnObject", withGrid("[1]"), {}, "scene.json: lightGrid: expected an object, got an array"},
        SceneErrorCase{"UnknownKey", withGrid(R"({"cout": 3})"), {}, "lightGrid.cout: unknown key"},
        SceneErrorCase{"TooMany", withGrid(R"({"count": 300})"), {}, "lightGrid.count: expected at most 256 lights"},
        SceneErrorCase{"TooManyWithLights", withGrid(R"({"count": 256})", R"([{"type": "directional"}])"), {},
                       "lightGrid.count: expected at most 255 lights (at most 256 in a scene, 1 in `lights`), got 256"},
        SceneErrorCase{"TooManySet", withGrid(R"({"count": 3})"), {"lightGrid.count=1000"}, "--set lightGrid.count=1000: lightGrid.count: expected at most 256"},
        SceneErrorCase{"NegativeCount", withGrid(R"({"count": -1})"), {}, "lightGrid.count: expected an integer in 0..256, got -1"},
        SceneErrorCase{"FractionalCount", withGrid(R"({"count": 2.5})"), {}, "lightGrid.count: expected an integer"},
        // Issue 59: the default count counts against the room too (it made 320
        // lights beside 256), and the template is checked as a spot and as a
        // point light even when the count or the spots' share makes none.
        SceneErrorCase{"DefaultCountPastTheRoom", withGrid(R"({})", "[" + [] {
                           std::string many;
                           for (int i = 0; i < 200; ++i) many += std::string(i ? "," : "") + R"({"type": "directional", "shadow": {"technique": "none"}})";
                           return many;
                       }() + "]"),
                       {}, "lightGrid: count: not given, and its default 64 is more than the 56 lights left (at most 256 in a scene, 200 in `lights`)"},
        SceneErrorCase{"TemplateCheckedAtCountZero", withGrid(R"({"count": 0, "light": {"shadow": {"technique": "bogus"}}})"), {},
                       "lightGrid.light.shadow.technique: unknown technique 'bogus'"},
        SceneErrorCase{"SpotTemplateCheckedWithoutSpots", withGrid(R"({"count": 4, "spots": 0, "light": {"outerCone": 600}})"), {},
                       "lightGrid.light.outerCone: expected degrees in (0, 90), got 600"},
        // A seed past its documented range names the range (issue 59: 2147483647, the maximum, was "integer out of range").
        SceneErrorCase{"SeedPastItsRange", withGrid(R"({"seed": 2147483648})"), {}, "lightGrid.seed: expected an integer in 0..2147483647, got 2147483648"},
        SceneErrorCase{"EmptyRectangle", withGrid(R"({"min": [0, 0], "max": [0, 5]})"), {}, "lightGrid.max: expected max > min in x and z"},
        // The --set that broke it is named (issue 59: it was blamed on the file's max).
        SceneErrorCase{"EmptyRectangleBySet", withGrid(R"({"min": [-24, -12], "max": [24, 12]})"), {"lightGrid.min=[24,12]"},
                       "--set lightGrid.min=[24,12]: lightGrid.min: expected max > min in x and z"},
        SceneErrorCase{"SidePastAFloat", withGrid(R"({"min": [-3e38, -1], "max": [3e38, 1]})"), {},
                       "lightGrid.max: the rectangle's side max - min is past a float's range of 3e38 in x"},
        SceneErrorCase{"SidePastAFloatBySet", withGrid(R"({"min": [-1, -1], "max": [3e38, 1]})"), {"lightGrid.min=[-3e38,-1]"},
                       "--set lightGrid.min=[-3e38,-1]: lightGrid.min: the rectangle's side"},
        SceneErrorCase{"CornerNotAPair", withGrid(R"({"min": [0, 0, 0]})"), {}, "lightGrid.min: expected [x, z]"},
        SceneErrorCase{"SpotShare", withGrid(R"({"spots": 1.5})"), {}, "lightGrid.spots: expected a share in 0..1, got 1.5"},
        SceneErrorCase{"TemplateType", withGrid(R"({"light": {"type": "point"}})"), {}, "lightGrid.light.type: unknown key"},
        SceneErrorCase{"TemplateRange", withGrid(R"({"light": {"range": -2}})"), {}, "lightGrid.light.range: expected a number >= 0, got -2"},
        SceneErrorCase{"TemplateShadow", withGrid(R"({"light": {"shadow": {"technique": "maps"}}})"), {},
                       "lightGrid.light.shadow.technique: unknown technique 'maps'"},
        SceneErrorCase{"TemplateKeyframes", withGrid(R"({"light": {"path": {"type": "keyframes", "times": [0], "positions": [[0, 1, 0]]}}})"), {},
                       "lightGrid.light.path: expected a path of type \"sine\""},
        SceneErrorCase{"TemplateShadowSet", withGrid(R"({"count": 2})"), {"lightGrid.light.shadow.map.size=7"},
                       "--set lightGrid.light.shadow.map.size=7: lightGrid.light.shadow.map.size: map: size: expected 0 (follow the frame) or 16..16384 texels, got 7"}),
    sceneErrorCaseName);
