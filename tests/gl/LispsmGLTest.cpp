// Warp "lispsm" (light space perspective shadow maps, issue 26): a
// directional light's fitted box seen through a perspective along the view,
// so that texels shrink towards the camera. Measured against the reference
// and by the texel footprint (screen pixels a map texel covers).
#include "Comparisons.h"
#include "GLTestContext.h"

#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::glContext;
using shadowlab::test::sceneOf;
using shadowlab::test::GLTest;

namespace {

class LispsmGLTest : public GLTest {};

std::string bundled(const char* name) { return std::string(SHADOWLAB_SOURCE_DIR) + "/scenes/" + name; }

} // namespace

// The issue's street (300 m from eye height, a sun 13 degrees high) with
// one 2048^2 map instead of its four cascades. Measured at 800x600: the
// tight fit's p95 footprint 20.5 pixels a texel, 2.4 % misclassified away
// from the band (shadow tips near the camera lost); lispsm 5.0 and 0.13 %.
// The bars: at most half the footprint and a quarter of the misclassified.
TEST_F(LispsmGLTest, DownALongStreetTheMapGivesTheNearViewItsTexels) {
    const std::vector<std::string> oneMap{"lights[0].shadow.map.cascades=1"};
    std::vector<std::string> warped = oneMap;
    warped.push_back("lights[0].shadow.map.warp=\"lispsm\"");
    const Comparison tight = compareScene(loadSceneFile(bundled("long-view.json"), oneMap), 800, 600);
    const Comparison lispsm = compareScene(loadSceneFile(bundled("long-view.json"), warped), 800, 600);
    ASSERT_GT(lispsm.lights[0].referenceShadowedPixels, 5000u);
    EXPECT_LE(lispsm.lights[0].texelFootprintP95, 0.5 * tight.lights[0].texelFootprintP95);
    EXPECT_LE(awayFromEdges(lispsm.lights[0]), 0.25 * awayFromEdges(tight.lights[0]));
}

// Small scenes keep their shadows exactly as the unwarped map does (0
// misclassified away from the band on each, measured), with no acne: the
// offsets take each texel's size where the receiver is, the long and narrow
// texels far from the camera by their extent along the receiver's slope.
TEST_F(LispsmGLTest, SmallScenesKeepTheirShadowsWithoutAcne) {
    for (const char* name : {"two-boxes-sun.json", "torus-floating.json", "spheres-sun.json"}) {
        SCOPED_TRACE(name);
        const Comparison c = compareScene(loadSceneFile(bundled(name), {"lights[0].shadow.map.warp=\"lispsm\""}), 480, 270);
        ASSERT_GT(c.lights[0].referenceShadowedPixels, 100u);
        EXPECT_EQ(c.lights[0].falseShadowAwayFromEdges, 0.0);  // acne would be false shadow on lit receivers
        EXPECT_LE(awayFromEdges(c.lights[0]), 0.0005);
    }
}

// Cascades fitted tightly (stabilize false) take the warp slice by slice,
// each slice's warp near plane at least its own near end. On cascades-field
// as shipped but unstabilised (four of 1024^2, 960x540), measured: 0.007 %
// misclassified away from the band against 0.011 % unwarped, p95 footprint
// 8.6 against 6.7 pixels a texel (each slice's far end gets fewer texels).
// The bar: the issue's 0.05 %, and no more than the unwarped cascades.
TEST_F(LispsmGLTest, TightCascadesTakeTheWarpSliceBySlice) {
    const std::vector<std::string> tight{"lights[0].shadow.map.stabilize=false"};
    std::vector<std::string> warped = tight;
    warped.push_back("lights[0].shadow.map.warp=\"lispsm\"");
    const Comparison none = compareScene(loadSceneFile(bundled("cascades-field.json"), tight));
    const Comparison lispsm = compareScene(loadSceneFile(bundled("cascades-field.json"), warped));
    EXPECT_LE(awayFromEdges(lispsm.lights[0]), 0.0005);
    EXPECT_LE(awayFromEdges(lispsm.lights[0]), awayFromEdges(none.lights[0]));
}

// A camera looking along the light: the warp has no axis (the view's
// direction across the light vanishes), so the map is the unwarped one,
// the frame the same pixel for pixel. The same scene under a light 30
// degrees off the view is warped: its frame differs (so this test sees the
// warp at all).
TEST_F(LispsmGLTest, ALightAlongTheViewIsNotWarped) {
    const char* const json = R"({
      "camera": { "position": [0, 10, 0.001], "target": [0, 0, 0], "fovY": 50 },
      "lights": [ { "type": "directional", "direction": [0, -1, -0.0001], "shadow": { "technique": "map" } } ],
      "nodes": [
        { "name": "ground", "shape": { "type": "plane", "size": [20, 20] } },
        { "name": "box", "shape": { "type": "box", "size": [1, 1, 1] }, "translation": [1, 2, 0] }
      ] })";
    const auto frame = [&](const char* warp, const char* direction) {
        const Scene scene = sceneOf(json, {std::string("lights[0].shadow.map.warp=\"") + warp + "\"",
                                           std::string("lights[0].direction=") + direction});
        Renderer renderer(glContext());
        renderer.upload(scene);
        renderer.render(scene, RenderOptions{320, 240});
        return renderer.readColor().pixels;
    };
    const auto differing = [](const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
        std::size_t differ = 0;
        for (std::size_t p = 0; p < a.size(); p += 4) differ += a[p] != b[p] || a[p + 1] != b[p + 1] || a[p + 2] != b[p + 2];
        return differ;
    };
    const char* const along = "[0, -1, -0.0001]";
    const char* const across = "[0, -1, -0.58]";
    EXPECT_EQ(differing(frame("none", along), frame("lispsm", along)), 0u);
    EXPECT_GT(differing(frame("none", across), frame("lispsm", across)), 0u);
}

// What the warp is not for, refused in one line naming the option:
// stabilised cascades (snapped to whole texels, which a warp undoes).
TEST_F(LispsmGLTest, SpotLightsStabilisedCascadesAndPcssAreRefused) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {R"({ "lights": [ { "type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "shadow": { "technique": "map", "map": { "warp": "lispsm" } } } ] })",
         "warp \"lispsm\" is for directional lights"},
        {R"({ "lights": [ { "type": "directional", "direction": [0, -1, 0.3], "shadow": { "technique": "map", "map": { "warp": "lispsm", "cascades": 4 } } } ] })",
         "warp \"lispsm\" with cascades takes stabilize false"},
        {R"({ "lights": [ { "type": "directional", "direction": [0, -1, 0.3], "size": 1, "shadow": { "technique": "map", "map": { "warp": "lispsm", "filter": "pcss" } } } ] })",
         "filter \"pcss\" takes distances along the light from an unwarped map"},
    };
    for (const auto& [json, message] : cases) {
        try {
            sceneOf(json);
            ADD_FAILURE() << "accepted: " << json;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("lights[0].shadow.map."), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    }
}
