// Technique "map" (shadow maps for directional and spot lights) against the
// ray-traced reference: accuracy on every bundled scene, no acne, no
// peter-panning, the map's outside, the cone, the filters' penumbrae,
// several lights in one frame, and the RGBA8 packing.
#include "GLTestContext.h"
#include "Comparisons.h"
#include "ImageArtifacts.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/SceneFile.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>

using namespace shadowlab;
using shadowlab::test::bundledScenes;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

// `--set` lines that give every directional and spot light of `scene` the
// map technique with `extra` options (each "key=value").
std::vector<std::string> mapOverrides(const Scene& scene, const std::vector<std::string>& extra = {}) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (scene.lights[i].type == LightType::Point) continue;
        const std::string at = "lights[" + std::to_string(i) + "].shadow.";
        out.push_back(at + "technique=map");
        for (const std::string& e : extra) out.push_back(at + "map." + e);
    }
    return out;
}

// A plane seen from above under one light; `nodes` adds more nodes.
Scene planeScene(const std::string& light, const std::string& nodes = "", const std::string& camera = R"({"position": [0, 9, 6], "target": [0, 0, 0]})") {
    return parseScene(R"({"camera": )" + camera + R"(, "lights": [)" + light + R"(],
      "nodes": [{"name": "ground", "shape": {"type": "plane", "size": [40, 40]}})" + nodes + "]}",
                      "test", ".");
}

} // namespace

class MapGLTest : public GLTest {};

// The issue's bar: at the default size (1024^2) with filter "none", at most 0.05 %
// of the receivers misclassified outside the 1-pixel edge band, for every
// directional and spot light of every bundled scene (measured: at most
// 0.025 %, the bunny's thin ears); and the tight fit at least as good as the
// lecture's scene box on every one of them (equal where both are 0).
TEST_F(MapGLTest, EveryBundledSceneMatchesTheReferenceAwayFromEdges) {
    int lights = 0;
    for (const fs::path& file : bundledScenes()) {
        // A 400 m field and a 300 m street seen from eye height: one 2048^2
        // map misclassifies 0.21 % and 1.6 % there away from edges
        // (measured; docs/techniques/fits.md).
        // The scenes ship four cascades, tested on them separately
        // (FourCascadesBeatOneMapOnTheField, DefaultShadowsGLTest), and
        // fit "scene" is one map, not cascades.
        if (file.filename() == "cascades-field.json" || file.filename() == "long-view.json") continue;
        const Scene plain = loadSceneFile(file);
        const auto overrides = mapOverrides(plain, {"filter=\"none\""});
        if (overrides.empty()) continue;
        SCOPED_TRACE(file.filename().string());
        const Scene scene = loadSceneFile(file, overrides);
        const Comparison c = compareScene(scene);
        // The scene box at the tight fit's size: with size 0 its map would
        // grow by the share of it the view sees (MapDefectsGLTest).
        std::vector<std::string> boxed = mapOverrides(plain, {"filter=\"none\"", "fit=\"scene\""});
        for (std::size_t i = 0; i < plain.lights.size(); ++i)
            if (plain.lights[i].type != LightType::Point && plain.lights[i].shadow.get<MapOptions>().size == 0)
                boxed.push_back("lights[" + std::to_string(i) + "].shadow.map.size=" + std::to_string(frameMapSize(960, 540)));
        const Comparison sceneFit = compareScene(loadSceneFile(file, boxed));
        const bool failedBefore = HasFailure();
        for (std::size_t i = 0; i < c.lights.size(); ++i) {
            if (scene.lights[i].type == LightType::Point) continue;
            EXPECT_LE(awayFromEdges(c.lights[i]), 0.0005) << c.lights[i].name;
            // 0.001 % of slack (3 pixels of the 330,000 here): the two fits
            // place their texels differently (torus-resting at 1024^2:
            // tight 1 pixel, the box 0).
            EXPECT_LE(awayFromEdges(c.lights[i]), awayFromEdges(sceneFit.lights[i]) + 1e-5)
                << c.lights[i].name << ": tight fit worse than the scene box";
            ++lights;
        }
        if (!failedBefore && HasFailure()) test::saveImagesIfFailed(file.stem().string(), c.technique, c.reference);
    }
    EXPECT_GE(lights, 6);
}

// LearnOpenGL's own settings on its own scene, and ours, against the
// 0.023 % its demo misclassifies outside the band (measured by the issue).
TEST_F(MapGLTest, LearnOpenGlSceneBeatsTheDemo) {
    const fs::path file = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "learnopengl-shadow-mapping.json";
    const Comparison theirs = compareScene(loadSceneFile(file, {"lights[0].shadow.technique=map", "lights[0].shadow.map.preset=learnopengl"}), 800, 600);
    const Comparison ours = compareScene(loadSceneFile(file, {"lights[0].shadow.technique=map"}), 800, 600);
    EXPECT_LT(awayFromEdges(theirs.lights[0]), 0.00023);
    EXPECT_LT(awayFromEdges(ours.lights[0]), awayFromEdges(theirs.lights[0]));  // measured: 0 pixels against 3
    EXPECT_GT(theirs.lights[0].referenceShadowedPixels, 10000u) << "the cubes' shadows are in view";
}

// Acne: a plane lit from 0 to 80 degrees off its normal must not shadow
// itself anywhere with the default bias (all receivers, edge band included:
// there is no true shadow edge to excuse a pixel).
TEST_F(MapGLTest, NoAcneOnALitPlaneFromZeroToEightyDegrees) {
    for (int degrees = 0; degrees <= 80; degrees += 10) {
        SCOPED_TRACE(std::to_string(degrees) + " degrees");
        const float a = glm::radians(static_cast<float>(degrees));
        const std::string dir = "[" + std::to_string(std::sin(a)) + ", " + std::to_string(-std::cos(a)) + ", 0.1]";
        for (const char* type : {"directional", "spot"}) {
            SCOPED_TRACE(type);
            const std::string light = std::string(type) == "directional"
                ? R"({"type": "directional", "direction": )" + dir + R"(, "shadow": {"technique": "map"}})"
                : R"({"type": "spot", "position": [)" + std::to_string(-6.0f * std::sin(a)) + ", " + std::to_string(6.0f * std::cos(a)) +
                      R"(, 0], "direction": )" + dir + R"(, "outerCone": 45, "innerCone": 40, "shadow": {"technique": "map"}})";
            const Comparison c = compareScene(planeScene(light), 320, 180);
            EXPECT_GT(c.lights[0].receiverPixels, 10000u);
            EXPECT_EQ(c.lights[0].falseShadow, 0.0);
        }
    }
}

// Peter-panning: a box standing on the plane; its shadow must start at its
// base. A gap of more than a pixel along the base would be false lit
// outside the band, a line of tens of pixels here. At most 2 pixels: where
// a texel of the default 768^2 map spans more than a pixel, one step of the
// edge's staircase can fall a pixel outside the band (the spot: 1 pixel,
// away from the base; 0 at 1024^2).
TEST_F(MapGLTest, NoPeterPanningUnderABoxOnThePlane) {
    for (const char* light : {R"({"type": "directional", "direction": [0.5, -1, 0.3], "shadow": {"technique": "map"}})",
                              R"({"type": "spot", "position": [-3, 6, -2], "direction": [0.5, -1, 0.3], "outerCone": 40, "shadow": {"technique": "map"}})"}) {
        SCOPED_TRACE(light);
        const Comparison c = compareScene(planeScene(light, R"(, {"shape": {"type": "box", "size": [1, 1, 1]}, "translation": [0, 0.5, 0]})"), 640, 360);
        EXPECT_GT(c.lights[0].referenceShadowedPixels, 1000u);
        EXPECT_LE(c.lights[0].falseLitAwayFromEdges * static_cast<double>(c.lights[0].receiverPixels), 2.0);
        EXPECT_EQ(c.lights[0].falseShadowAwayFromEdges, 0.0);
        test::saveImagesIfFailed("box", c.technique, c.reference);
    }
}

// Receivers outside the light camera are lit, not shadowed by the border:
// the scene fit and a map whose tight box covers only the casters both
// leave the far ground lit. Spot: outside the cone the point is unlit by
// the light itself (reach), and the map does not change that.
TEST_F(MapGLTest, OutsideTheMapIsLitAndOutsideTheConeIsUnlit) {
    // A small caster far to one side: the tight map covers its footprint only.
    const Scene dir = planeScene(R"({"type": "directional", "direction": [0.3, -1, 0.2], "shadow": {"technique": "map"}})",
                                 R"(, {"shape": {"type": "box", "size": [0.5, 0.5, 0.5]}, "translation": [-8, 0.25, -8]})");
    Renderer renderer(test::glContext());
    renderer.upload(dir);
    renderer.render(dir, {320, 180});
    const std::vector<float> vis = renderer.readVisibility(dir, 0);
    std::size_t lit = 0, ground = 0;
    for (float v : vis) {
        ground += v > 0.0f;
        lit += v == 1.0f;
    }
    // Everything but the small box's shadow (and the box) is lit.
    EXPECT_GT(lit, ground * 95 / 100);
    const Comparison c = compareScene(dir, 320, 180);
    EXPECT_EQ(c.lights[0].falseShadow, 0.0);

    const Scene spot = planeScene(R"({"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "outerCone": 15, "innerCone": 10,
                                      "shadow": {"technique": "map"}})");
    renderer.upload(spot);
    renderer.render(spot, {160, 90});
    const ImageRGBA8 image = renderer.readColor();
    const Scene ambientOnly = planeScene(R"({"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "outerCone": 15, "innerCone": 10, "intensity": 0})");
    renderer.upload(ambientOnly);
    renderer.render(ambientOnly, {160, 90});
    const ImageRGBA8 dark = renderer.readColor();
    // The corners lie far outside the 15 degree cone: exactly the ambient colour.
    for (std::size_t corner : {std::size_t(0), std::size_t(159), std::size_t(89 * 160), std::size_t(89 * 160 + 159)})
        for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(image.pixels[corner * 4 + ch], dark.pixels[corner * 4 + ch]) << corner;
}

// PCF: across a straight shadow edge visibility rises monotonically from 0
// to 1, over a width that grows with the kernel; dither4 stays within the
// values four taps can give; box is wider than one bilinear compare.
TEST_F(MapGLTest, FilteredEdgesRiseMonotonicallyAndWidenWithTheKernel) {
    // A slab's straight shadow edge across the view: the slab hangs above
    // the camera (which looks straight down, so it does not see it) and
    // covers x > 0; the sun shines straight down. Fit "scene" over the 40 m
    // plane at 256^2 makes one texel ~0.22 m, ~20 pixels here, so every
    // kernel's penumbra spans many pixels of the row.
    auto edgeProfile = [](const std::string& filterJson) {
        const Scene scene = planeScene(R"({"type": "directional", "direction": [0, -1, 0.0001],
                                          "shadow": {"technique": "map", "map": {"size": 256, "fit": "scene", )" + filterJson + R"(}}})",
                                       R"(, {"shape": {"type": "box", "size": [20, 0.2, 20]}, "translation": [10, 5, 0]})",
                                       R"({"position": [0, 2, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fovY": 20})");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        renderer.render(scene, {256, 64});
        const std::vector<float> vis = renderer.readVisibility(scene, 0);
        return std::vector<float>(vis.begin() + 32 * 256, vis.begin() + 33 * 256);  // one row across the edge
    };
    auto width = [](const std::vector<float>& row) {  // pixels strictly between 0 and 1
        int n = 0;
        for (float v : row) n += v > 0.0f && v < 1.0f;
        return n;
    };
    int previous = -1;
    for (int kernel : {2, 3, 5, 8}) {
        SCOPED_TRACE("kernel " + std::to_string(kernel));
        const std::vector<float> row = edgeProfile(R"("filter": "grid", "gridTaps": "bilinear", "kernel": )" + std::to_string(kernel));
        EXPECT_EQ(row.front(), 1.0f);  // x < 0: lit
        EXPECT_EQ(row.back(), 0.0f);   // under the slab
        for (std::size_t x = 1; x < row.size(); ++x) EXPECT_LE(row[x], row[x - 1] + 1e-6f) << "x " << x;  // lit to shadowed: never rises
        EXPECT_GT(width(row), previous) << "a wider kernel, a wider penumbra";
        previous = width(row);
        // ceil(N/2)^2 bilinear compares and N^2 nearest ones: the same box
        // average of the same comparisons (to float rounding of the weights).
        const std::vector<float> nearest =
            edgeProfile(R"("filter": "grid", "gridTaps": "nearest", "kernel": )" + std::to_string(kernel));
        for (std::size_t x = 0; x < row.size(); ++x) EXPECT_NEAR(row[x], nearest[x], 1e-4f) << "x " << x;
    }
    const std::vector<float> dither = edgeProfile(R"("filter": "dither4")");
    for (float v : dither) {
        const float quarters = v * 4.0f;  // four taps: 0, 1/4, ... 1
        EXPECT_NEAR(quarters, std::round(quarters), 1e-4f) << v;
    }
    EXPECT_GT(width(dither), 0);
    const std::vector<float> poisson = edgeProfile(R"("filter": "poisson", "samples": 16, "radius": 2)");
    EXPECT_GT(width(poisson), 0);
    // box: four bilinear compares half a texel apart, a tent over three
    // texels: monotonic, and wider than one bilinear compare's two texels.
    const std::vector<float> box = edgeProfile(R"("filter": "box")");
    EXPECT_EQ(box.front(), 1.0f);
    EXPECT_EQ(box.back(), 0.0f);
    for (std::size_t x = 1; x < box.size(); ++x) EXPECT_LE(box[x], box[x - 1] + 1e-6f) << "box, x " << x;  // never rises (float rounding of the weights)
    EXPECT_GT(width(box), width(edgeProfile(R"("filter": "hardware")")));
}

// Four shadowed lights, two directional and two spot, in one frame.
TEST_F(MapGLTest, FourLightsInOneFrameEachMatchTheReference) {
    const Scene scene = parseScene(R"({
      "camera": {"position": [0, 10, 10], "target": [0, 0, 0], "fovY": 50},
      "lights": [
        {"name": "sun a", "type": "directional", "direction": [0.5, -1, 0.2], "intensity": 0.3, "shadow": {"technique": "map"}},
        {"name": "sun b", "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.3, "shadow": {"technique": "map", "map": {"size": 1024}}},
        {"name": "spot a", "type": "spot", "position": [4, 6, 0], "direction": [-0.6, -1, 0], "outerCone": 40, "intensity": 0.3, "shadow": {"technique": "map"}},
        {"name": "spot b", "type": "spot", "position": [-4, 6, 3], "direction": [0.6, -1, -0.4], "outerCone": 40, "intensity": 0.3, "shadow": {"technique": "map", "map": {"format": "depth24"}}}
      ],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [30, 30]}},
        {"name": "box", "shape": {"type": "box", "size": [1, 2, 1]}, "translation": [-1, 1, 0]},
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.8}, "translation": [1.5, 1.2, 0.5]},
        {"name": "torus", "shape": {"type": "torus", "majorRadius": 0.8, "minorRadius": 0.25}, "translation": [0, 0.6, 2.5], "rotation": [30, 0, 0]}
      ]
    })", "four-lights", ".");
    const Comparison c = compareScene(scene);
    ASSERT_EQ(c.lights.size(), 4u);
    for (const LightComparison& l : c.lights) {
        SCOPED_TRACE(l.name);
        EXPECT_GT(l.referenceShadowedPixels, 1000u);
        EXPECT_LE(awayFromEdges(l), 0.0005);
    }
    test::saveImagesIfFailed("four-lights", c.technique, c.reference);
}

// RGBA8 packing (Ganovelli et al. §8.3.1) classifies like depth32f on at least
// 99.9 % of the receivers of every directional and spot scene.
TEST_F(MapGLTest, Rgba8PackingClassifiesLikeDepth32f) {
    for (const fs::path& file : bundledScenes()) {
        const Scene plain = loadSceneFile(file);
        const auto base = mapOverrides(plain, {"filter=\"none\""});
        if (base.empty()) continue;
        SCOPED_TRACE(file.filename().string());
        const Scene packed = loadSceneFile(file, mapOverrides(plain, {"filter=\"none\"", "format=\"rgba8\""}));
        const Scene depth = loadSceneFile(file, base);
        Renderer renderer(test::glContext());
        renderer.upload(depth);
        renderer.render(depth, {480, 270});
        std::vector<std::vector<float>> a, b;
        for (std::size_t i = 0; i < depth.lights.size(); ++i) a.push_back(renderer.readVisibility(depth, i));
        renderer.render(packed, {480, 270});
        for (std::size_t i = 0; i < packed.lights.size(); ++i) b.push_back(renderer.readVisibility(packed, i));
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (depth.lights[i].type == LightType::Point) continue;
            std::size_t same = 0, counted = 0;
            for (std::size_t p = 0; p < a[i].size(); ++p) {
                // Both 0: background, or shadowed in both (agreeing); leaving
                // them out only makes the share stricter.
                if (a[i][p] == 0.0f && b[i][p] == 0.0f) continue;
                ++counted;
                same += (a[i][p] >= 0.5f) == (b[i][p] >= 0.5f);
            }
            EXPECT_GE(static_cast<double>(same), 0.999 * static_cast<double>(counted)) << "light " << i;
        }
    }
}

// The "flashlight in the eye" (Wolberg's lecture): a spot light at the camera,
// pointing where it looks, shows no shadow: every shadow falls behind what
// the camera sees.
TEST_F(MapGLTest, AFlashlightInTheEyeShowsNoShadow) {
    Scene scene = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "two-boxes-sun.json");
    Light flashlight;
    flashlight.name = "flashlight";
    flashlight.type = LightType::Spot;
    flashlight.position = scene.camera.position;
    flashlight.direction = glm::normalize(scene.camera.target - scene.camera.position);
    flashlight.outerConeDeg = 35.0f;
    flashlight.innerConeDeg = 30.0f;
    flashlight.shadow.technique = "map";
    scene.lights = {flashlight};
    const Comparison c = compareScene(scene, 480, 270);
    const LightComparison& l = c.lights[0];
    EXPECT_GT(l.receiverPixels, 20000u);
    // The truth: nothing the camera sees is shadowed from its own eye but
    // silhouette pixels, whose surface point lies a hair behind the edge a
    // ray to the eye then grazes (1 of ~12,000 measured): 0.05 % allows ~6.
    const double share = static_cast<double>(l.referenceShadowedPixels) / static_cast<double>(l.receiverPixels);
    EXPECT_LE(share, 0.0005);
    // And the map shows no shadow either, the edge band included.
    EXPECT_LE(l.falseShadow, 0.0005);
}

// Preset "lecture-000" remakes Wolberg's torus and pyramid: its point light
// through one 60-degree map towards the origin, at the window's size, with
// its polygon offset and dithered PCF. Its acne (the stripes the lecture
// shows) is no concern here; its shadows must be where the truth has them.
TEST_F(MapGLTest, TheLecturePresetRemakesTheTorusAndPyramid) {
    const Scene scene = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "torus-pyramid.json",
                                      {"lights[0].shadow.technique=map", "lights[0].shadow.map.preset=\"lecture-000\""});
    const Comparison c = compareScene(scene, 480, 270);
    const LightComparison& l = c.lights[0];
    EXPECT_GT(l.referenceShadowedPixels, 2000u);
    // 0.009 % measured at 960x540; a tenth of a percent would be a missing shadow.
    EXPECT_LT(l.falseLitAwayFromEdges, 0.001);
}

// shadowedLight (preset "lecture": 0.6, Ganovelli et al. listing 8.4's
// color *= 0.6) is a look: shadowed receivers keep part of the light and so
// are brighter than with 0, lit ones are unchanged, and compare, which
// judges the shadow test, counts exactly the same pixels.
TEST_F(MapGLTest, ShadowedLightBrightensTheShadowButNotTheTest) {
    const std::string sun = R"({"type": "directional", "direction": [0.3, -1, -0.2], "shadow": {"technique": "map", "map": {"shadowedLight": )";
    const std::string box = R"(, {"name": "box", "shape": {"type": "box", "size": [2, 2, 2]}, "translation": [0, 1.5, 0]})";
    const Comparison dark = compareScene(planeScene(sun + "0}}}", box), 480, 270);
    const Comparison bright = compareScene(planeScene(sun + "0.6}}}", box), 480, 270);
    const LightComparison& d = dark.lights[0];
    const LightComparison& b = bright.lights[0];
    EXPECT_GT(d.referenceShadowedPixels, 800u) << "the box's shadow is in view";
    EXPECT_EQ(d.falseShadow, b.falseShadow);
    EXPECT_EQ(d.falseLit, b.falseLit);
    std::size_t brighter = 0, shadowed = 0, litChanged = 0;
    for (std::size_t i = 0; i < d.referenceVisibility.pixels.size(); ++i) {
        if (!d.reach.pixels[i]) continue;
        const int before = dark.technique.pixels[i * 4 + 1], after = bright.technique.pixels[i * 4 + 1];
        if (d.referenceVisibility.pixels[i] == 0) {
            ++shadowed;
            brighter += after > before + 10;  // 60 % of the light in sRGB: far more than 10 levels
        } else if (d.referenceVisibility.pixels[i] == 65535) {
            litChanged += after != before;
        }
    }
    // Edge pixels may differ in class between the map and the truth: allow 2 %.
    EXPECT_GE(static_cast<double>(brighter), 0.98 * static_cast<double>(shadowed));
    EXPECT_LE(static_cast<double>(litChanged), 0.0005 * static_cast<double>(d.receiverPixels));
}

// What the viewer draws as a light's frustums: the cameras the maps were
// rendered from. Every receiver pixel the reference shadows must lie inside
// one of them (else its shadow could not be in the map): inside x and y of
// a directional light's box (its depth is clamped), inside the whole volume
// of a spot's frustum or of one of a point light's six faces.
TEST_F(MapGLTest, TheLightFrustumsHoldEveryShadowedReceiver) {
    for (const char* name : {"spot-objects.json", "spheres-sun.json", "four-spheres-point.json", "room-point.json"}) {
        SCOPED_TRACE(name);
        const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / name;
        const Scene plain = loadSceneFile(path.string());
        std::vector<std::string> overrides;
        for (std::size_t i = 0; i < plain.lights.size(); ++i) overrides.push_back("lights[" + std::to_string(i) + "].shadow.technique=map");
        const Scene scene = loadSceneFile(path.string(), overrides);
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        CompareOptions options;
        options.width = 320;
        options.height = 180;
        const Comparison c = compareWithReference(renderer, scene, options);
        RenderOptions frame;
        frame.width = options.width;
        frame.height = options.height;
        renderer.render(scene, frame);
        const std::vector<LightFrustum> frustums = renderer.lightFrustums(scene);
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            const Light& light = scene.lights[l];
            std::vector<glm::mat4> mine;
            for (const LightFrustum& f : frustums)
                if (f.light == static_cast<int>(l)) mine.push_back(f.clipFromWorld);
            ASSERT_EQ(mine.size(), light.type == LightType::Point ? 6u : 1u) << "light " << l;
            std::size_t shadowed = 0, outside = 0;
            for (std::size_t i = 0; i < c.surfaces.position.size(); ++i) {
                if (c.lights[l].reach.pixels[i] == 0 || c.lights[l].referenceVisibility.pixels[i] >= 32768) continue;
                ++shadowed;
                bool in = false;
                for (const glm::mat4& m : mine) {
                    const glm::vec4 p = m * glm::vec4(glm::vec3(c.surfaces.position[i]), 1.0f);
                    // 1e-3 of the volume's half size: float rounding of the fit, far below a texel.
                    const float w = std::fabs(p.w) * 1.001f;
                    in = in || (p.w > 0.0f && std::fabs(p.x) <= w && std::fabs(p.y) <= w && (light.type == LightType::Directional || std::fabs(p.z) <= w));
                }
                outside += !in;
            }
            EXPECT_GT(shadowed, 100u) << "light " << l << ": the test needs shadow in view";
            EXPECT_EQ(outside, 0u) << "light " << l << ": shadowed receivers outside every frustum";
        }
    }
    // A light whose technique renders no map has no frustum.
    const Scene none = planeScene(R"({"type": "directional", "direction": [0, -1, 0], "shadow": {"technique": "none"}})");
    Renderer renderer(test::glContext());
    renderer.upload(none);
    renderer.render(none);
    EXPECT_TRUE(renderer.lightFrustums(none).empty());
}

// Issue 17's bar for cascades: on cascades-field (a 400 m ground, casters
// from 2 m to 150 m away, a camera at eye height), 4 cascades of 2048^2
// with filter none misclassify at most 0.1 % of the receivers outside the
// 1-pixel band, stabilised or fitted tightly, and strictly fewer than one
// 2048^2 map over the same view (measured 0.011 %, 0.000 % and 0.212 %).
TEST_F(MapGLTest, FourCascadesBeatOneMapOnTheField) {
    const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "cascades-field.json";
    const std::vector<std::string> hard = {"lights[0].shadow.technique=\"map\"", "lights[0].shadow.map.filter=\"none\"", "lights[0].shadow.map.size=2048"};
    auto with = [&](std::vector<std::string> extra) {
        extra.insert(extra.begin(), hard.begin(), hard.end());
        return awayFromEdges(compareScene(loadSceneFile(path, extra)).lights[0]);
    };
    const double one = with({"lights[0].shadow.map.cascades=1"});  // the scene ships 4
    const double stabilised = with({"lights[0].shadow.map.cascades=4", "lights[0].shadow.map.stabilize=true"});
    const double tight = with({"lights[0].shadow.map.cascades=4", "lights[0].shadow.map.stabilize=false"});
    EXPECT_LE(stabilised, 0.001);
    EXPECT_LE(tight, 0.001);
    EXPECT_LT(stabilised, one);
    EXPECT_LT(tight, one);
}

// The cascades colour view shows one colour per slice, nearest first: on
// the field, with 4 cascades, all four appear, red (the first) at the
// bottom of the frame (the ground at the camera's feet) and the last
// cascade's colour towards the horizon.
TEST_F(MapGLTest, TheCascadeViewColoursEachSlice) {
    const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "cascades-field.json";
    const Scene scene = loadSceneFile(path, {"lights[0].shadow.technique=\"map\"", "lights[0].shadow.map.cascades=4", "lights[0].shadow.map.size=512",
                                             "lights[0].shadow.map.cascadeBlend=0"});
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = 320;
    options.height = 180;
    renderer.render(scene, options);
    const ImageRGBA8* view = nullptr;
    std::vector<DebugImage> images = renderer.debugImages(scene);
    int maps = 0;
    for (const DebugImage& d : images) {
        if (d.name == "light0-cascades") view = &d.image;
        maps += d.name.find("-map") != std::string::npos;
    }
    EXPECT_EQ(maps, 4);
    ASSERT_NE(view, nullptr);
    // The dominant channel picks the colour (shading only scales it).
    auto hue = [&](int x, int y) {
        const std::uint8_t* p = &view->pixels[(static_cast<std::size_t>(y) * view->width + x) * 4];
        return p[0] > 2 * p[1] && p[0] > 2 * p[2] ? 'r' : p[1] > p[0] && p[1] > p[2] ? 'g' : p[2] > p[0] && p[2] > p[1] ? 'b' : 'y';
    };
    EXPECT_EQ(hue(160, 178), 'r');
    std::set<char> seen;
    for (int y = 0; y < view->height; ++y)
        for (int x = 0; x < view->width; ++x) {
            const std::uint8_t* p = &view->pixels[(static_cast<std::size_t>(y) * view->width + x) * 4];
            if (p[0] + p[1] + p[2] > 30) seen.insert(hue(x, y));
        }
    EXPECT_EQ(seen, (std::set<char>{'r', 'g', 'b', 'y'}));
}

// RenderOptions::reuseShadowMaps (bench --flips reads one view through two
// frames' maps): with it, no shadow pass runs and each map keeps the light
// camera it was drawn with, so after the sun turns the shadow stays where
// the old map put it; without it the shadow follows the sun. Not quite
// pixel for pixel: the receiver's normal offset follows the light's
// current direction (its N.L), which can move a pixel at the shadow's edge
// across it (1 of the 160x90 at the default 768^2, 0 at 1024^2), so at
// most 2 change, against the hundreds a turned sun moves. A renderer that
// has drawn no map says so in one line.
TEST_F(MapGLTest, ReusedShadowMapsKeepThePreviousFramesShadow) {
    Scene scene = defaultScene({"lights[0].shadow.technique=map"});
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = 160;
    options.height = 90;
    options.reuseShadowMaps = true;
    try {
        renderer.render(scene, options);
        ADD_FAILURE() << "reuseShadowMaps with no earlier frame succeeded";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("reuseShadowMaps: light 0 has no shadow map from the previous frame"), std::string::npos) << e.what();
    }
    options.reuseShadowMaps = false;
    options.surfaces = true;
    renderer.render(scene, options);
    const std::vector<float> before = renderer.readVisibility(scene, 0);
    // Counted on the ground alone: the torus's own terminator moves with the
    // sun whatever map is read (the visibility term is 0 facing away).
    const SurfaceBuffer surfaces = renderer.readSurfaces();
    scene.lights[0].direction = glm::normalize(scene.lights[0].direction + glm::vec3(0.6f, 0.0f, 0.0f));
    options.reuseShadowMaps = true;
    renderer.render(scene, options);
    const auto changedFromBefore = [&](const std::vector<float>& v) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < v.size(); ++i) {
            const glm::vec4& p = surfaces.position[i];
            if (p.w > 0.5f && std::abs(p.y) < 1e-3f) n += (v[i] >= 0.5f) != (before[i] >= 0.5f);
        }
        return n;
    };
    const std::size_t kept = changedFromBefore(renderer.readVisibility(scene, 0));
    options.reuseShadowMaps = false;
    renderer.render(scene, options);
    const std::size_t turned = changedFromBefore(renderer.readVisibility(scene, 0));
    std::printf("pixels whose class changed: %zu through the kept map, %zu through a new one\n", kept, turned);
    EXPECT_GT(turned, 100u) << "the turned sun must move the shadow for the check to mean anything";
    EXPECT_LE(kept, 2u);
}

// RenderOptions::cacheShadowMaps: a frame whose map inputs did not change
// keeps the previous frame's maps (its pass says "cached" and draws
// nothing) and looks the same; a moved caster, a turned light or a moved
// camera redraws them, and the frame is then the one a fresh renderer gives.
TEST_F(MapGLTest, CachedMapsAreKeptOnlyWhileTheirInputsStay) {
    const fs::path file = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "two-boxes-sun.json";
    RenderOptions options{160, 90};
    options.cacheShadowMaps = true;
    auto cachedCount = [](const FrameStats& stats) {
        for (const auto& [name, value] : stats.counters)
            if (name == "shadow[0].cached") return value;
        return 0.0;
    };
    auto fresh = [&](const Scene& s) {
        Renderer other(test::glContext());
        other.upload(s);
        other.render(s, RenderOptions{160, 90});
        return other.readColor().pixels;
    };
    Scene scene = loadSceneFile(file, {"lights[0].shadow.technique=map"});
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    EXPECT_EQ(cachedCount(renderer.render(scene, options)), 0.0);
    const std::vector<std::uint8_t> first = renderer.readColor().pixels;
    EXPECT_EQ(cachedCount(renderer.render(scene, options)), 1.0);
    EXPECT_EQ(renderer.readColor().pixels, first);
    const std::vector<std::pair<const char*, std::function<void(Scene&)>>> changes = {
        {"a caster moved", [](Scene& s) { s.nodes.back().translation.x += 0.5f; }},
        {"the light turned", [](Scene& s) { s.lights[0].direction = glm::normalize(s.lights[0].direction + glm::vec3(0.2f, 0.0f, 0.0f)); }},
        {"the camera moved", [](Scene& s) { s.camera.position.x += 0.5f; }},
    };
    // A frame lit by given visibility (the reference's) refits the maps but
    // draws none: the next cached frame must not take them as drawn.
    scene.lights[0].direction = glm::normalize(scene.lights[0].direction + glm::vec3(0.0f, 0.0f, 0.2f));
    const std::size_t pixels = 160u * 90u;
    renderer.renderWithVisibility(scene, RenderOptions{160, 90}, {std::vector<float>(pixels, 1.0f)});
    EXPECT_EQ(cachedCount(renderer.render(scene, options)), 0.0);
    EXPECT_EQ(renderer.readColor().pixels, fresh(scene));
    for (const auto& [what, change] : changes) {
        SCOPED_TRACE(what);
        change(scene);
        EXPECT_EQ(cachedCount(renderer.render(scene, options)), 0.0);
        const std::vector<std::uint8_t> redrawn = renderer.readColor().pixels;
        EXPECT_NE(redrawn, first);
        EXPECT_EQ(redrawn, fresh(scene));
    }
}
