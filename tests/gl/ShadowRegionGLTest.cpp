// RenderOptions::shadowRegions: the base pass runs its light's test only in
// the screen rectangles its technique says the light's shadows can fall in
// (technique "map", one 2D map: src/techniques/map/fit/Region.h) and shades
// the rest lit without it (src/render/RegionDraw.cpp). That must change no
// pixel: the frames with and without it are compared byte for byte, over
// every bundled scene and over the options that move a shadow off its
// caster's box (filters' reach, normal offset, biases), spot and
// directional lights, translucent casters, and a view from inside a shadow.
#include "Comparisons.h"
#include "GLTestContext.h"
#include "ImageArtifacts.h"

#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::bundledScenes;
using shadowlab::test::GLTest;

namespace {

struct Frame {
    ImageRGBA8 image;
    std::optional<double> share;  // the base pass's "shadowedShare": the rectangles' share of the frame, when they were used
};

Frame render(const Scene& scene, bool regions, int width = 320, int height = 240) {
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options{width, height};
    options.shadowRegions = regions;
    const FrameStats stats = renderer.render(scene, options);
    Frame f{renderer.readColor(), std::nullopt};
    for (const auto& [name, value] : stats.counters)
        if (name == "base.shadowedShare") f.share = value;
    return f;
}

// The frame with the rectangles is the frame without them, byte for byte;
// returns the share they covered (nothing when they were not used).
std::optional<double> expectSameFrame(const Scene& scene, const std::string& what) {
    const Frame with = render(scene, true), without = render(scene, false);
    EXPECT_FALSE(without.share.has_value()) << what << ": off, the base pass tests every pixel";
    std::size_t differing = 0;
    for (std::size_t i = 0; i < with.image.pixels.size(); i += 4)
        differing += with.image.pixels[i] != without.image.pixels[i] || with.image.pixels[i + 1] != without.image.pixels[i + 1] ||
                     with.image.pixels[i + 2] != without.image.pixels[i + 2];
    EXPECT_EQ(differing, 0u) << what << ": the shadow regions changed pixels";
    std::string name = "shadow-region-" + what;
    std::replace_if(name.begin(), name.end(), [](char c) { return c == ' ' || c == '=' || c == '/'; }, '-');
    test::saveImagesIfFailed(name, with.image, without.image);
    return with.share;
}

// `--set` lines giving light 0 technique "map" and each of `set` (under
// lights[0].), each also added to `what`.
std::vector<std::string> lightSettings(const std::vector<std::string>& set, std::string& what) {
    std::vector<std::string> overrides = {"lights[0].shadow.technique=map"};
    for (const std::string& s : set) {
        overrides.push_back("lights[0]." + s);
        what += " " + s;
    }
    return overrides;
}

} // namespace

class ShadowRegionGLTest : public GLTest {};

// Every bundled scene as shipped. Most of them have a directional or spot
// light with one 2D map, or technique "disc", first (the base pass's
// light); those must use the rectangles and cover less than the whole
// frame with them (measured at 320x240: every such scene, 11 of them).
TEST_F(ShadowRegionGLTest, EveryBundledSceneLooksTheSame) {
    int used = 0;
    for (const auto& file : bundledScenes()) {
        if (file.stem() == "many-lights") continue;  // 64 point and spot lights in the atlas, none in the base pass's test
        SCOPED_TRACE(file.filename().string());
        const std::optional<double> share = expectSameFrame(loadSceneFile(file), file.stem().string());
        if (share) {
            ++used;
            EXPECT_LT(*share, 1.0);
        }
    }
    EXPECT_GE(used, 11) << "the rectangles were used on fewer scenes than they apply to";
}

// The options that move where a shadow falls, or how far from it a
// receiver's test reads, on a spot (perspective) and a sun (orthographic).
TEST_F(ShadowRegionGLTest, FiltersOffsetsAndBiasesLookTheSame) {
    const std::vector<std::vector<std::string>> settings = {
        {"shadow.map.filter=none"},
        {"shadow.map.filter=hardware"},
        {"shadow.map.filter=grid", "shadow.map.kernel=5"},
        {"shadow.map.filter=poisson", "shadow.map.radius=4"},
        {"shadow.map.filter=box"},
        {"shadow.map.filter=pcss", "size=0.3"},
        {"shadow.map.normalBias=6"},
        {"shadow.map.constantBias=0.02"},
        {"shadow.map.constantBias=0", "shadow.map.normalBias=0", "shadow.map.slopeBias=0", "shadow.map.offsetUnits=0"},  // acne
        {"shadow.map.cullFront=true"},
        {"shadow.map.preset=learnopengl"},
        {"shadow.map.size=64", "shadow.map.filter=poisson", "shadow.map.radius=8"},  // a penumbra far past the box's shadow
        {"shadow.map.size=64", "shadow.map.filter=grid", "shadow.map.kernel=8"},
        {"shadow.map.size=64", "shadow.map.normalBias=8"},
    };
    for (const char* file : {"scenes/spot-objects.json", "scenes/learnopengl-shadow-mapping.json", "scenes/torus-resting.json"}) {
        for (const auto& set : settings) {
            std::string what = std::filesystem::path(file).stem().string();
            std::vector<std::string> overrides = lightSettings(set, what);
            // pcss on a sun takes an angular size in degrees.
            if (set.back() == "size=0.3" && std::string(file) != "scenes/spot-objects.json") overrides.back() = "lights[0].size=2";
            SCOPED_TRACE(what);
            expectSameFrame(loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / file, overrides), what);
        }
    }
}

// Point lights' cubes: each caster's box widened by its taps' reach
// (texels as an angle, the radial filters' world radius, pcss's search and
// penumbra as angles), in a perspective light space from the lamp around
// it, or, too wide for one, projected onto the planar receivers in the world.
TEST_F(ShadowRegionGLTest, PointLightsLookTheSame) {
    const std::vector<std::vector<std::string>> settings = {
        {"shadow.map.filter=none"},
        {"shadow.map.filter=hardware"},
        {"shadow.map.filter=grid"},
        {"shadow.map.filter=pcf20"},
        {"shadow.map.filter=poisson"},
        {"shadow.map.filter=box"},
        {"shadow.map.filter=pcss", "size=0.4"},
        {"shadow.map.filter=pcf20", "shadow.map.diskRadius=0.4", "shadow.map.diskGrowth=4"},  // a blur far past the shadow's edge
        {"shadow.map.size=64", "shadow.map.filter=hardware"},
        {"shadow.map.size=64", "shadow.map.normalBias=8"},
        {"shadow.map.preset=learnopengl"},
    };
    for (const char* file : {"scenes/four-spheres-point.json", "scenes/torus-pyramid.json", "scenes/room-point.json", "scenes/penumbra-step.json"}) {
        for (const auto& set : settings) {
            std::string what = std::filesystem::path(file).stem().string();
            std::vector<std::string> overrides = lightSettings(set, what);
            SCOPED_TRACE(what);
            expectSameFrame(loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / file, overrides), what);
        }
    }
}

// A lamp over a floor and a small floating box, the box's shadow blurred
// far past its edge: the rectangle must reach that far (each case fails
// with the taps' reach left out of the box's widening: checked; the grid's
// box, widened, spreads too wide for a perspective view from the lamp and
// goes through the world's rays, which fail without the tilt: checked).
// pcf20's radius here reaches over nine tenths of the frame, so that frame
// is drawn in one draw with the test; the others leave part of it to skip.
TEST_F(ShadowRegionGLTest, APointLightsBlurredShadowLooksTheSame) {
    const std::vector<std::pair<const char*, bool>> filters = {{R"("filter": "pcf20", "diskRadius": 0.5, "diskGrowth": 2)", false},
                                                               {R"("filter": "grid", "diskRadius": 0.4)", true},
                                                               {R"("filter": "pcss")", true},
                                                               {R"("filter": "hardware", "size": 32)", true}};
    for (const auto& [filter, skips] : filters) {
        SCOPED_TRACE(filter);
        const Scene scene = test::sceneOf(std::string(R"({"camera": {"position": [0, 7, 7], "target": [0, 0, 0], "fovY": 50},
          "lights": [{"type": "point", "position": [0, 4, 0], "size": 0.8, "shadow": {"technique": "map", "map": {)") + filter + R"(}}}],
          "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [20, 20]}},
                    {"name": "box", "shape": {"type": "box", "size": [0.5, 0.5, 0.5]}, "translation": [0.5, 2, 0.5]}]})");
        const std::optional<double> share = expectSameFrame(scene, "blurred-point");
        EXPECT_EQ(share.has_value(), skips);
    }
}

// A lamp's pcss shadow of a sheet too wide for a view around it (its
// rectangles then come from rays through its corners, tilted by the taps'
// reach): the far edge of the shadow, 18 m from the lamp, where the search
// and penumbra reach furthest (penumbra-step's sheet, seen from beyond that
// edge, under the sheet).
TEST_F(ShadowRegionGLTest, AWideCastersFarPenumbraLooksTheSame) {
    for (const char* camera : {R"({"position": [-24, 1.0, 3], "target": [-11, 0, 0], "fovY": 40})",
                               R"({"position": [-13, 8, 0.01], "target": [-13, 0, 0], "fovY": 30})"}) {
        SCOPED_TRACE(camera);
        // At the default size: the scene ships 256^2, whose texels widen the
        // rectangles over nine tenths of these views (then not used).
        const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes/penumbra-step.json",
                                          {std::string("camera=") + camera, "lights[0].shadow.map.size=768"});
        const std::optional<double> share = expectSameFrame(scene, "far-penumbra");
        EXPECT_TRUE(share.has_value());
    }
    // A wall a metre from a lamp 3 m over the floor: the far edge of its
    // shadow, 4.2 m from the lamp, is cast by the wall's top at 1.4 m, so
    // its penumbra reaches 0.2 (1 / 1.4 - 1 / 4.2) radians, more than at the
    // floor's nearest point (3 m); seen from above, the edge on the left.
    const Scene wall = test::sceneOf(R"({"camera": {"position": [4, 8, 0.01], "target": [4, 0, 0], "fovY": 30},
      "lights": [{"type": "point", "position": [0, 3, 0], "size": 0.2, "shadow": {"technique": "map", "map": {"filter": "pcss"}}}],
      "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [40, 40]}},
                {"name": "wall", "shape": {"type": "box", "size": [0.02, 1.5, 6]}, "translation": [1.01, 1.25, 0], "receivesShadows": false}]})");
    const std::optional<double> share = expectSameFrame(wall, "wall-far-penumbra");
    EXPECT_TRUE(share.has_value());
}

// Cascades: a pixel is shadowed only by the casters of the cascades it
// reads (its slice's, and the next one's where the slice fades into it),
// so the rectangles of every cascade's casters together; over the field,
// with the blend share wide, none and the default, two to eight slices,
// and the filters that reach furthest.
TEST_F(ShadowRegionGLTest, CascadesLookTheSame) {
    // Whether the rectangles leave some of the frame out (pcss's, which
    // count every receiver past a caster's nearest depth, cover it all).
    const std::vector<std::pair<std::vector<std::string>, bool>> settings = {
        {{}, true},
        {{"lights[0].shadow.map.cascadeBlend=0.3"}, true},
        {{"lights[0].shadow.map.cascadeBlend=0", "lights[0].shadow.map.cascades=2"}, true},
        {{"lights[0].shadow.map.cascades=8", "lights[0].shadow.map.filter=grid", "lights[0].shadow.map.kernel=5"}, true},
        {{"lights[0].shadow.map.filter=pcss", "lights[0].size=0.05"}, false},
        {{"lights[0].shadow.map.stabilize=false"}, true},
    };
    for (const auto& [set, skips] : settings) {
        std::string what = "cascades";
        for (const std::string& s : set) what += " " + s;
        SCOPED_TRACE(what);
        const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes/cascades-field.json", set);
        const std::optional<double> share = expectSameFrame(scene, what);
        EXPECT_EQ(share.has_value(), skips);
    }
}

// Stabilised cascades draw only the texels their lookups can read (the
// receivers seen in each slice, widened by the filter's footprint and the
// normal offset; MapCameras: drawnTexels): the frames are the same as with
// every texel drawn, under the options that widen what a lookup reads, and
// the street's cascades leave most of their squares out.
TEST_F(ShadowRegionGLTest, CascadesDrawOnlyWhatTheirLookupsRead) {
    const std::filesystem::path scenes = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes";
    struct Case {
        std::string scene;
        std::vector<std::string> set;
    };
    const std::string m = "lights[0].shadow.map.";
    const std::vector<Case> cases = {
        {"long-view.json", {}},
        {"long-view.json", {m + "filter=poisson", m + "radius=8", m + "size=256"}},  // a wide footprint in large texels
        {"long-view.json", {m + "filter=box", m + "normalBias=8", m + "size=256"}},   // the normal offset moves the point 8 texels
        {"long-view.json", {m + "filter=pcss", "lights[0].size=1.5", m + "size=512"}},
        {"long-view.json", {m + "cascades=8", m + "cascadeBlend=0.5"}},
        {"long-view.json", {"camera.target=[30, 8, -10]"}},   // turned towards the houses on the right
        {"long-view.json", {"camera.position=[0, 40, 30]", "camera.target=[0, 0, -60]"}},  // from above
        {"cascades-field.json", {}},
        {"cascades-field.json", {m + "cascades=2", m + "filter=grid", m + "kernel=8", m + "size=256"}},
    };
    for (const Case& c : cases) {
        std::string what = c.scene;
        for (const std::string& s : c.set) what += " " + s;
        SCOPED_TRACE(what);
        const Scene scene = loadSceneFile(scenes / c.scene, c.set);
        expectSameFrame(scene, what);
    }
    // As shipped, the street's cascades draw 0.15, 0.26, 0.21 and 0.62 of
    // their windows (measured, at 320x240 as at 800x600: the fit does not
    // depend on the frame's size). The last slice's window is the street's
    // width under its casters across the light (core/LightCamera:
    // receiversWindow), most of which it reads; the nearer ones' are their
    // spheres', of which the lookups read little. Bounds: the three nearer
    // under 0.3, the last under 0.7; off, every texel (1).
    Renderer renderer(test::glContext());
    const Scene street = loadSceneFile(scenes / "long-view.json");
    renderer.upload(street);
    for (const bool regions : {true, false}) {
        RenderOptions options{320, 240};
        options.shadowRegions = regions;
        const FrameStats stats = renderer.render(street, options);
        int counted = 0;
        for (const auto& [name, value] : stats.counters) {
            if (name.find(".drawnShare") == std::string::npos) continue;
            ++counted;
            if (!regions)
                EXPECT_EQ(value, 1.0) << name << ": off, every texel";
            else if (name.find("cascade3.") != std::string::npos)
                EXPECT_LT(value, 0.7) << name;
            else
                EXPECT_LT(value, 0.3) << name;
        }
        EXPECT_EQ(counted, 4) << "one share per cascade";
    }
}

// Technique "disc" under each light type: an orthographic light space for
// the sun, a perspective one from the lamp around each disc.
TEST_F(ShadowRegionGLTest, DiscsUnderEveryLightTypeLookTheSame) {
    const std::vector<std::vector<std::string>> lights = {
        {},
        {R"(lights[0]={"type": "point", "position": [0.5, 6, 0.5], "shadow": {"technique": "disc"}})"},
        {R"(lights[0]={"type": "spot", "position": [1, 7, 1], "direction": [-0.1, -1, -0.1], "outerCone": 60, "innerCone": 50, "shadow": {"technique": "disc"}})"},
        {R"(lights[0]={"type": "point", "position": [-2, 5, 0], "shadow": {"technique": "disc"}})"},  // 2 m over a disc of 1 m: its shadow spreads wide
    };
    for (const auto& set : lights) {
        std::string what = "discs";
        for (const std::string& s : set) what += " " + s;
        SCOPED_TRACE(what);
        const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes/discs.json", set);
        const std::optional<double> share = expectSameFrame(scene, what);
        EXPECT_TRUE(share.has_value()) << "the rectangles were not used";
    }
}

// A camera low under a floating slab, looking along the ground through its
// shadow, so that the slab's shadow reaches behind the viewer (the
// rectangles are then not known: the whole frame is tested), and one
// looking up from inside the shadow at the slab.
TEST_F(ShadowRegionGLTest, AViewFromInsideAShadowLooksTheSame) {
    for (const char* camera : {R"("position": [0, 0.3, 0], "target": [0, 0.3, -5])", R"("position": [0.5, 0.2, 0.5], "target": [0, 2, 0])"}) {
        SCOPED_TRACE(camera);
        const Scene scene = test::sceneOf(std::string(R"({"camera": {)") + camera + R"(, "fovY": 70},
          "lights": [{"type": "directional", "direction": [0.2, -1, 0.1], "shadow": {"technique": "map", "map": {"filter": "grid"}}}],
          "nodes": [{"name": "ground", "shape": {"type": "plane", "size": [30, 30]}},
                    {"name": "slab", "shape": {"type": "box", "size": [4, 0.2, 4]}, "translation": [0, 2, 0]},
                    {"name": "post", "shape": {"type": "box", "size": [0.3, 1, 0.3]}, "translation": [3, 0.5, -4]}]})");
        expectSameFrame(scene, "inside-shadow");
    }
}

// An item that receives no shadows is drawn without the test, whether the
// light has rectangles or not (cascades: none; fit sdsm: a depth pre-pass,
// where items are not split).
TEST_F(ShadowRegionGLTest, ItemsThatReceiveNoShadowsLookTheSame) {
    for (const char* how : {"lights[0].shadow.map.filter=grid", "lights[0].shadow.map.cascades=3", "lights[0].shadow.map.fit=sdsm"}) {
        SCOPED_TRACE(how);
        const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes/learnopengl-shadow-mapping.json",
                                          {"lights[0].shadow.technique=map", how, "nodes[0].receivesShadows=false", "nodes[2].receivesShadows=false"});
        expectSameFrame(scene, std::string("no-receivers ") + how);
    }
}

// LearnOpenGL's directional scene at the peer's settings (a 3x3 kernel):
// the three cubes' shadows and the cubes take a fifth of the frame or so
// (measured: 0.22 at 800x600); the rest of the floor is shaded without the
// nine taps. Less than 0.4: the rectangles are around each cube, not one
// around all three (0.48).
TEST_F(ShadowRegionGLTest, LearnOpenGlsFloorIsMostlyShadedWithoutTheTest) {
    const Scene scene = loadSceneFile(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes/learnopengl-shadow-mapping.json",
                                      {"lights[0].shadow.technique=map", "lights[0].shadow.map.preset=learnopengl"});
    const Frame f = render(scene, true, 800, 600);
    ASSERT_TRUE(f.share.has_value()) << "the rectangles were not used";
    EXPECT_GT(*f.share, 0.05) << "the shadows are in view: some pixels must be tested";
    EXPECT_LT(*f.share, 0.4);
}
