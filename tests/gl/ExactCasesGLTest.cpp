// Cases an independent exact checker found wrong (issue 24), each against
// the ray-traced reference with the bar the issue sets. Every scene is
// written out here, so each test says exactly what it feeds.
#include "Comparisons.h"
#include "GLTestContext.h"

#include <shadowlab/SceneFile.h>

#include <filesystem>
#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::sceneOf;
using shadowlab::test::GLTest;

namespace {

// A spot 6 m up with a 70° outer cone over a 40 m ground; four boxes stand
// across the cone's rim (it meets the ground 16.5 m out), so their large
// faces cross the cone's edge and their shadows run to the rim.
const char* const kWideCone = R"({
  "camera": { "position": [0, 26, 16], "target": [0, 0, 0], "fovY": 60 },
  "lights": [ { "type": "spot", "position": [0, 6, 0], "direction": [0, -1, 0],
                "innerCone": 60, "outerCone": 70, "shadow": { "technique": "map" } } ],
  "nodes": [
    { "name": "ground", "shape": { "type": "plane", "size": [40, 40] } },
    { "name": "west", "shape": { "type": "box", "size": [3, 4, 3] }, "translation": [-14, 2, 0] },
    { "name": "east", "shape": { "type": "box", "size": [3, 4, 3] }, "translation": [14, 2, 0], "rotation": [0, 30, 0] },
    { "name": "south", "shape": { "type": "box", "size": [6, 3, 2] }, "translation": [0, 1.5, 14] },
    { "name": "north", "shape": { "type": "box", "size": [3, 5, 3] }, "translation": [6, 2.5, -12], "rotation": [0, 20, 0] }
  ]
})";

} // namespace

class ExactCasesGLTest : public GLTest {};

// Spot shadows hold to the rim of a wide cone: no receiver misclassified
// outside the 1-pixel edge band (the issue's bar: 0). Before, the shadow
// pass discarded casters outside the cone by a per-vertex x/w interpolated
// across the boxes' faces (0.55 % false lit here), and the texels just past
// the rim were left empty for the compares at the rim to read.
TEST_F(ExactCasesGLTest, SpotShadowsHoldToTheRimOfAWideCone) {
    // At 2048^2, the size the issue measured (the default 1024^2 with filter
    // none leaves 10 pixels, 0.005 %, past the band at the rim).
    for (const char* set : {"", "lights[0].shadow.map.filter=none", "lights[0].shadow.map.format=rgba8"}) {
        SCOPED_TRACE(set);
        std::vector<std::string> overrides = {"lights[0].shadow.map.size=2048"};
        if (*set) overrides.emplace_back(set);
        const Comparison c = compareScene(sceneOf(kWideCone, overrides), 640, 360);
        ASSERT_GT(c.lights[0].referenceShadowedPixels, 500u) << "the boxes' shadows must be in view";
        EXPECT_EQ(awayFromEdges(c.lights[0]), 0.0);
    }
}

// cullFront (back faces only) on the same wide cone. The back faces meet
// the ground at each box's foot, where their depth and the ground's become
// equal, so a strip there one map texel wide is left to depth precision:
// at most 0.02 % (here: 0.009 %, 10 pixels). Before, the polygon offset was
// applied to the back faces too and lifted them off the ground there:
// 0.58 % false lit with the old cone test, 0.15 % with the new one.
TEST_F(ExactCasesGLTest, BackFacesOnlyKeepTheShadowAtACastersFoot) {
    // At 2048^2 (1024^2: 0.12 %, the strip a texel wide).
    const Comparison c = compareScene(sceneOf(kWideCone, {"lights[0].shadow.map.cullFront=true", "lights[0].shadow.map.size=2048"}), 640, 360);
    ASSERT_GT(c.lights[0].referenceShadowedPixels, 500u);
    EXPECT_LE(awayFromEdges(c.lights[0]), 0.0002);
}

// 32-bit moment maps at casters' feet on cascades-field (a 400 m field of
// boxes, trees and bunnies under a low sun) as it ships (four stabilised
// cascades of 1024², lambda 0.9): evsm4 and msm at most 0.05 % misclassified
// outside the band at 960x540, compare's default (the issue's bar; measured
// 0.040 % and 0.047 %, the depth map 0.034 %). Each stabilised cascade's
// depth range was the whole scene's along the light, about 500 m, in which
// a caster's foot and the ground under it were too close for the moments
// to part (0.059 % and 0.094 %); it is now the slice's. MSM pulled its
// moments towards the middle by 3e-5, a 16-bit value, and leaked 0.67 %
// there (now 3e-6).
TEST_F(ExactCasesGLTest, MomentMapsHoldAtCastersFeet) {
    const std::filesystem::path field = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "cascades-field.json";
    for (const char* representation : {"evsm4", "msm"}) {
        SCOPED_TRACE(representation);
        const Comparison c = compareScene(loadSceneFile(field, {std::string("lights[0].shadow.map.representation=") + representation}), 960, 540);
        ASSERT_GT(c.lights[0].referenceShadowedPixels, 3000u) << "the casters' shadows must be in view";
        EXPECT_LE(awayFromEdges(c.lights[0]), 0.0005);
    }
}

// A point light inside a closed caster (a lamp in a shade): everything
// outside is in its shadow. No face of the box faces the light, so volumes
// capped with the light-facing triangles were empty (100 % false lit with
// every method); closed meshes are now capped with the triangles facing
// away. Depth-pass is left out: it counts from the camera, which is inside
// this volume, the case docs/techniques/volume.md says it gets wrong.
TEST_F(ExactCasesGLTest, VolumesShadowEverythingOutsideALampsShade) {
    const char* const shade = R"({
      "camera": { "position": [6, 5, 8], "target": [0, 1, 0], "fovY": 50 },
      "lights": [ { "type": "point", "position": [0, 2, 0], "shadow": { "technique": "volume" } } ],
      "nodes": [
        { "name": "ground", "shape": { "type": "plane", "size": [20, 20] } },
        { "name": "shade", "shape": { "type": "box", "size": [1, 1, 1] }, "translation": [0, 2, 0] }
      ]
    })";
    for (const char* set : {"", "lights[0].shadow.volume.method=book", "lights[0].shadow.volume.extrusion=cpu",
                            "lights[0].shadow.volume.openMeshes=triangles"}) {
        SCOPED_TRACE(set);
        const Comparison c = compareScene(sceneOf(shade, *set ? std::vector<std::string>{set} : std::vector<std::string>{}), 320, 180);
        ASSERT_GT(c.lights[0].receiverPixels, 10000u);
        EXPECT_EQ(c.lights[0].referenceShadowedPixels, c.lights[0].receiverPixels) << "the reference: all in the shade's shadow";
        EXPECT_EQ(awayFromEdges(c.lights[0]), 0.0);
    }
}

// A point light in a disc's plane, inside its radius, sees the disc
// edge-on: a disc of no thickness shadows nothing (the reference: 0
// shadowed). The segment to the light met the plane at the light itself,
// inside the circle: 97.7 % false shadow. Flat and tilted by 30°.
TEST_F(ExactCasesGLTest, ADiscSeenEdgeOnFromItsPlaneShadowsNothing) {
    const std::string scene = R"({
      "camera": { "position": [4, 5, 6], "target": [0, 0, 0], "fovY": 50 },
      "lights": [ { "type": "point", "position": [0.3, 1.5, 0.2], "shadow": { "technique": "disc" } } ],
      "nodes": [
        { "name": "ground", "shape": { "type": "plane", "size": [12, 12] } },
        { "name": "disc", "shape": { "type": "disc", "radius": 1.5 }, "translation": [0, 1.5, 0] }
      ]
    })";
    // Tilted: the disc's normal is (0, cos 30°, sin 30°); the light stays in its plane.
    for (const std::vector<std::string>& set :
         {std::vector<std::string>{}, std::vector<std::string>{"nodes[1].rotation=[30, 0, 0]", "lights[0].position=[0.3, 1.3, 0.34641016]"}}) {
        SCOPED_TRACE(set.empty() ? "flat" : "tilted");
        const Comparison c = compareScene(sceneOf(scene, set), 320, 180);
        ASSERT_GT(c.lights[0].receiverPixels, 10000u);
        // Tilted, the light lies within float rounding of the disc's plane,
        // so the truth may hold a sliver of shadow (0.28 % here, a line);
        // flat, it is exactly in it.
        if (set.empty()) {
            EXPECT_EQ(c.lights[0].referenceShadowedPixels, 0u);
        }
        EXPECT_EQ(awayFromEdges(c.lights[0]), 0.0);
    }
}

// Two stabilised cascades keep a thin caster's shadow under a low sun: a
// 3 cm slab on a 200 m ground and a plate 15 cm up, the sun 10° high, the
// camera's far plane at 300 m. At most 0.05 % misclassified outside the
// band (the issue's bar; measured 0.028 %, one map and unstabilised
// cascades 0). The slices ended at the far plane, 100 m past the scene, and
// the first one's texels were so wide that the slab's 17 cm shadow strip
// nearly vanished (0.086 %); they end where the scene does now.
TEST_F(ExactCasesGLTest, StabilisedCascadesKeepAThinCastersShadow) {
    const char* const thin = R"({
      "camera": { "position": [0, 1.6, 6], "target": [0, 0, 0], "fovY": 50, "far": 300 },
      "lights": [ { "type": "directional", "direction": [-0.3, -0.1763, -0.95],
                    "shadow": { "technique": "map", "map": { "cascades": 2 } } } ],
      "nodes": [
        { "name": "ground", "shape": { "type": "plane", "size": [200, 200] } },
        { "name": "slab", "shape": { "type": "box", "size": [2, 0.03, 1] }, "translation": [-1.2, 0.015, 0] },
        { "name": "plate", "shape": { "type": "box", "size": [1.5, 0.02, 1] }, "translation": [1.2, 0.16, 0.5] }
      ]
    })";
    // At 2048^2, as the issue measured (1024^2: 0.094 %).
    const Comparison c = compareScene(sceneOf(thin, {"lights[0].shadow.map.size=2048"}));
    ASSERT_GT(c.lights[0].referenceShadowedPixels, 800u) << "the slab's and the plate's shadows must be in view";
    EXPECT_LE(awayFromEdges(c.lights[0]), 0.0005);
}
