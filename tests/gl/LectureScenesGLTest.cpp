// The lecture scenes (scenes/lecture/): each shows one effect the shadow
// lectures teach, at a frame size of 400x225, measured against the exact
// reference; each test fails if its effect disappears, and again if its fix
// stops fixing it. The fix is the command README.md gives.
#include "GLTestContext.h"
#include "Comparisons.h"

#include <shadowlab/Compare.h>
#include <shadowlab/SceneFile.h>

#include <cmath>
#include <filesystem>
#include <algorithm>
#include <map>

using namespace shadowlab;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;

namespace {

LightComparison lectureScene(const std::string& name, const std::vector<std::string>& overrides = {}) {
    const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "lecture" / (name + ".json"), overrides);
    return compareScene(scene, 400, 225).lights.at(0);
}

// The defaults' bar for hard shadows: misclassified outside the 1-pixel
// edge band (docs/metrics.md).
constexpr double kDefaultsBar = 0.0005;

} // namespace

class LectureScenesGLTest : public GLTest {};

// Acne: no bias of any kind and one nearest tap, so every lit surface
// shadows itself in stripes, the ground included (a thin box: a flat plane
// that shadows nothing is left out of the map). Measured: 48 % of the lit
// receivers are falsely shadowed away from edges. Bar: more than 20 %, a
// striped half of every lit surface, not a few stray pixels. The fix, the
// default bias (a map block of filter "none" alone, so the filter stays
// the lecture's one tap): within the defaults' bar.
TEST_F(LectureScenesGLTest, AcneCoversTheLitSurfacesAndTheDefaultBiasRemovesIt) {
    const LightComparison acne = lectureScene("acne");
    EXPECT_GT(acne.falseShadowAwayFromEdges, 0.20) << "acne is no longer there";
    const LightComparison fixed = lectureScene("acne", {R"(lights[0].shadow.map={"filter": "none"})"});
    EXPECT_LT(fixed.falseShadowAwayFromEdges, kDefaultsBar) << "the default bias leaves acne";
    EXPECT_LT(fixed.falseLitAwayFromEdges, kDefaultsBar);
}

// Peter panning: a constant bias of 0.1 of the map's depth range (about
// half a metre here) lifts the crate's and the post's shadows off their
// feet. Measured: 0.61 % of the receivers falsely lit away from edges,
// a fifth of the 3.2 % truly shadowed. Bar: false lit more than a tenth
// of the truly shadowed pixels. The fix, the default constant bias of 0:
// within the defaults' bar.
TEST_F(LectureScenesGLTest, PeterPanningDetachesShadowsAndTheDefaultBiasReattachesThem) {
    const LightComparison panned = lectureScene("peter-panning");
    const double shadowed = static_cast<double>(panned.referenceShadowedPixels) / static_cast<double>(panned.receiverPixels);
    EXPECT_GT(panned.falseLitAwayFromEdges, 0.1 * shadowed) << "the shadows no longer detach";
    EXPECT_LT(panned.falseShadowAwayFromEdges, kDefaultsBar) << "a constant bias should not add shadow";
    const LightComparison fixed = lectureScene("peter-panning", {"lights[0].shadow.map.constantBias=0"});
    EXPECT_LT(fixed.falseLitAwayFromEdges, kDefaultsBar) << "the default bias leaves the shadows detached";
    EXPECT_LT(fixed.falseShadowAwayFromEdges, kDefaultsBar);
}

// Aliasing: a 256^2 map fitted around the whole 30 m ground (fit "scene")
// and one nearest tap: a texel covers about 15 pixels at the median and the
// torus's ring shadow is drawn in blocks. Bars: the texel footprint's p95
// over 8 pixels a texel and at least three times the fix's, and the
// misclassified share (all receivers, edges included: the blocks are at the
// edges) at least twice the fix's. The fix, the default map (a tight fit
// and a size that follows the frame): within the defaults' bar away from
// edges.
TEST_F(LectureScenesGLTest, ABadlyFittedSmallMapAliasesAndTheDefaultMapDoesNot) {
    const LightComparison blocky = lectureScene("aliasing");
    const LightComparison fixed = lectureScene("aliasing", {"lights[0].shadow.map={}"});
    EXPECT_GT(blocky.texelFootprintP95, 8.0);
    EXPECT_GT(blocky.texelFootprintP95, 3.0 * fixed.texelFootprintP95);
    EXPECT_GT(blocky.falseLit + blocky.falseShadow, 2.0 * (fixed.falseLit + fixed.falseShadow));
    EXPECT_LT(fixed.falseLitAwayFromEdges, kDefaultsBar);
    EXPECT_LT(fixed.falseShadowAwayFromEdges, kDefaultsBar);
}

// PCF: filter "pcf" (the lectures' 8x8 grid) turns a hard edge into a ramp
// a few pixels wide. Measured: 1,736 pixels between 2 % and 98 % visibility
// at 400x225, none with one nearest tap. Bar: more than 500 such pixels
// with pcf, none without; the filter must not move the edge (within the
// defaults' bar away from edges).
TEST_F(LectureScenesGLTest, PcfSoftensTheEdgeWithoutMovingIt) {
    const LightComparison pcf = lectureScene("pcf");
    const LightComparison hard = lectureScene("pcf", {"lights[0].shadow.map.filter=none"});
    EXPECT_GT(pcf.techniquePenumbraPixels, 500u);
    EXPECT_EQ(hard.techniquePenumbraPixels, 0u);
    EXPECT_LT(pcf.falseLitAwayFromEdges + pcf.falseShadowAwayFromEdges, kDefaultsBar);
}

// Planar shadows drawn as the lecture draws them (dark polygons blended
// onto the ground with depth only): where two polygons' shadows overlap,
// the ground is darkened twice, even within one caster (a slab's top and
// bottom faces both project). Measured at 400x225: 3,172 ground pixels at
// 0.16 visibility (0.4 twice) beside 894 at a single 0.4. Bar: more than
// 1,000 pixels darker than a single shadow. The fix, style "stencil": each
// shadowed pixel darkened once, so the shadowed ground has one level.
TEST_F(LectureScenesGLTest, PlanarShadowsBlendTwiceWhereTheyOverlapAndTheStencilDoesNot) {
    const auto levels = [](const LightComparison& l) {
        std::map<int, std::size_t> count;  // visibility in hundredths -> pixels, on reached pixels in some shadow
        for (std::size_t i = 0; i < l.techniqueVisibility.pixels.size(); ++i) {
            const double v = l.techniqueVisibility.pixels[i] / 65535.0;
            if (l.reach.pixels[i] && v < 0.99) ++count[static_cast<int>(std::lround(v * 100.0))];
        }
        return count;
    };
    const auto lecture = levels(lectureScene("planar-double-blending"));
    ASSERT_TRUE(lecture.count(40)) << "no single shadow at 1 - darkness 0.6";
    std::size_t darker = 0;
    for (const auto& [v, n] : lecture) darker += v < 40 - 2 ? n : 0;
    EXPECT_GT(darker, 1000u) << "no ground darkened twice";
    const auto stencil = levels(lectureScene("planar-double-blending", {"lights[0].shadow.planar.style=stencil"}));
    std::size_t shadowLevels = 0;
    for (const auto& [v, n] : stencil) shadowLevels += n > 50;  // levels of more than a few edge pixels
    EXPECT_EQ(shadowLevels, 1u) << "the stencil left more than one shade of shadow";
}

// Shadow volumes counted depth-pass with the camera inside a shadow (under
// the roof's volume): every count starts one off, and the whole frame turns
// to shadow while the crate's real shadow turns lit. Measured: 99.96 % of
// the receivers falsely shadowed away from edges. Bar: more than 90 %. The
// fix, depth-fail (the caps make the count right wherever the camera is): 0
// misclassified away from edges.
TEST_F(LectureScenesGLTest, DepthPassFailsWithTheCameraInAShadowAndDepthFailDoesNot) {
    const LightComparison pass = lectureScene("volume-camera-in-shadow");
    EXPECT_GT(pass.falseShadowAwayFromEdges, 0.90);
    const LightComparison fail = lectureScene("volume-camera-in-shadow", {"lights[0].shadow.volume.method=depth-fail"});
    EXPECT_EQ(fail.falseShadowAwayFromEdges + fail.falseLitAwayFromEdges, 0.0);
}

// Depth packed into RGBA8 (the textbook's WebGL 1 client could not sample a
// depth texture) classifies as a float depth map does: measured, both 0
// misclassified away from edges. Bar: within 0.01 % of each other, both
// within the defaults' bar.
// Outside the map (LearnOpenGL's over-sampling): its fixed box read as a
// repeating texture (outside "repeat"), so the boxes' shadows repeat past
// the box, and the floor past its far plane is deeper than any stored
// depth, so shadowed. Measured: 36.7 % of the receivers falsely shadowed
// away from edges, nearly all of it that floor. Bar: more than 20 %. The
// fix, outside "lit" (a border of 1, depths past 1 lit): within the
// defaults' bar, the preset's other settings unchanged.
TEST_F(LectureScenesGLTest, OutsideTheMapIsShadowedUntilItIsLit) {
    const LightComparison repeated = lectureScene("outside-map");
    EXPECT_GT(repeated.falseShadowAwayFromEdges, 0.20) << "the floor outside the map is no longer shadowed";
    const LightComparison fixed = lectureScene("outside-map", {"lights[0].shadow.map.outside=lit"});
    EXPECT_LT(fixed.falseShadowAwayFromEdges, kDefaultsBar) << "outside lit leaves false shadow";
    EXPECT_LT(fixed.falseLitAwayFromEdges, kDefaultsBar);
}

TEST_F(LectureScenesGLTest, Rgba8PackingClassifiesAsAFloatDepthMap) {
    const LightComparison packed = lectureScene("rgba8-packing");
    const LightComparison floats = lectureScene("rgba8-packing", {"lights[0].shadow.map.format=depth32f"});
    const double a = packed.falseLitAwayFromEdges + packed.falseShadowAwayFromEdges;
    const double b = floats.falseLitAwayFromEdges + floats.falseShadowAwayFromEdges;
    EXPECT_NEAR(a, b, 0.0001);
    EXPECT_LT(a, kDefaultsBar);
}

// A point light's cube map: six 90-degree views, each written by the
// casters it sees (a crate in each side, a hanging box above, crates below).
// Bar: every face stores some depth nearer than its cleared far value (a
// face left empty would mean a view not drawn). The same faces are the
// cross `render --debug shadow-maps` writes.
TEST_F(LectureScenesGLTest, APointLightsCubeMapHasSixWrittenFaces) {
    const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "lecture" / "point-cube.json");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = 400;
    options.height = 225;
    renderer.render(scene, options);
    const std::vector<DebugImage> images = renderer.debugImages(scene);
    const auto cube = std::find_if(images.begin(), images.end(), [](const DebugImage& d) { return d.kind == DebugImageKind::CubeCross; });
    ASSERT_NE(cube, images.end()) << "no cube cross among the debug images";
    ASSERT_FALSE(cube->values.empty());
    ASSERT_EQ(cube->values.size() % 6, 0u);
    const std::size_t face = cube->values.size() / 6;
    const float cleared = *std::max_element(cube->values.begin(), cube->values.end());
    for (int f = 0; f < 6; ++f) {
        const auto first = cube->values.begin() + static_cast<long>(f * face);
        EXPECT_LT(*std::min_element(first, first + static_cast<long>(face)), cleared) << "face " << f << " holds no caster";
    }
}
