// Technique "volume" (stencil shadow volumes, Ganovelli et al. §8.5) against the
// ray-traced reference: closed casters under the three kinds of light, the
// camera inside a volume (depth-fail right, depth-pass wrong), open meshes.
#include "GLTestContext.h"
#include "Comparisons.h"
#include "ImageArtifacts.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include "core/Adjacency.h"

#include <filesystem>
#include <set>

using namespace shadowlab;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

double all(const LightComparison& l) { return l.falseLit + l.falseShadow; }

} // namespace

class VolumeGLTest : public GLTest {};

// Volumes are exact up to rasterisation: on every bundled scene (their
// casters are closed meshes, and the planes among them are left out where
// nothing visible is behind them), under suns, spots and point lights, no
// misclassified pixel away from the 1-pixel edge band, and at most 0.1 %
// over all receivers (measured: at most 0.002 %).
TEST_F(VolumeGLTest, ClosedCastersAreExactUnderEveryKindOfLight) {
    std::set<LightType> kinds;
    for (const fs::path& file : test::bundledScenes()) {
        const std::string name = file.stem().string();
        // glass-panel's caster is alpha-tested: volumes follow geometry and
        // shadow the whole panel (docs/scene-format.md); the note says so
        // (VolumeGLTest.AlphaTestedCastersAreRefused).
        if (name == "glass-panel") continue;
        SCOPED_TRACE(name);
        const Scene scene = loadSceneFile(file, {"lights[0].shadow.technique=volume"});
        kinds.insert(scene.lights[0].type);
        const Comparison c = compareScene(scene, 960, 540);
        const bool failedBefore = HasFailure();
        EXPECT_GT(c.lights[0].referenceShadowedPixels, 1000u);
        // cascades-field's small, distant bunnies (many triangles to a pixel)
        // leave 14 false-shadow pixels (0.005 %, measured) on their own
        // terminators outside the band: a known gap, not hidden by moving
        // the scene. Every other scene is exact.
        EXPECT_LE(awayFromEdges(c.lights[0]), name == "cascades-field" ? 0.0001 : 0.0);
        EXPECT_LE(all(c.lights[0]), 0.001);
        if (!failedBefore && HasFailure()) test::saveImagesIfFailed(name, c.technique, c.reference);
    }
    EXPECT_EQ(kinds.size(), 3u) << "suns, spots and point lights";
}

// The camera under a slab, inside its shadow volume, looking at the floor
// in the slab's shadow and beyond it: depth-fail counts the faces behind
// the floor and is right; depth-pass misses the volume's face behind the
// camera, so it turns the shadow inside out.
TEST_F(VolumeGLTest, InsideAVolumeDepthFailIsRightAndDepthPassIsNot) {
    auto scene = [](const char* method) {
        return parseScene(std::string(R"({"camera": {"position": [0, 1, 0], "target": [3, 0, 2], "fovY": 70},
          "lights": [{"type": "directional", "direction": [0, -1, 0], "shadow": {"technique": "volume", "volume": {"method": ")") +
                              method + R"("}}}],
          "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [30, 30]}},
                    {"name": "slab", "shape": {"type": "box", "size": [6, 0.3, 6]}, "translation": [0, 3, 0]}]})",
                          "inside", ".");
    };
    const Comparison fail = compareScene(scene("depth-fail"), 640, 360);
    const Comparison pass = compareScene(scene("depth-pass"), 640, 360);
    EXPECT_GT(fail.lights[0].referenceShadowedPixels, 10000u) << "the floor under the slab is in view";
    EXPECT_EQ(awayFromEdges(fail.lights[0]), 0.0);
    EXPECT_GT(awayFromEdges(pass.lights[0]), 0.1) << "depth-pass inside a volume";
}

// An alpha-tested caster cannot cast through its holes with volumes: the
// frame is refused in one line naming the light and the material (a note
// used to say so while the holes were shadowed whole). The same caster
// made opaque renders.
TEST_F(VolumeGLTest, AlphaTestedCastersAreRefused) {
    const fs::path glass = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "glass-panel.json";
    const Scene scene = loadSceneFile(glass, {"lights[0].shadow.technique=volume"});
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    try {
        renderer.render(scene);
        ADD_FAILURE() << "an alpha-tested caster was drawn with volumes";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("lights[0].shadow.technique: volume: material 'glass' is alpha-tested"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    const Scene opaque = loadSceneFile(glass, {"lights[0].shadow.technique=volume", "materials.glass.alphaMode=\"opaque\""});
    renderer.upload(opaque);
    EXPECT_NO_THROW(renderer.render(opaque));
}

// An open mesh (a lone quad over the floor) is named in the frame's notes
// and still casts the right shadow: its light-facing side with its open
// edges extruded; "triangles" (every triangle its own volume) agrees.
TEST_F(VolumeGLTest, AnOpenCasterIsNotedAndStillCastsItsShadow) {
    for (const char* open : {"facing", "triangles"}) {
        SCOPED_TRACE(open);
        const Scene scene = parseScene(std::string(R"({"camera": {"position": [0, 8, 7], "target": [0, 0, 0]},
          "lights": [{"type": "point", "position": [0.5, 6, 0.3], "shadow": {"technique": "volume", "volume": {"openMeshes": ")") +
                                           open + R"("}}}],
          "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [20, 20]}},
                    {"name": "sheet", "shape": {"type": "plane", "size": [2, 2]}, "translation": [0, 2, 0], "rotation": [20, 0, 10]},
                    {"name": "crate", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [2, 0.5, 1]}]})",
                                       "open", ".");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 320;
        options.height = 180;
        const FrameStats stats = renderer.render(scene, options);
        bool named = false;
        for (const std::string& note : stats.notes) named = named || note.find("'plane") != std::string::npos || note.find("sheet") != std::string::npos;
        EXPECT_TRUE(named) << (stats.notes.empty() ? std::string("no notes") : stats.notes[0]);
        const Comparison c = compareScene(scene, 640, 360);
        EXPECT_GT(c.lights[0].referenceShadowedPixels, 2000u);
        EXPECT_EQ(awayFromEdges(c.lights[0]), 0.0);
    }
}

// With the camera outside every volume the three counts agree: depth-fail,
// depth-pass and the book's construction (finite extrusion, two culled
// passes) shadow the same pixels of the spot scene.
TEST_F(VolumeGLTest, TheThreeMethodsAgreeWithTheCameraOutside) {
    std::vector<float> visibility[3];
    const char* methods[3] = {"depth-fail", "depth-pass", "book"};
    for (int k = 0; k < 3; ++k) {
        const Scene scene = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "spot-objects.json",
                                          {"lights[0].shadow.technique=volume", std::string("lights[0].shadow.volume.method=\"") + methods[k] + "\""});
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        RenderOptions options;
        options.width = 640;
        options.height = 360;
        renderer.render(scene, options);
        visibility[k] = renderer.readVisibility(scene, 0);
    }
    std::size_t shadowed = 0, differ = 0;
    for (std::size_t i = 0; i < visibility[0].size(); ++i) {
        shadowed += visibility[0][i] < 0.5f;
        differ += (visibility[1][i] < 0.5f) != (visibility[0][i] < 0.5f) || (visibility[2][i] < 0.5f) != (visibility[0][i] < 0.5f);
    }
    EXPECT_GT(shadowed, 2000u);
    // Rasterised volume faces meet the same pixels; a few edge pixels may round either way.
    EXPECT_LE(static_cast<double>(differ), 0.001 * static_cast<double>(shadowed));
}

// Silhouettes found and extruded on the CPU and by the geometry shader
// build the same volumes (the same facing decisions, in object space and
// double precision on both sides). Tolerance: a handful of pixels may
// differ where a volume's edge passes through a pixel centre, because the
// vertex and geometry stages round the same expression differently in the
// last bit (measured: 0 to 10 of 518,400 pixels on these scenes); the bar
// is 1 in 10,000.
TEST_F(VolumeGLTest, CpuAndGpuExtrusionGiveTheSameShadows) {
    for (const char* name : {"two-boxes-sun", "room-point", "four-spheres-point"}) {
        SCOPED_TRACE(name);
        std::vector<float> visibility[2];
        std::size_t volumes[2] = {0, 0};
        const char* extrusion[2] = {"gpu", "cpu"};
        for (int k = 0; k < 2; ++k) {
            const Scene scene = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / (std::string(name) + ".json"),
                                              {"lights[0].shadow.technique=volume", std::string("lights[0].shadow.volume.extrusion=\"") + extrusion[k] + "\""});
            Renderer renderer(test::glContext());
            renderer.upload(scene);
            RenderOptions options;
            options.width = 960;
            options.height = 540;
            const FrameStats stats = renderer.render(scene, options);
            for (const auto& [key, value] : stats.counters) volumes[k] += key == "light[0].cpuTriangles" ? static_cast<std::size_t>(value) : 0;
            visibility[k] = renderer.readVisibility(scene, 0);
        }
        EXPECT_EQ(volumes[0], 0u) << "the GPU path does no CPU work";
        EXPECT_GT(volumes[1], 0u) << "the CPU path did";
        std::size_t shadowed = 0, differ = 0;
        for (std::size_t i = 0; i < visibility[0].size(); ++i) {
            shadowed += visibility[0][i] < 0.5f;
            differ += (visibility[0][i] < 0.5f) != (visibility[1][i] < 0.5f);
        }
        EXPECT_GT(shadowed, 2000u);
        EXPECT_LE(static_cast<double>(differ), 1e-4 * static_cast<double>(visibility[0].size()));
    }
}

namespace {

// A closed slab whose top is an n x n grid of faces lifted by up to 1e-6 at
// random: nearly coplanar neighbours (Ganovelli et al.'s §8.5 "hole" case).
Mesh jitteredSlab(int n) {
    Mesh m;
    m.name = "jittered slab";
    auto id = [n](int i, int j, int layer) { return static_cast<std::uint32_t>(layer * (n + 1) * (n + 1) + j * (n + 1) + i); };
    std::uint32_t state = 12345u;
    auto noise = [&state] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f - 0.5f;
    };
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const float x = -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n), z = -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(n);
                const bool inner = i > 0 && j > 0 && i < n && j < n;
                m.positions.push_back({x, layer == 1 ? 1.0f + (inner ? 2e-6f * noise() : 0.0f) : 0.8f, z});
            }
    auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {  // a b c d counter-clockwise seen from outside
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            quad(id(i, j, 1), id(i, j + 1, 1), id(i + 1, j + 1, 1), id(i + 1, j, 1));  // top, seen from +y
            quad(id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0));  // bottom, seen from -y
        }
    for (int k = 0; k < n; ++k) {
        quad(id(k, 0, 0), id(k, 0, 1), id(k + 1, 0, 1), id(k + 1, 0, 0));          // z = -1
        quad(id(k + 1, n, 0), id(k + 1, n, 1), id(k, n, 1), id(k, n, 0));          // z = +1
        quad(id(0, k + 1, 0), id(0, k + 1, 1), id(0, k, 1), id(0, k, 0));          // x = -1
        quad(id(n, k, 0), id(n, k, 1), id(n, k + 1, 1), id(n, k + 1, 0));          // x = +1
    }
    m.normals.assign(m.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    return m;
}

} // namespace

// A light grazing the slab's top exactly: each face's facing is a coin
// toss of rounding, and silhouettes run all over the top. The slab's shadow
// on the wall behind must still be a clean band (0 misclassified away from
// the edge band against the reference), so a face and its neighbour must
// never disagree about their shared edge, on the GPU or the CPU.
TEST_F(VolumeGLTest, NearlyCoplanarFacesMakeNoHoles) {
    for (const char* extrusion : {"gpu", "cpu"}) {
        SCOPED_TRACE(extrusion);
        Scene scene = parseScene(std::string(R"({"camera": {"position": [-4, 2.5, 3], "target": [4, 0.9, 0]},
          "lights": [{"type": "directional", "direction": [1, 0, 0.15], "shadow": {"technique": "volume", "volume": {"extrusion": ")") +
                                     extrusion + R"("}}}],
          "nodes": [{"name": "wall", "shape": {"type": "plane", "size": [4, 10]}, "translation": [5, 1, 0], "rotation": [0, 0, 90]}]})",
                                 "coplanar", ".");
        const Mesh slab = jitteredSlab(24);
        ASSERT_EQ(openEdges(slab.positions, slab.indices), 0u) << "the slab is closed";
        scene.meshes.push_back(slab);
        Node node;
        node.name = "slab";
        node.mesh = static_cast<int>(scene.meshes.size()) - 1;
        node.receivesShadows = false;
        scene.nodes.push_back(node);
        const Comparison c = test::compareScene(scene, 640, 360);
        EXPECT_GT(c.lights[0].referenceShadowedPixels, 800u) << "the slab's band on the wall is in view";
        EXPECT_EQ(awayFromEdges(c.lights[0]), 0.0);
        if (HasFailure()) test::saveImagesIfFailed(std::string("coplanar-") + extrusion, c.technique, c.reference);
    }
}

// Several lights in one frame, each with its own volumes: the stencil is
// cleared per light and each light is added where its own count is zero.
TEST_F(VolumeGLTest, SeveralLightsEachCountTheirOwnVolumes) {
    const Scene scene = parseScene(R"({"camera": {"position": [5, 6, 9], "target": [0, 0.8, 0]},
      "lights": [
        {"name": "sun", "type": "directional", "direction": [0.4, -1, -0.3], "intensity": 0.5, "shadow": {"technique": "volume"}},
        {"name": "lamp", "type": "point", "position": [-2, 3, 1], "intensity": 0.5, "shadow": {"technique": "volume", "volume": {"extrusion": "cpu"}}},
        {"name": "spot", "type": "spot", "position": [1, 5, 3], "direction": [0, -1, -0.5], "outerCone": 40, "innerCone": 35, "intensity": 0.5,
         "shadow": {"technique": "volume", "volume": {"method": "book"}}}],
      "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [14, 14]}},
                {"name": "ball", "shape": {"type": "sphere", "radius": 0.6}, "translation": [0, 1, 0]},
                {"name": "crate", "shape": {"type": "box", "size": [1, 1.4, 1]}, "translation": [1.2, 0.7, 1.5], "rotation": [0, 30, 0]},
                {"name": "ring", "shape": {"type": "torus", "majorRadius": 0.6, "minorRadius": 0.15}, "translation": [-1.2, 1.2, -1.5], "rotation": [60, 0, 0]}]})",
                                   "three", ".");
    const Comparison c = compareScene(scene, 800, 450);
    ASSERT_EQ(c.lights.size(), 3u);
    for (const LightComparison& l : c.lights) {
        EXPECT_GT(l.referenceShadowedPixels, 1000u) << l.name;
        EXPECT_EQ(awayFromEdges(l), 0.0) << l.name;
    }
}
