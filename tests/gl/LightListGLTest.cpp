// The clustered light list: the lights without shadows beyond the base pass's
// shaded in one pass ("lights") instead of a pass each.
#include "GLTestContext.h"

#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

using namespace shadowlab;
using shadowlab::test::GLTest;

namespace fs = std::filesystem;

namespace {

struct Frames {
    ImageRGBA8 grouped, perLight;
    FrameStats groupedStats, perLightStats;
};

Frames renderBoth(const Scene& scene, int width, int height) {
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.clock = TimingClock::CpuFinish;
    Frames f;
    f.groupedStats = renderer.render(scene, options);
    f.grouped = renderer.readColor();
    options.groupLights = false;
    f.perLightStats = renderer.render(scene, options);
    f.perLight = renderer.readColor();
    return f;
}

bool hasPass(const FrameStats& stats, const std::string& name) {
    return std::any_of(stats.passes.begin(), stats.passes.end(), [&](const PassTiming& p) { return p.name == name; });
}

// Per channel: the largest difference and the share of channels that differ by more than `by`.
struct Difference {
    int largest = 0;
    double over = 0.0;
};
Difference difference(const ImageRGBA8& a, const ImageRGBA8& b, int by) {
    Difference d;
    std::size_t over = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const int delta = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        d.largest = std::max(d.largest, delta);
        over += delta > by ? 1 : 0;
    }
    d.over = double(over) / double(a.pixels.size());
    return d;
}

} // namespace

class LightListGLTest : public GLTest {};

// The bundled hall with 64 lights, unshadowed (63 in the list, the first in the base
// pass): the one pass gives the frame of a pass per light up to rounding.
// A pass per light rounds the sum to 8-bit sRGB after each light, the list
// once, so a pixel under k lights may differ by up to about k/2 levels;
// measured here: at most 2 levels, no channel by more than 2. A light the
// list left out of a tile where it reaches shows: with the spots' bounding
// spheres shrunk to 0.7 of their radius (their faint outer rims lost) the
// largest difference is 13 levels.
TEST_F(LightListGLTest, ManyLightsInOnePassMatchAPassEach) {
    const Scene scene = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "many-lights.json", {"lightGrid.light.shadow.technique=none"});
    ASSERT_EQ(scene.lights.size(), 64u);
    const Frames f = renderBoth(scene, 400, 300);
    EXPECT_TRUE(hasPass(f.groupedStats, "lights"));
    EXPECT_FALSE(hasPass(f.groupedStats, "light[1]"));
    EXPECT_TRUE(hasPass(f.perLightStats, "light[63]"));
    EXPECT_FALSE(hasPass(f.perLightStats, "lights"));
    const Difference d = difference(f.grouped, f.perLight, 2);
    EXPECT_LE(d.largest, 3);
    EXPECT_LE(d.over, 0.0001);
}
