// Soft shadows against the area-light reference (lights with a `size`):
// PCSS (technique "map", filter "pcss") on the lecture scenes made soft,
// and its penumbra growing with the distance from occluder to receiver.
#include "Comparisons.h"
#include "GLTestContext.h"

#include <shadowlab/Compare.h>
#include <shadowlab/SceneFile.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace shadowlab;
using shadowlab::test::compareScene;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

// A point light of radius 0.5 at height 6 over the ground, a large sheet
// whose edge runs along z over x = 0 at height h: the penumbra on the
// ground is R h / (6 - h) to each side of x = 0 (similar triangles).
Scene edgeScene(float h, const std::string& filter) {
    const std::string height = std::to_string(h);
    return parseScene(R"({
      "camera": {"position": [8, 7, 0], "target": [0, 0, 0], "fovY": 30},
      "lights": [{"name": "lamp", "type": "point", "position": [0, 6, 0], "size": 0.5,
                  "shadow": {"technique": "map", "map": {"filter": ")" + filter + R"("}}}],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [30, 30]}},
        {"name": "sheet", "shape": {"type": "box", "size": [8, 0.02, 16]}, "translation": [-4, )" + height + R"(, 0], "receivesShadows": false}
      ]
    })", "edge", ".");
}

// Along the image's centre column (the plane z = 0), the ground's x where
// the visibility first rises through `level` coming from the shadowed side
// (smallest x), linearly between pixels.
float crossing(const Comparison& c, const ImageGray16& visibility, float level) {
    const SurfaceBuffer& s = c.surfaces;
    const int x = s.width / 2;
    float bestX = 1e9f;
    for (int y = 0; y + 1 < s.height; ++y) {
        const std::size_t i = static_cast<std::size_t>(y) * s.width + x, j = i + s.width;
        if (s.position[i].w < 0.5f || s.position[j].w < 0.5f || std::fabs(s.position[i].y) > 1e-3f || std::fabs(s.position[j].y) > 1e-3f) continue;
        const float a = visibility.pixels[i] / 65535.0f, b = visibility.pixels[j] / 65535.0f;
        if ((a - level) * (b - level) > 0.0f || a == b) continue;
        const float t = (level - a) / (b - a);
        bestX = std::min(bestX, s.position[i].x + t * (s.position[j].x - s.position[i].x));
    }
    return bestX;
}

float penumbraWidth(const Comparison& c, const ImageGray16& visibility) {
    return crossing(c, visibility, 0.9f) - crossing(c, visibility, 0.1f);
}

} // namespace

class SoftShadowGLTest : public GLTest {};

// The issue's bar: RMSE at most 0.05 against the 1024-sample reference on
// every lecture scene made soft (spot and point lights of radius 0.3,
// directional ones 2 degrees across); measured 0.010 to 0.028. And always
// closer than the hard map (filter "hardware", measured 0.018 to 0.12) to
// the soft truth (that one against 256 samples: it only has to lose).
TEST_F(SoftShadowGLTest, PcssMatchesTheAreaLightReferenceOnTheLectureScenes) {
    for (const char* name : {"torus-pyramid.json", "torus-floating.json", "room-point.json", "spheres-sun.json", "spot-objects.json",
                             "slide-projector.json"}) {
        SCOPED_TRACE(name);
        const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / name;
        const Scene plain = loadSceneFile(path);
        const std::string size = plain.lights[0].type == LightType::Directional ? "2" : "0.3";
        const std::vector<std::string> soft = {"lights[0].size=" + size, "lights[0].shadow.technique=\"map\""};
        std::vector<std::string> pcss = soft;
        pcss.push_back("lights[0].shadow.map.filter=\"pcss\"");
        const Comparison withPcss = compareScene(loadSceneFile(path, pcss), 480, 270, 1024);
        const Comparison hard = compareScene(loadSceneFile(path, soft), 480, 270, 256);
        ASSERT_TRUE(withPcss.lights[0].soft);
        EXPECT_LE(withPcss.lights[0].rmse, 0.05);
        EXPECT_LT(withPcss.lights[0].rmse, hard.lights[0].rmse);
    }
}

// The issue's large light: torus-floating's sun 3 degrees across, and
// point lights of radius 1 and 2, a third and two thirds of their height
// (measured 0.016, 0.020 and 0.031; radius 3: 0.046, docs/techniques/pcss.md).
// Before the blocker search was bounded by the nearest caster (it reached
// three radii), radius 1.5 and more missed the bar (0.065 to 0.084).
TEST_F(SoftShadowGLTest, PcssMatchesTheAreaLightReferenceForALargeLight) {
    const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "torus-floating.json";
    for (const std::string& light : {std::string("lights[0].size=3"), std::string(R"(lights[0]={"type":"point","position":[2,6,1.5],"size":1})"),
                                     std::string(R"(lights[0]={"type":"point","position":[2,6,1.5],"size":2})")}) {
        SCOPED_TRACE(light);
        const Comparison c = compareScene(
            loadSceneFile(path, {light, "lights[0].shadow.technique=\"map\"", "lights[0].shadow.map.filter=\"pcss\""}), 480, 270, 1024);
        ASSERT_TRUE(c.lights[0].soft);
        EXPECT_LE(c.lights[0].rmse, 0.05);
    }
}

// The penumbra widens as the occluder rises from the receiver (h = 1, 2,
// 3: true half widths 0.1, 0.25, 0.5), in the reference and in PCSS; PCSS
// within a quarter of the reference's width (measured within 7 %), where
// a hard map stays under a twentieth of a unit at every height.
TEST_F(SoftShadowGLTest, PcssPenumbraGrowsWithTheOccluderToReceiverDistance) {
    float previousReference = 0.0f, previousPcss = 0.0f;
    for (float h : {1.0f, 2.0f, 3.0f}) {
        SCOPED_TRACE("occluder at height " + std::to_string(h));
        const Comparison c = compareScene(edgeScene(h, "pcss"), 480, 480, 1024);
        const float reference = penumbraWidth(c, c.lights[0].referenceVisibility);
        const float pcss = penumbraWidth(c, c.lights[0].techniqueVisibility);
        ASSERT_LT(reference, 100.0f) << "the penumbra must be in view";
        ASSERT_LT(pcss, 100.0f) << "the penumbra must be in view";
        EXPECT_GT(reference, previousReference);
        EXPECT_GT(pcss, previousPcss);
        EXPECT_NEAR(pcss, reference, 0.25f * reference);
        previousReference = reference;
        previousPcss = pcss;
        // A hard map's edge is its bilinear compare's one texel, whatever the
        // height (measured 0.014 units at all three): under 0.05, a third of
        // the narrowest true penumbra here.
        const Comparison hard = compareScene(edgeScene(h, "hardware"), 480, 480, 64);
        EXPECT_LT(penumbraWidth(hard, hard.lights[0].techniqueVisibility), 0.05f);
    }
}

// Filterable maps on the light-leak scene (an upper plate shadowing the edge
// of a lower one: the blur mixes their two depths over the ground, where
// Chebyshev's bound lets light through). Leaked light: the technique's mean
// visibility over the reference's umbra away from edges. VSM leaks (measured at 960x540:
// 0.07 % with blur 2, 0.4 % with blur 6 at 1024^2); EVSM4 and MSM leak less
// (measured 0 and 0.004 %, 0.1 % and 0.09 %).
TEST_F(SoftShadowGLTest, Evsm4AndMsmLeakLessThanVsm) {
    const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "light-leak.json";
    for (int blur : {2, 6}) {
        SCOPED_TRACE("blur " + std::to_string(blur));
        auto leak = [&](const std::string& representation) {
            const Scene scene = loadSceneFile(path, {"lights[0].shadow.map.representation=\"" + representation + "\"",
                                                     "lights[0].shadow.map.blur=" + std::to_string(blur), "lights[0].shadow.map.size=1024"});
            const LightComparison l = compareScene(scene, 480, 270, 1).lights[0];
            EXPECT_GT(l.umbraPixels, 5000u) << "the umbra must be in view";
            return l.leakedInUmbra;
        };
        const double vsm = leak("vsm"), evsm4 = leak("evsm4"), msm = leak("msm");
        EXPECT_GT(vsm, 1e-4) << "the scene must make VSM leak";
        EXPECT_LT(evsm4, vsm);
        EXPECT_LT(msm, vsm);
        EXPECT_EQ(leak("depth"), 0.0) << "a depth map compares, it cannot leak";
    }
}

// Every representation shadows like the depth map away from edges on a
// hard scene (at most 0.05 % misclassified outside the 1-pixel band, the
// shadow-map issue's bar), in 32- and 16-bit moments.
TEST_F(SoftShadowGLTest, MomentMapsClassifyLikeDepthMapsAwayFromEdges) {
    const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "spheres-sun.json";
    for (const char* representation : {"vsm", "evsm2", "evsm4", "msm"})
        for (const char* format : {"rgba32f", "rgba16f"}) {
            SCOPED_TRACE(std::string(representation) + " " + format);
            const Scene scene = loadSceneFile(path, {"lights[0].shadow.technique=\"map\"",
                                                     std::string("lights[0].shadow.map.representation=\"") + representation + "\"",
                                                     std::string("lights[0].shadow.map.momentFormat=\"") + format + "\""});
            const LightComparison l = compareScene(scene, 480, 270, 1).lights[0];
            EXPECT_LE(l.falseLitAwayFromEdges + l.falseShadowAwayFromEdges, 0.0005);
        }
}

// Moments with no blur, no mipmaps and 32-bit floats are taken from the
// depth by the light pass (map/passes/Arrays.h: momentsFromDepth), so such a map
// holds its depth alone (bench's mapBytes: 4 bytes a texel); 16-bit or
// blurred moments are made and stored beside it. The two tests above hold
// both kinds to the reference (32-bit unblurred, 16-bit, and blurred).
TEST_F(SoftShadowGLTest, MomentsTakenFromTheDepthTakeNoMemoryOfTheirOwn) {
    const fs::path path = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "light-leak.json";
    const double texels = 1024.0 * 1024.0;
    auto bytes = [&](const std::string& representation, const std::string& more) {
        std::vector<std::string> set = {"lights[0].shadow.map.size=1024", "lights[0].shadow.map.representation=\"" + representation + "\""};
        if (!more.empty()) set.push_back(more);
        const Scene scene = loadSceneFile(path, set);
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        double b = -1.0;
        for (const auto& [name, value] : renderer.render(scene, RenderOptions{64, 48}).counters)
            if (name == "shadow[0].mapBytes") b = value;
        return b;
    };
    for (const auto& [representation, moments] : {std::pair{"vsm", 2.0}, std::pair{"evsm4", 4.0}, std::pair{"msm", 4.0}}) {
        SCOPED_TRACE(representation);
        EXPECT_EQ(bytes(representation, ""), 4.0 * texels);
        EXPECT_EQ(bytes(representation, "lights[0].shadow.map.momentFormat=\"rgba16f\""), (4.0 + 2.0 * moments) * texels);
        EXPECT_EQ(bytes(representation, "lights[0].shadow.map.blur=2"), (4.0 + 4.0 * moments) * texels);
    }
}
