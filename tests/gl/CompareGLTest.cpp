// compareWithReference on the headless context: the reference agrees with
// the exact analytic shadow, and the metrics count what they say.
#include "GLTestContext.h"

#include "core/AnalyticShadow.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

using namespace shadowlab;
using shadowlab::test::GLTest;

namespace {

// A unit sphere 2 m above a large plane, a tilted sun, a camera looking down
// at the shadow. 128x64 segments: the mesh silhouette deviates from the true
// sphere by at most r(1 - cos(pi/64)) = 1.2e-3 m, under a tenth of a pixel's
// footprint on the ground here (~0.02 m), so the mesh's shadow equals the
// analytic ellipse except within the edge band.
const glm::vec3 kSphereCentre(0.0f, 2.0f, 0.0f);
const glm::vec3 kSun = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));

Scene sphereOverPlane() {
    return parseScene(R"({
      "camera": {"position": [3, 7, 6], "target": [0.6, 0, 0.4], "fovY": 45},
      "lights": [{"name": "sun", "type": "directional", "direction": [0.4, -1.0, 0.3]}],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [40, 40]}},
        {"name": "ball", "shape": {"type": "sphere", "radius": 1, "segments": 128, "rings": 64}, "translation": [0, 2, 0],
         "receivesShadows": false}
      ]
    })", "sphere-over-plane", ".");
}

// Uploads the scene and compares it at `width` x `height`.
Comparison compareAt(Renderer& renderer, const Scene& scene, int width, int height) {
    renderer.upload(scene);
    CompareOptions options;
    options.width = width;
    options.height = height;
    return compareWithReference(renderer, scene, options);
}

} // namespace

class CompareGLTest : public GLTest {};

TEST_F(CompareGLTest, ReferenceMatchesTheAnalyticEllipseAwayFromEdges) {
    const Scene scene = sphereOverPlane();
    Renderer renderer(test::glContext());
    const Comparison c = compareAt(renderer, scene, 480, 270);
    const SurfaceBuffer s = renderer.readSurfaces();  // the same camera and size
    const int w = s.width, h = s.height;
    const auto& vis = c.lights.at(0).referenceVisibility.pixels;

    // Ground pixels (y ~ 0) and their analytic class.
    std::vector<int> truth(static_cast<std::size_t>(w) * h, -1);  // -1 not ground, 0 shadow, 1 lit
    for (std::size_t i = 0; i < truth.size(); ++i)
        if (s.position[i].w > 0.5f && std::fabs(s.position[i].y) < 1e-4f)
            truth[i] = inSphereShadowOnGround(glm::vec3(s.position[i]), kSphereCentre, 1.0f, kSun) ? 0 : 1;
    std::size_t compared = 0, agree = 0, shadowed = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (truth[i] < 0) continue;
            bool edge = false;  // an 8-neighbour ground pixel of the other analytic class
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const int t = truth[static_cast<std::size_t>(ny) * w + nx];
                    edge = edge || (t >= 0 && t != truth[i]);
                }
            if (edge) continue;
            ++compared;
            shadowed += truth[i] == 0;
            agree += (vis[i] >= 32768) == (truth[i] == 1);
        }
    ASSERT_GT(compared, 50000u);
    ASSERT_GT(shadowed, 2000u);  // the shadow is in view, so the check means something
    // Acceptance: >= 99.9 % agreement away from the 1-pixel band.
    EXPECT_GE(static_cast<double>(agree) / static_cast<double>(compared), 0.999)
        << agree << " of " << compared << " ground pixels agree";
}

TEST_F(CompareGLTest, UnshadowedTechniqueIsAllFalseLitAndNeverFalseShadow) {
    const Scene scene = sphereOverPlane();
    Renderer renderer(test::glContext());
    const Comparison c = compareAt(renderer, scene, 320, 180);
    ASSERT_EQ(c.lights.size(), 1u);
    const LightComparison& l = c.lights[0];
    EXPECT_GT(l.receiverPixels, 30000u);
    EXPECT_GT(l.referenceShadowedPixels, 1000u);
    // "none" says visibility 1 everywhere: every truly shadowed receiver is
    // false lit, nothing is false shadow, and the visibility error is exactly that.
    EXPECT_EQ(l.falseShadow, 0.0);
    EXPECT_DOUBLE_EQ(l.falseLit, double(l.referenceShadowedPixels) / double(l.receiverPixels));
    EXPECT_NEAR(l.meanAbsError, l.falseLit, 1e-9);  // |1 - 0| on exactly those pixels (hard light)
    EXPECT_NEAR(l.rmse, std::sqrt(l.falseLit), 1e-9);
    EXPECT_GT(l.falseLitAwayFromEdges, 0.0);
    EXPECT_LT(l.falseLitAwayFromEdges, l.falseLit);  // the band removes some of them
    // The images: same size, and the reference is darker where the shadow is.
    EXPECT_EQ(c.technique.width, 320);
    EXPECT_EQ(c.reference.pixels.size(), c.technique.pixels.size());
    // Full red marks false lit away from edges (pale red inside the band).
    std::size_t red = 0;
    for (std::size_t i = 0; i < l.errorImage.pixels.size(); i += 4)
        red += l.errorImage.pixels[i] == 235 && l.errorImage.pixels[i + 1] == 40;
    EXPECT_EQ(red, static_cast<std::size_t>(std::lround(l.falseLitAwayFromEdges * double(l.receiverPixels - l.edgePixels))));
}

TEST_F(CompareGLTest, ReferenceImageUsesExactVisibility) {
    const Scene scene = sphereOverPlane();
    Renderer renderer(test::glContext());
    const Comparison c = compareAt(renderer, scene, 160, 90);
    const auto& vis = c.lights[0].referenceVisibility.pixels;
    const SurfaceBuffer s = renderer.readSurfaces();
    // Where the reference says the ground is shadowed, the reference image has
    // ambient-only shading, darker than the technique image (no shadows).
    std::size_t darker = 0, shadowedPixels = 0;
    for (std::size_t i = 0; i < vis.size(); ++i) {
        const bool ground = s.position[i].w > 0.5f && std::fabs(s.position[i].y) < 1e-4f;
        if (vis[i] != 0 || !ground) continue;
        ++shadowedPixels;
        darker += c.reference.pixels[i * 4] + 20 < c.technique.pixels[i * 4];
    }
    ASSERT_GT(shadowedPixels, 100u);
    EXPECT_EQ(darker, shadowedPixels);
}

TEST_F(CompareGLTest, BadOptionsAreErrors) {
    const Scene scene = sphereOverPlane();
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    CompareOptions options;
    options.softSamples = 0;
    EXPECT_THROW(compareWithReference(renderer, scene, options), Error);
}
