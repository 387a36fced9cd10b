// The texel footprint (docs/metrics.md): screen pixels one shadow-map
// texel covers at a receiver, measured where the answer is known in closed
// form. A wall parallel to the image plane is seen at a constant world size
// per pixel, 2 d tan(fovY / 2) / height at distance d, so every pixel of it
// must report the same footprint.
#include "Comparisons.h"
#include "GLTestContext.h"

#include <shadowlab/DebugImage.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <cmath>
#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::compareScene;
using shadowlab::test::sceneOf;
using shadowlab::test::GLTest;

namespace {

// A 30 m wall in the plane z = 0 facing +z, seen from 10 m straight on
// (fovY 45 at 800x600: the frame is all wall).
std::string wallScene(const std::string& light) {
    return R"({
      "camera": { "position": [0, 0, 10], "target": [0, 0, 0], "fovY": 45 },
      "lights": [ )" + light + R"( ],
      "nodes": [ { "name": "wall", "shape": { "type": "plane", "size": [30, 30] }, "rotation": [90, 0, 0] } ]
    })";
}

constexpr int kWidth = 800, kHeight = 600;
// World size of a pixel on the wall: 2 x 10 x tan(22.5°) / 600.
const double kPixel = 2.0 * 10.0 * std::tan(22.5 * 3.14159265358979 / 180.0) / kHeight;

class TexelFootprintGLTest : public GLTest {};

} // namespace

// LearnOpenGL's fixed light camera (ortho ±10 over 1024 texels: 20/1024 m
// a texel) for a sun along (0, -1, -1): the map's right axis is x, along
// the wall, one texel long on it; its up axis (0, 1, -1)/√2 meets the wall
// √2 texels long. So the footprint is √2 x (20/1024) / pixel = 2.0 on
// every pixel. 1 % covers float rounding of the derivatives.
TEST_F(TexelFootprintGLTest, AnOrthographicMapOverAWallHasTheFootprintOfItsProjectedTexel) {
    const Comparison c = compareScene(
        sceneOf(wallScene(R"({ "type": "directional", "direction": [0, -1, -1], "shadow": { "technique": "map", "map": { "preset": "learnopengl" } } })")),
        kWidth, kHeight);
    const LightComparison& l = c.lights[0];
    ASSERT_GT(l.receiverPixels, static_cast<std::size_t>(kWidth * kHeight * 9 / 10));
    const double expected = std::sqrt(2.0) * (20.0 / 1024.0) / kPixel;
    EXPECT_NEAR(expected, 2.0, 0.01) << "the closed form itself";
    EXPECT_NEAR(l.texelFootprintP50, expected, 0.01 * expected);
    EXPECT_NEAR(l.texelFootprintP95, expected, 0.01 * expected);
    EXPECT_NEAR(l.texelFootprintMax, expected, 0.01 * expected);
}

// A point light 6 m in front of the wall: the cube's -z face sees the
// whole wall in view (|x|, |y| < 6), and on a plane square to a face's
// axis the face's coordinates are the plane's over the distance, so one
// texel is 6 x 2/size m everywhere at the default size: 0.849 pixels a
// texel at 1024^2, 1.132 at 768^2.
TEST_F(TexelFootprintGLTest, ACubeFaceSquareToAWallHasTheFootprintOfItsTexelThere) {
    const Comparison c = compareScene(sceneOf(wallScene(R"({ "type": "point", "position": [0, 0, 6], "shadow": { "technique": "map" } })")),
                                      kWidth, kHeight);
    const LightComparison& l = c.lights[0];
    ASSERT_GT(l.receiverPixels, static_cast<std::size_t>(kWidth * kHeight * 9 / 10));
    const double expected = 6.0 * (2.0 / static_cast<double>(MapOptions{}.size)) / kPixel;
    EXPECT_NEAR(l.texelFootprintP50, expected, 0.01 * expected);
    EXPECT_NEAR(l.texelFootprintP95, expected, 0.01 * expected);
    EXPECT_NEAR(l.texelFootprintMax, expected, 0.01 * expected);
}

// On a bundled scene with a tight fit, a map of twice the side halves the
// footprint (within 5 %: the fit's margins are whole texels); techniques
// without a map measure nothing.
TEST_F(TexelFootprintGLTest, TwiceTheMapsSideHalvesTheFootprintAndNoMapMeasuresNothing) {
    const std::string scene = std::string(SHADOWLAB_SOURCE_DIR) + "/scenes/learnopengl-shadow-mapping.json";
    const Comparison small = compareScene(loadSceneFile(scene, {"lights[0].shadow.map.size=512"}), 480, 360);
    const Comparison large = compareScene(loadSceneFile(scene, {"lights[0].shadow.map.size=1024"}), 480, 360);
    ASSERT_GT(small.lights[0].texelFootprintP95, 0.0);
    EXPECT_NEAR(small.lights[0].texelFootprintP50 / large.lights[0].texelFootprintP50, 2.0, 0.1);
    EXPECT_NEAR(small.lights[0].texelFootprintP95 / large.lights[0].texelFootprintP95, 2.0, 0.1);
    const Comparison none = compareScene(loadSceneFile(scene, {"lights[0].shadow.technique=none"}), 480, 360);
    EXPECT_LT(none.lights[0].texelFootprintP50, 0.0);
}

// compare asks Renderer::debugImages for the texel density alone: it gets
// that kind only (no map or cube read back), with the same values as
// among every kind; a 2D map with cascades and a point light's cube.
TEST_F(TexelFootprintGLTest, AskedForOneKindDebugImagesMakeOnlyThatKindAndTheSameValues) {
    const std::string sun = R"({"type": "directional", "direction": [0, -1, -1], "shadow": {"technique": "map", "map": {"size": 256, "cascades": 2}}})";
    const std::string lamp = R"({"type": "point", "position": [0, 0, 4], "shadow": {"technique": "map", "map": {"size": 256}}})";
    const Scene scene = sceneOf(wallScene(sun + ", " + lamp));
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {160, 120});
    const std::vector<DebugImage> every = renderer.debugImages(scene);
    const std::vector<DebugImage> density = renderer.debugImages(scene, {{DebugImageKind::TexelDensity}});
    ASSERT_EQ(density.size(), 2u) << "one texel-density image per light";
    std::size_t compared = 0;
    for (const DebugImage& d : density) {
        EXPECT_EQ(d.kind, DebugImageKind::TexelDensity);
        for (const DebugImage& e : every)
            if (e.kind == DebugImageKind::TexelDensity && e.light == d.light) {
                EXPECT_EQ(e.values, d.values) << d.name;
                EXPECT_EQ(e.image.pixels, d.image.pixels) << d.name;
                ++compared;
            }
    }
    EXPECT_EQ(compared, 2u);
    EXPECT_GT(every.size(), density.size()) << "every kind: the maps, the cube cross and the cascades too";
}
