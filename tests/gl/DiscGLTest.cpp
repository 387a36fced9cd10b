// Technique "disc" (issue 18, Ganovelli et al. exercise 8.6.2-1): flat discs'
// shadows computed exactly in the light pass, without a shadow pass, match
// the ray-traced reference (the discs as 256-gons: their rims stay within
// the 1-pixel band here) with no misclassified pixel outside the band,
// whatever the discs' orientation and scale and the light's type.
#include "GLTestContext.h"
#include "Comparisons.h"

#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/SceneFile.h>

#include <filesystem>

using namespace shadowlab;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {
const fs::path kDiscs = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "discs.json";
} // namespace

class DiscGLTest : public GLTest {};

TEST_F(DiscGLTest, DiscShadowsAreExactUnderEveryKindOfLight) {
    for (const char* light : {"", R"(lights[0]={"type": "spot", "position": [1, 7, 1], "direction": [0, -1, 0], "outerCone": 60, "shadow": {"technique": "disc"}})",
                              R"(lights[0]={"type": "point", "position": [1, 7, 1], "shadow": {"technique": "disc"}})"}) {
        SCOPED_TRACE(light);
        const Scene scene = loadSceneFile(kDiscs, *light ? std::vector<std::string>{light} : std::vector<std::string>{});
        const Comparison c = compareScene(scene);
        ASSERT_GT(c.lights[0].referenceShadowedPixels, 10000u) << "the five discs' shadows must be in view";
        EXPECT_EQ(awayFromEdges(c.lights[0]), 0.0);
    }
}

// Two disc lights in one frame, each its own variant (DISC_COUNT: the
// sun every disc, the lamp one): the sun stays exact (a count too small
// would drop discs from its test), and the lamp's classification is what
// it is alone in the scene (the same pixels misclassified, both ways).
TEST_F(DiscGLTest, EachLightTestsItsOwnDiscs) {
    const std::string sun = R"({"name": "sun", "type": "directional", "direction": [0.3, -1.0, 0.2], "shadow": {"technique": "disc"}})";
    const std::string lamp = R"({"name": "lamp", "type": "point", "position": [0.5, 6, 0.5], "intensity": 0.5,
                                 "shadow": {"technique": "disc", "disc": {"casters": "ufo 1"}}})";
    const Comparison both = compareScene(loadSceneFile(kDiscs, {"lights=[" + sun + ", " + lamp + "]"}), 480, 270);
    const Comparison alone = compareScene(loadSceneFile(kDiscs, {"lights=[" + lamp + "]"}), 480, 270);
    ASSERT_EQ(both.lights.size(), 2u);
    EXPECT_EQ(awayFromEdges(both.lights[0]), 0.0);
    EXPECT_GT(both.lights[1].falseLitAwayFromEdges, 0.001);  // the other discs' shadows: only the reference has them
    EXPECT_EQ(both.lights[1].falseLit, alone.lights[0].falseLit);
    EXPECT_EQ(both.lights[1].falseShadow, alone.lights[0].falseShadow);
}

// Only the named discs cast; a named node that is no disc, or no node at
// all, is an error naming the option.
TEST_F(DiscGLTest, CastersNamesTheDiscs) {
    const Comparison all = compareScene(loadSceneFile(kDiscs), 480, 270);
    const Comparison one = compareScene(loadSceneFile(kDiscs, {"lights[0].shadow.disc.casters=\"ufo 1\""}), 480, 270);
    EXPECT_EQ(one.lights[0].referenceShadowedPixels, all.lights[0].referenceShadowedPixels);  // the reference sees every disc...
    EXPECT_GT(one.lights[0].falseLitAwayFromEdges, 0.01);                                     // ...the technique only ufo 1
    EXPECT_EQ(awayFromEdges(all.lights[0]), 0.0);
    EXPECT_EQ(one.lights[0].falseShadow, 0.0);
    for (const auto& [setting, message] : {std::pair<std::string, std::string>{"lights[0].shadow.disc.casters=\"ground\"",
                                                                                "lights[0].shadow.disc.casters: node 'ground' is not a disc shape"},
                                           {"lights[0].shadow.disc.casters=\"ufo 9\"", "lights[0].shadow.disc.casters: no node named 'ufo 9'"}}) {
        const Scene scene = loadSceneFile(kDiscs, {setting});
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        try {
            renderer.render(scene);
            ADD_FAILURE() << "no error for " << setting;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
}

// Variation 2: casters that are always nearer the light than what they
// shadow need few depth bits. Format r8 keeps one byte a texel (rounded up:
// no caster shadows itself) and matches the reference on the discs as the
// 32-bit map does (0 outside the band), in a quarter of its memory (the
// shadow pass's mapBytes; the depth test's buffer is one layer shared by
// every r8 map).
TEST_F(DiscGLTest, AnEightBitMapSufficesForCastersNearerTheLight) {
    double bytes[2] = {0.0, 0.0};
    int k = 0;
    for (const char* format : {"depth32f", "r8"}) {
        SCOPED_TRACE(format);
        const Scene scene = loadSceneFile(kDiscs, {"lights[0].shadow.technique=\"map\"", "lights[0].shadow.map.filter=\"none\"",
                                                   std::string("lights[0].shadow.map.format=\"") + format + "\""});
        EXPECT_EQ(awayFromEdges(compareScene(scene).lights[0]), 0.0);
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        for (const auto& [name, value] : renderer.render(scene).counters)
            if (name == "shadow[0].mapBytes") bytes[k] = value;
        ++k;
    }
    const RenderOptions defaults;
    const double side = frameMapSize(defaults.width, defaults.height);  // the default size (size 0: the frame's)
    const double texels = side * side;
    EXPECT_EQ(bytes[0], 4.0 * texels);
    EXPECT_EQ(bytes[1], 1.0 * texels);
}
