// Technique "map" on point lights: depth cube maps (Lawonn's lecture) against the
// ray-traced reference: every face of a room, the bundled point-light
// scenes, LearnOpenGL's point-shadow scene, one pass against six, no seams,
// and culling per face.
#include "Comparisons.h"
#include "GLTestContext.h"
#include "ImageArtifacts.h"

#include "techniques/map/options/Filters.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/SceneFile.h>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <sstream>

using namespace shadowlab;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

std::string vec(const glm::vec3& v) {
    std::ostringstream s;
    s << "[" << v.x << ", " << v.y << ", " << v.z << "]";
    return s.str();
}

// A closed 10 m room seen from inside, a point light off its centre, and a
// crate 2.5 m from the light along each axis, so each cube face holds a
// caster whose shadow falls on the wall it faces.
const glm::vec3 kLight(0.3f, 0.2f, 0.1f);
const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

std::string roomNodes() {
    std::string nodes = R"({"name": "room", "shape": {"type": "box", "size": [10, 10, 10]}})";
    for (int f = 0; f < 6; ++f)
        nodes += R"(, {"name": "crate )" + std::to_string(f) + R"(", "shape": {"type": "box", "size": [0.8, 0.8, 0.8]}, "translation": )" +
                 vec(kLight + 2.5f * kAxes[f]) + R"(, "rotation": [10, 20, 30]})";
    return nodes;
}

Scene roomScene(const glm::vec3& cameraPosition, const glm::vec3& target, const std::string& mapOptions) {
    return parseScene(R"({"camera": {"position": )" + vec(cameraPosition) + R"(, "target": )" + vec(target) + R"(, "fovY": 100},
      "lights": [{"type": "point", "position": )" + vec(kLight) + R"(, "shadow": {"technique": "map", "map": {)" + mapOptions + R"(}}}],
      "nodes": [)" + roomNodes() + "]}",
                      "room", ".");
}

std::vector<fs::path> pointLightScenes() {
    std::vector<fs::path> out;
    for (const fs::path& file : test::bundledScenes()) {
        for (const Light& light : loadSceneFile(file).lights)
            if (light.type == LightType::Point) {
                out.push_back(file);
                break;
            }
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

class CubeMapGLTest : public GLTest {};

// The issue's bar for each of the six face directions: filter "none" at
// 1024^2 per face, at most 0.05 % of the receivers misclassified outside the
// 1-pixel band. The camera stands beside the light looking along each axis
// at the wall that face covers (the crate's shadow on it in view).
TEST_F(CubeMapGLTest, APointLightInARoomShadowsAllSixWalls) {
    for (int f = 0; f < 6; ++f) {
        SCOPED_TRACE("face " + std::to_string(f));
        const glm::vec3 d = kAxes[f];
        const glm::vec3 side = std::abs(d.y) > 0.5f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
        const Scene scene = roomScene(kLight - 1.0f * d + 2.2f * side + 0.8f * glm::cross(d, side), kLight + 5.0f * d,
                                      R"("filter": "none", "size": 1024)");
        const Comparison c = compareScene(scene, 640, 360);
        const LightComparison& l = c.lights[0];
        const bool failedBefore = HasFailure();
        EXPECT_GT(l.referenceShadowedPixels, 1000u) << "the crate's shadow on the wall is in view";
        EXPECT_LE(awayFromEdges(l), 0.0005);
        if (!failedBefore && HasFailure()) test::saveImagesIfFailed("room-face-" + std::to_string(f), c.technique, c.reference);
    }
}

// Every bundled scene with a point light meets the same bound (filter none, 1024^2).
TEST_F(CubeMapGLTest, EveryBundledPointLightSceneMatchesTheReference) {
    int lights = 0;
    for (const fs::path& file : pointLightScenes()) {
        SCOPED_TRACE(file.filename().string());
        const Scene plain = loadSceneFile(file);
        std::vector<std::string> overrides;
        for (std::size_t i = 0; i < plain.lights.size(); ++i) {
            if (plain.lights[i].type != LightType::Point) continue;
            const std::string at = "lights[" + std::to_string(i) + "].shadow.";
            overrides.insert(overrides.end(), {at + "technique=map", at + "map.filter=\"none\"", at + "map.size=1024"});
        }
        const Scene scene = loadSceneFile(file, overrides);
        const Comparison c = compareScene(scene, 960, 540);
        for (std::size_t i = 0; i < c.lights.size(); ++i) {
            if (scene.lights[i].type != LightType::Point) continue;
            EXPECT_LE(awayFromEdges(c.lights[i]), 0.0005) << c.lights[i].name;
            ++lights;
        }
        if (HasFailure()) {
            test::saveImagesIfFailed(file.stem().string(), c.technique, c.reference);
            break;
        }
    }
    EXPECT_GE(lights, 4);
}

// LearnOpenGL's point-shadow demo on its own scene misclassifies 0.092 % of
// the receivers outside the band (measured for the issue); its settings
// here must do better, and our defaults better still or as well.
TEST_F(CubeMapGLTest, LearnOpenGlPointSceneBeatsTheDemo) {
    const fs::path file = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "learnopengl-point-shadows.json";
    const Comparison theirs = compareScene(loadSceneFile(file, {"lights[0].shadow.technique=map", "lights[0].shadow.map.preset=\"learnopengl\""}), 800, 600);
    const Comparison ours = compareScene(loadSceneFile(file, {"lights[0].shadow.technique=map"}), 800, 600);
    EXPECT_GT(theirs.lights[0].referenceShadowedPixels, 5000u) << "the cubes' shadows are in view";
    EXPECT_LT(awayFromEdges(theirs.lights[0]), 0.00092);
    EXPECT_LE(awayFromEdges(ours.lights[0]), awayFromEdges(theirs.lights[0]));
}

// One geometry-shader pass and six passes store the same depth in every
// texel of every face (the same fragment shader runs on the same fragments).
TEST_F(CubeMapGLTest, OnePassAndSixPassesGiveTheSameMap) {
    std::vector<float> maps[2];
    const char* passes[2] = {"one", "six"};
    for (int k = 0; k < 2; ++k) {
        const Scene scene = roomScene(glm::vec3(-3.0f, 3.0f, 4.0f), kLight, std::string(R"("size": 256, "cubePasses": ")") + passes[k] + "\"");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 320;
        options.height = 180;
        renderer.render(scene, options);
        for (DebugImage& image : renderer.debugImages(scene))
            if (image.name == "light0-cube") maps[k] = std::move(image.values);
    }
    ASSERT_EQ(maps[0].size(), 6u * 256u * 256u);
    ASSERT_EQ(maps[0].size(), maps[1].size());
    std::size_t covered = 0, different = 0;
    for (std::size_t i = 0; i < maps[0].size(); ++i) {
        covered += maps[0][i] < 1.0f;
        different += maps[0][i] != maps[1][i];
    }
    EXPECT_GT(covered, 6u * 1000u) << "the crates are in every face";
    EXPECT_EQ(different, 0u);
}

// A floor under a light crosses four cube-face edges (the -Y face's
// boundary). Nothing shadows it, so a single falsely shadowed pixel, edge
// band included, is a seam; with every filter. (A crate under the floor
// keeps the floor in the map: it could shadow that crate.) Every filter a
// cube takes but PCSS, whose soft shadows need a light with a size
// (SoftShadowGLTest).
TEST_F(CubeMapGLTest, NoSeamsWhereAFloorCrossesFaceEdges) {
    for (const map::FilterInfo& info : map::filters()) {
        if (!info.forCube || info.filter == MapFilter::Pcss) continue;
        const std::string filter = info.name;
        SCOPED_TRACE(filter);
        const Scene scene = parseScene(
            std::string(R"({"camera": {"position": [0.2, 6, 0.3], "target": [0, 0, 0], "fovY": 100},
              "lights": [{"type": "point", "position": [0, 1, 0], "shadow": {"technique": "map", "map": {"size": 256, "filter": ")") +
                filter + R"("}}}],
              "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [30, 30]}},
                        {"name": "under", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [0, -3, 0], "receivesShadows": false}]})",
            "seams", ".");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 480;
        options.height = 270;
        options.surfaces = true;
        const FrameStats stats = renderer.render(scene, options);
        double triangles = -1.0;
        for (const auto& [name, value] : stats.counters)
            if (name == "shadow[0].triangles") triangles = value;
        EXPECT_GE(triangles, 2.0) << "the floor is drawn into the map";
        const std::vector<float> visibility = renderer.readVisibility(scene, 0);
        std::size_t shadowed = 0, floor = 0;
        const SurfaceBuffer surfaces = renderer.readSurfaces();
        for (std::size_t i = 0; i < visibility.size(); ++i) {
            if (surfaces.position[i].w < 0.5f || std::abs(surfaces.position[i].y) > 1e-3f) continue;
            ++floor;
            shadowed += visibility[i] < 0.5f;
        }
        EXPECT_GT(floor, 100000u);
        EXPECT_EQ(shadowed, 0u);
    }
}

// Casters on one side of the light reach only the faces they touch: fewer
// triangles sent than with faceCulling false (every caster to all six).
TEST_F(CubeMapGLTest, CastersAreDrawnOnlyIntoTheFacesTheyTouch) {
    double sent[2] = {0.0, 0.0};
    const bool culling[2] = {true, false};
    for (int k = 0; k < 2; ++k) {
        const Scene scene = parseScene(std::string(R"({"camera": {"position": [0, 6, 8], "target": [0, 0, 0]},
          "lights": [{"type": "point", "position": [0, 3, 0], "shadow": {"technique": "map", "map": {"size": 256, "faceCulling": )") +
                                           (culling[k] ? "true" : "false") + R"(}}}],
          "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [20, 20]}},
                    {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "translation": [0.3, 1, 0.2]},
                    {"name": "crate", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [-1, 0.5, 0.5]}]})",
                                       "culling", ".");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 320;
        options.height = 180;
        const FrameStats stats = renderer.render(scene, options);
        for (const auto& [name, value] : stats.counters)
            if (name.rfind("shadow[0].faceTriangles.", 0) == 0) sent[k] += value;
    }
    // Both casters lie below the light: only -Y (and no side face fully) sees them.
    EXPECT_GT(sent[0], 0.0);
    EXPECT_LT(sent[0], 0.5 * sent[1]);
}

// A cube's pass leaves out the far sides of closed casters the light sees
// from outside (map/passes/CasterDraw.h). Whichever way a crate's triangles wind
// (as built, mirrored by its transform, turned inside out), the map keeps
// its near side: the crate's side facing the light lies 2.5 m from it
// along +X, its far side 3.5 m, and a floor (open: both sides drawn) 2 m
// below it (a ball under the floor keeps it in the map), so the stored distances at the two faces' centres stand at
// 1.25 (the far side: 1.75; the offsets and slope bias, a texel's slope
// at most there, move it by well under 0.05).
TEST_F(CubeMapGLTest, ClosedCastersKeepTheirNearSideWhicheverWayTheyWind) {
    const char* ways[3] = {"as built", "mirrored", "inside out"};
    for (int k = 0; k < 3; ++k) {
        Scene scene = parseScene(R"({"camera": {"position": [0, 1, 8], "target": [0, 0, 0]},
          "lights": [{"type": "point", "position": [0, 0, 0], "shadow": {"technique": "map", "map": {"size": 256}}}],
          "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [20, 20]}, "translation": [0, -2, 0]},
                    {"name": "crate", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [3, 0, 0]},
                    {"name": "under", "shape": {"type": "sphere", "radius": 0.3}, "translation": [1, -3, 0]}]})",
                                 "winding", ".");
        for (Node& node : scene.nodes)
            if (node.name == "crate" && k == 1) node.scale = glm::vec3(-1.0f, 1.0f, 1.0f);
        if (k == 2)
            for (Mesh& mesh : scene.meshes)
                if (mesh.triangleCount() == 12)  // the crate's box (the floor has two)
                    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 160;
        options.height = 120;
        renderer.render(scene, options);
        std::vector<float> cube;
        for (DebugImage& image : renderer.debugImages(scene))
            if (image.name == "light0-cube") cube = std::move(image.values);
        ASSERT_EQ(cube.size(), 6u * 256u * 256u) << ways[k];
        const std::size_t centre = 128u * 256u + 128u;
        const float crate = cube[0 * 256u * 256u + centre], floor = cube[3 * 256u * 256u + centre];  // faces +X and -Y
        ASSERT_LT(crate, 1.0f) << ways[k];
        ASSERT_LT(floor, 1.0f) << ways[k];
        EXPECT_NEAR(crate / floor, 1.25f, 0.05f) << ways[k] << ": the crate's near side, not its far side (1.75)";
    }
}

// Point-light options that only make sense for 2D maps, and the reverse, are named errors.
TEST_F(CubeMapGLTest, FiltersForTheOtherKindOfMapAreNamedErrors) {
    auto load = [](const std::string& type, const std::string& options) {
        return parseScene(R"({"lights": [{"type": ")" + type + R"(", "position": [0, 3, 0], "shadow": {"technique": "map", "map": {)" + options +
                              "}}}], \"nodes\": []}",
                          "scene.json", ".");
    };
    try {
        load("point", R"("filter": "dither4")");
        FAIL() << "dither4 on a cube";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("lights[0].shadow.map.filter"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("dither4"), std::string::npos) << e.what();
    }
    EXPECT_THROW(load("point", R"("mipmaps": true)"), Error);
    EXPECT_THROW(load("directional", R"("filter": "pcf20")"), Error);
    EXPECT_NO_THROW(load("point", R"("filter": "pcf20")"));
}

// Two point lights (one cube-map array), a spot and a sun in one frame:
// each within the same 0.05 % of the reference; the rgba8 packing of the
// cubes classifies like depth32f on 99.9 % of the receivers.
TEST_F(CubeMapGLTest, TwoPointLightsASpotAndASunInOneFrame) {
    const std::string lights = R"(
        {"name": "lamp a", "type": "point", "position": [-2, 2.5, 1], "intensity": 0.6, "shadow": {"technique": "map", "map": {"filter": "none", "format": "FORMAT"}}},
        {"name": "lamp b", "type": "point", "position": [2.5, 1.5, -1], "intensity": 0.6, "shadow": {"technique": "map", "map": {"filter": "none", "format": "FORMAT"}}},
        {"name": "spot", "type": "spot", "position": [0, 6, 4], "direction": [0, -1, -0.6], "outerCone": 35, "innerCone": 30, "intensity": 0.5,
         "shadow": {"technique": "map", "map": {"filter": "none"}}},
        {"name": "sun", "type": "directional", "direction": [0.4, -1, -0.3], "intensity": 0.4, "shadow": {"technique": "map", "map": {"filter": "none"}}})";
    const std::string nodes = R"(
        {"name": "floor", "shape": {"type": "plane", "size": [14, 14]}},
        {"name": "wall", "shape": {"type": "plane", "size": [14, 6]}, "translation": [0, 3, -4], "rotation": [90, 0, 0]},
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.6}, "translation": [0, 1, 0]},
        {"name": "crate", "shape": {"type": "box", "size": [1, 1.4, 1]}, "translation": [1, 0.7, 1.5], "rotation": [0, 30, 0]},
        {"name": "ring", "shape": {"type": "torus", "majorRadius": 0.6, "minorRadius": 0.15}, "translation": [-1.2, 1.2, -1.5], "rotation": [60, 0, 0]})";
    auto scene = [&](const std::string& format) {
        std::string l = lights;
        for (std::size_t at = l.find("FORMAT"); at != std::string::npos; at = l.find("FORMAT")) l.replace(at, 6, format);
        return parseScene(R"({"camera": {"position": [5, 6, 9], "target": [0, 0.8, 0]}, "lights": [)" + l + R"(], "nodes": [)" + nodes + "]}", "four", ".");
    };
    const Comparison depth = compareScene(scene("depth32f"), 800, 450);
    ASSERT_EQ(depth.lights.size(), 4u);
    for (const LightComparison& l : depth.lights) {
        EXPECT_GT(l.referenceShadowedPixels, 1000u) << l.name;
        EXPECT_LE(awayFromEdges(l), 0.0005) << l.name;
    }
    Renderer renderer(test::glContext());
    const Scene packedScene = scene("rgba8"), depthScene = scene("depth32f");
    RenderOptions options;
    options.width = 800;
    options.height = 450;
    std::vector<float> visibility[2];
    renderer.upload(depthScene);
    renderer.render(depthScene, options);
    visibility[0] = renderer.readVisibility(depthScene, 0);
    renderer.upload(packedScene);
    renderer.render(packedScene, options);
    visibility[1] = renderer.readVisibility(packedScene, 0);
    std::size_t same = 0;
    for (std::size_t i = 0; i < visibility[0].size(); ++i) same += (visibility[0][i] >= 0.5f) == (visibility[1][i] >= 0.5f);
    EXPECT_GE(static_cast<double>(same), 0.999 * static_cast<double>(visibility[0].size()));
}

// A moving light (room-point's path): each face is cleared only where
// casters were or are, so a map carried from frame to frame must equal one
// drawn afresh, texel for texel.
TEST_F(CubeMapGLTest, AMovingLightLeavesNoStaleDepths) {
    const Scene animated = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "room-point.json",
                                         {"lights[0].shadow.technique=map", "lights[0].shadow.map.size=256"});
    ASSERT_TRUE(animated.lights[0].path.has_value());
    RenderOptions options;
    options.width = 320;
    options.height = 180;
    auto cube = [](Renderer& renderer, const Scene& scene) {
        for (DebugImage& image : renderer.debugImages(scene))
            if (image.name == "light0-cube") return std::move(image.values);
        return std::vector<float>{};
    };
    Renderer carried(test::glContext());
    carried.upload(animated);
    std::vector<float> last;
    for (double t : {0.0, 1.0, 2.5, 6.0}) {
        const Scene at = sceneAtTime(animated, t);
        carried.render(at, options);
        last = cube(carried, at);
    }
    const Scene at = sceneAtTime(animated, 6.0);
    Renderer fresh(test::glContext());
    fresh.upload(at);
    fresh.render(at, options);
    const std::vector<float> expected = cube(fresh, at);
    ASSERT_EQ(last.size(), expected.size());
    ASSERT_FALSE(last.empty());
    std::size_t different = 0;
    for (std::size_t i = 0; i < last.size(); ++i) different += last[i] != expected[i];
    EXPECT_EQ(different, 0u);
}

// A cube stores the reversed window depth with the one-tap filters and
// distance / far written as the fragment's depth with the others
// (MapSettings: cubeWindowDepth): the two clear to different values, so a
// light switching between them on one renderer must clear its faces whole.
// Every frame's image equals a fresh renderer's, byte for byte; and the two
// measures shadow the same receivers (filter none against pcf20 with no
// radius: the same single tap), all but 0.05 % of the pixels.
TEST_F(CubeMapGLTest, SwitchingTheCubesMeasureLeavesNoStaleDepths) {
    const fs::path file = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "room-point.json";
    const std::vector<std::string> filters = {"\"hardware\"", "\"pcf20\"", "\"none\"", "\"poisson\"", "\"hardware\""};
    RenderOptions options;
    options.width = 320;
    options.height = 180;
    Renderer carried(test::glContext());
    for (std::size_t k = 0; k < filters.size(); ++k) {
        SCOPED_TRACE(filters[k]);
        const Scene scene = loadSceneFile(file, {"lights[0].shadow.map.size=256", "lights[0].shadow.map.filter=" + filters[k]});
        if (k == 0) carried.upload(scene);
        carried.render(scene, options);
        Renderer fresh(test::glContext());
        fresh.upload(scene);
        fresh.render(scene, options);
        EXPECT_TRUE(carried.readColor().pixels == fresh.readColor().pixels);
    }
    auto visibility = [&](const std::string& filter) {
        const Scene scene = loadSceneFile(file, {"lights[0].shadow.map.filter=" + filter, "lights[0].shadow.map.diskRadius=0", "lights[0].shadow.map.diskGrowth=0"});
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        renderer.render(scene, options);
        return renderer.readVisibilityRgb(scene, 0);
    };
    const std::vector<glm::vec3> window = visibility("\"none\""), written = visibility("\"pcf20\"");
    ASSERT_EQ(window.size(), written.size());
    std::size_t differ = 0, shadowed = 0;
    for (std::size_t i = 0; i < window.size(); ++i) {
        differ += (window[i].x >= 0.5f) != (written[i].x >= 0.5f);
        shadowed += window[i].x < 0.5f;
    }
    EXPECT_GT(shadowed, 1000u) << "the room's shadows must be in view";
    EXPECT_LE(static_cast<double>(differ), 0.0005 * static_cast<double>(window.size()));
}

// A point light over receivers far past any map's reach (a plane 1e20 m
// wide, a box spanning +-1.5e38 m below it): each face's projected
// rectangle is clamped before it becomes texels (it overflowed an int:
// issue 59, seen by UBSan) and the frame draws without a GL error, every
// visibility in 0..1. The shadows themselves are not judged: a surface
// interpolated between vertices 1e19 m and more apart has positions good
// to about 1e12 m in 32-bit floats. Run under the ASan+UBSan preset too,
// where an overflow stops the test.
TEST_F(CubeMapGLTest, ReceiversPastAnyReachDrawWithoutOverflow) {
    for (const char* ground : {R"({"name": "ground", "shape": {"type": "plane", "size": [1e20, 1e20]}})",
                               R"({"name": "ground", "shape": {"type": "box", "size": [3e38, 1, 3e38]}, "translation": [0, -0.5, 0]})"}) {
        SCOPED_TRACE(ground);
        const Scene scene = parseScene(std::string(R"({"camera": {"position": [0, 6, 6], "target": [0, 0, 0]},
          "lights": [{"type": "point", "position": [0, 3, 0], "shadow": {"technique": "map", "map": {"size": 256}}}],
          "nodes": [)") + ground + R"(, {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "translation": [0, 1, 0]}]})",
                                       "huge", ".");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 160;
        options.height = 90;
        renderer.render(scene, options);
        std::size_t outside = 0;
        for (const float x : renderer.readVisibility(scene, 0)) outside += !(x >= 0.0f && x <= 1.0f);
        EXPECT_EQ(outside, 0u) << "visibilities outside 0..1 (or NaN)";
    }
}
