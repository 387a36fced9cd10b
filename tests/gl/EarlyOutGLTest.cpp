// The filters' early out (MapOptions::earlyOut): grid (nearest taps) and
// pcf20 take the kernel's corners first and skip the taps between them
// where they agree. Across a straight shadow edge that is exactly every
// tap's answer (a caster's rasterised edge is a linear inequality over the
// texels, so taps between corners that satisfy it satisfy it too, and the
// grid's taps sit whole texels apart); on LearnOpenGL's two scenes at
// their presets the classification against the reference stays the same
// and only penumbra pixels where a caster's edges meet change.
#include "GLTestContext.h"
#include "Comparisons.h"

#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace shadowlab;
using shadowlab::test::awayFromEdges;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;
using shadowlab::test::sceneOf;

namespace {

std::vector<float> visibility(const Scene& scene, int width, int height) {
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {width, height});
    return renderer.readVisibility(scene, 0);
}

} // namespace

class EarlyOutGLTest : public GLTest {};

// A slab turned 30 degrees about the vertical, so that its edge crosses
// the map's texels diagonally (through the origin), under a sun straight
// down; the slab hangs above the camera, which looks straight down at the
// edge's shadow. At 512^2 over the 40 m plane one texel is ~0.08 m, ~11
// pixels here: every kernel's penumbra spans many pixels, and even kernel
// 8's leaves a fifth of the view wholly lit and a fifth wholly shadowed
// (measured: 23k of 102k pixels each; penumbrae 16k for kernel 3 to 56k).
TEST_F(EarlyOutGLTest, AStraightEdgeGetsEveryTapsAnswer) {
    for (int kernel : {3, 4, 5, 8}) {
        SCOPED_TRACE("grid kernel " + std::to_string(kernel));
        auto scene = [&](bool earlyOut) {
            return sceneOf(R"({"camera": {"position": [0, 2, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fovY": 60},
              "lights": [{"type": "directional", "direction": [0, -1, 0.0001], "shadow": {"technique": "map", "map":
                {"size": 512, "fit": "scene", "filter": "grid", "gridTaps": "nearest", "kernel": )" +
                               std::to_string(kernel) + R"(, "earlyOut": )" + (earlyOut ? "true" : "false") + R"(}}}],
              "nodes": [{"name": "ground", "shape": {"type": "plane", "size": [40, 40]}},
                        {"name": "slab", "shape": {"type": "box", "size": [20, 0.2, 20]}, "translation": [8.660254, 5, -5], "rotation": [0, 30, 0]}]})");
        };
        const std::vector<float> early = visibility(scene(true), 320, 320), every = visibility(scene(false), 320, 320);
        ASSERT_EQ(early.size(), every.size());
        int lit = 0, shadowed = 0, penumbra = 0, differing = 0;
        for (std::size_t i = 0; i < early.size(); ++i) {
            lit += every[i] == 1.0f;
            shadowed += every[i] == 0.0f;
            penumbra += every[i] > 0.0f && every[i] < 1.0f;
            differing += early[i] != every[i];
        }
        // The edge is in view with both sides and a penumbra between them.
        EXPECT_GT(lit, 20000);
        EXPECT_GT(shadowed, 20000);
        EXPECT_GT(penumbra, 10000);
        EXPECT_EQ(differing, 0) << "the early out changed pixels across a straight edge";
    }
}

// LearnOpenGL's scenes at their presets (grid 3x3 and pcf20), at
// compare's size: the share misclassified away from the edge band is the
// same to 0.001 % (5 pixels; measured: identical), and the visibility
// differs at no more than 0.05 % of the pixels (measured at 800x600: 7 and
// 65 pixels of the frame, penumbrae where a cube's edges meet its
// shadow's). More than none: the option reaches the light pass.
TEST_F(EarlyOutGLTest, LearnOpenGlScenesKeepTheirClassification) {
    for (const char* name : {"learnopengl-shadow-mapping", "learnopengl-point-shadows"}) {
        SCOPED_TRACE(name);
        const std::filesystem::path file = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes" / (std::string(name) + ".json");
        auto scene = [&](bool earlyOut) {
            return loadSceneFile(file, {"lights[0].shadow.technique=map", "lights[0].shadow.map.preset=learnopengl",
                                        std::string("lights[0].shadow.map.earlyOut=") + (earlyOut ? "true" : "false")});
        };
        const Comparison early = compareScene(scene(true)), every = compareScene(scene(false));
        EXPECT_NEAR(awayFromEdges(early.lights[0]), awayFromEdges(every.lights[0]), 1e-5);
        const std::vector<float> a = visibility(scene(true), 960, 540), b = visibility(scene(false), 960, 540);
        ASSERT_EQ(a.size(), b.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
        EXPECT_LE(static_cast<double>(differing) / static_cast<double>(a.size()), 0.0005);
        EXPECT_GT(differing, 0u) << "earlyOut false must take every tap: the two should differ somewhere";
    }
}

// pcss's umbra: where every blocker tap finds a blocker and the filter's
// disk lies inside their hull, the filter is skipped and the pixel is 0.
// penumbra-step (a point light of radius 0.5 over a sheet's straight
// edge: a quarter of the view is umbra) and spot-objects with a spot of
// radius 0.3 (a sphere, a cone, a cylinder and a box), at 480x270: no
// pixel changes (the filter's taps there are all blocked, as the hull
// argument says for straight edges; measured: none changes on the curved
// casters either), and the RMSE against the area light's reference is
// the same.
TEST_F(EarlyOutGLTest, PcssSkipsOnlyTheUmbrasFilter) {
    for (const auto& [name, size] : {std::pair{"penumbra-step", ""}, std::pair{"spot-objects", "lights[0].size=0.3"}}) {
        SCOPED_TRACE(name);
        const std::filesystem::path file = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes" / (std::string(name) + ".json");
        auto scene = [&](bool earlyOut) {
            std::vector<std::string> set = {"lights[0].shadow.technique=map", "lights[0].shadow.map.filter=pcss",
                                            std::string("lights[0].shadow.map.earlyOut=") + (earlyOut ? "true" : "false")};
            if (*size) set.emplace_back(size);
            return loadSceneFile(file, set);
        };
        const Comparison early = compareScene(scene(true), 480, 270), every = compareScene(scene(false), 480, 270);
        EXPECT_EQ(early.lights[0].rmse, every.lights[0].rmse);
        const std::vector<float> a = visibility(scene(true), 480, 270), b = visibility(scene(false), 480, 270);
        ASSERT_EQ(a.size(), b.size());
        std::size_t differing = 0, umbra = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            differing += a[i] != b[i];
            umbra += b[i] == 0.0f;
        }
        EXPECT_EQ(differing, 0u);
        EXPECT_GT(umbra, a.size() / 5) << "the test must cover a large umbra";
    }
}
