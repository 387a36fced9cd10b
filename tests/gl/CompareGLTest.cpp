// compareWithReference on the headless context: the reference agrees with
// the exact analytic shadow, and the metrics count what they say.
#include "GLTestContext.h"
#include "ImageArtifacts.h"

#include "core/AnalyticShadow.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include <thread>

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

// `extraNodes`: more JSON node objects, each with a leading comma.
Scene sphereOverPlane(const std::string& extraNodes = "") {
    return parseScene(R"({
      "camera": {"position": [3, 7, 6], "target": [0.6, 0, 0.4], "fovY": 45},
      "lights": [{"name": "sun", "type": "directional", "direction": [0.4, -1.0, 0.3], "shadow": {"technique": "none"}}],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [40, 40]}},
        {"name": "ball", "shape": {"type": "sphere", "radius": 1, "segments": 128, "rings": 64}, "translation": [0, 2, 0],
         "receivesShadows": false})" + extraNodes + R"(
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
    const SurfaceBuffer& s = c.surfaces;  // the same camera and size
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
    // The expected red pixels are counted independently of Compare.cpp's
    // classification and colouring: receivers from the base pass (geometry
    // that receives shadows and faces the sun; a directional light reaches
    // everything), true shadow from the ray-traced visibility image, and
    // "none" lights every pixel, so its false-lit pixels are exactly the truly
    // shadowed receivers; those outside the edge band are drawn full red.
    const SurfaceBuffer& s = c.surfaces;
    const int w = s.width, h = s.height;
    const std::size_t n = static_cast<std::size_t>(w) * h;
    std::vector<std::uint8_t> receiver(n, 0), shadowed(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 normal(s.normal[i]);
        receiver[i] = s.position[i].w > 0.5f && s.normal[i].w >= 0.5f && glm::dot(normal, -kSun) > 0.0f;
        shadowed[i] = receiver[i] && l.referenceVisibility.pixels[i] < 32768;  // visibility < 0.5
    }
    std::vector<std::uint8_t> expectedRed(n, 0), actualRed(n, 0);
    std::size_t receivers = 0, expectedCount = 0, actualCount = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            actualRed[i] = l.errorImage.pixels[i * 4] == 235 && l.errorImage.pixels[i * 4 + 1] == 40 &&
                           l.errorImage.pixels[i * 4 + 2] == 30;
            actualCount += actualRed[i];
            if (!receiver[i]) continue;
            ++receivers;
            bool edge = false;  // an 8-neighbour receiver of the other true class
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
                    edge = edge || (receiver[j] && shadowed[j] != shadowed[i]);
                }
            expectedRed[i] = shadowed[i] && !edge;
            expectedCount += expectedRed[i];
        }
    EXPECT_EQ(receivers, l.receiverPixels);
    ASSERT_GT(expectedCount, 500u) << "the shadow away from its edge must be in view";
    EXPECT_EQ(actualCount, expectedCount);
    EXPECT_EQ(actualRed, expectedRed) << "red pixels are not where the independent count puts them";
    EXPECT_EQ(expectedCount,
              static_cast<std::size_t>(std::lround(l.falseLitAwayFromEdges * double(l.receiverPixels - l.edgePixels))));
    test::saveImagesIfFailed("red", test::maskToRgba(w, h, actualRed), test::maskToRgba(w, h, expectedRed));
}

// Issue 11: a 1 cm box 1000 units away used to change ~170 reference pixels
// (the ray offset grew with the scene's bounds). It casts no shadow here, so
// the reference visibility must not change at all.
TEST_F(CompareGLTest, FarAwayTinyBoxLeavesTheReferenceUnchanged) {
    Renderer renderer(test::glContext());
    const Comparison plain = compareAt(renderer, sphereOverPlane(), 320, 180);
    const Comparison withBox = compareAt(renderer, sphereOverPlane(R"(,
        {"name": "speck", "shape": {"type": "box", "size": [0.01, 0.01, 0.01]}, "translation": [1000, 1, -1000]})"),
                                         320, 180);
    const ImageGray16& expected = plain.lights.at(0).referenceVisibility;
    const ImageGray16& actual = withBox.lights.at(0).referenceVisibility;
    ASSERT_EQ(actual.pixels.size(), expected.pixels.size());
    std::size_t changed = 0, lit = 0;
    for (std::size_t i = 0; i < actual.pixels.size(); ++i) {
        changed += actual.pixels[i] != expected.pixels[i];
        lit += expected.pixels[i] == 65535;
    }
    ASSERT_GT(lit, 10000u);  // the comparison covers a lit scene, not an empty image
    EXPECT_EQ(changed, 0u) << "reference pixels changed by a far-away 1 cm box";
    test::saveImagesIfFailed("visibility", test::toRgba(actual), test::toRgba(expected));
}

// The reference starts its rays from the positions the rasterizer
// interpolated into an RGBA32F target. offsetRayOrigin() pushes them
// 2^-16 * max(|p_i|, 1) along the normal on top of the Wachter-Binder offset
// for the error of that interpolation: measured here on a large tilted plane
// far from the origin (no coordinate is exactly 0, the plane equation does
// not vanish), the positions must lie within that push of the exact plane.
TEST_F(CompareGLTest, RasterizedPositionsLieWithinTheOriginPush) {
    const Scene scene = parseScene(R"({
      "camera": {"position": [30, 40, 35], "target": [20, 3, 10], "fovY": 60},
      "lights": [{"name": "sun", "type": "directional", "direction": [0.4, -1.0, 0.3]}],
      "nodes": [{"name": "slope", "shape": {"type": "plane", "size": [80, 80]}, "translation": [20, 3, 10],
                 "rotation": [17, 0, 11]}]
    })", "tilted-plane", ".");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {480, 270, TimingClock::Off, true});
    const SurfaceBuffer s = renderer.readSurfaces();
    const glm::dmat4 worldFromObject(scene.drawItems().at(0).worldFromObject);
    const glm::dvec3 origin(worldFromObject * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 normal = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(worldFromObject))) * glm::dvec3(0, 1, 0));
    std::size_t pixels = 0;
    double worstShare = 0.0, worstUlps = 0.0;  // |distance| over the push, and in ulps of the largest coordinate
    for (const glm::vec4& p : s.position) {
        if (p.w < 0.5f) continue;
        ++pixels;
        const double distance = std::abs(glm::dot(glm::dvec3(glm::vec3(p)) - origin, normal));
        const double largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
        worstShare = std::max(worstShare, distance / (0x1.0p-16 * largest));
        worstUlps = std::max(worstUlps, distance / (0x1.0p-23 * largest));
    }
    ASSERT_GT(pixels, 100000u);
    // The push must cover the measured error, with room (a factor of 4) for
    // other GPUs and for the CPU's own rounding of the triangle Embree sees.
    EXPECT_LT(worstShare, 0.25) << "rasterized positions lie up to " << worstUlps << " ulps off their plane";
    std::cout << "[ info ] rasterized positions: at most " << worstUlps << " ulps of the largest coordinate off the plane ("
              << worstShare << " of the push) over " << pixels << " pixels\n";
}

// visibility-<i> is 0 both for shadowed and for unreached points; the reach
// mask tells them apart and marks exactly the receiver pixels.
TEST_F(CompareGLTest, ReachMaskSeparatesUnreachedFromShadowed) {
    const Scene scene = parseScene(R"({
      "camera": {"position": [4, 9, 8], "target": [0, 0, 0], "fovY": 50},
      "lights": [{"name": "spot", "type": "spot", "position": [0, 6, 0], "direction": [0.2, -1, 0], "outerCone": 30}],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [40, 40]}},
        {"name": "ball", "shape": {"type": "sphere", "radius": 1}, "translation": [0.5, 2, 0], "receivesShadows": false}
      ]
    })", "spot-over-plane", ".");
    Renderer renderer(test::glContext());
    const Comparison c = compareAt(renderer, scene, 320, 180);
    const LightComparison& l = c.lights.at(0);
    const SurfaceBuffer& s = c.surfaces;
    ASSERT_EQ(l.reach.pixels.size(), l.referenceVisibility.pixels.size());
    std::size_t reached = 0, shadowedReached = 0, unreachedGround = 0, litUnreachedGround = 0;
    for (std::size_t i = 0; i < l.reach.pixels.size(); ++i) {
        const bool ground = s.position[i].w > 0.5f && std::fabs(s.position[i].y) < 1e-4f;
        const std::uint16_t v = l.referenceVisibility.pixels[i];
        ASSERT_TRUE(l.reach.pixels[i] == 0 || l.reach.pixels[i] == 255);
        if (l.reach.pixels[i]) {
            ++reached;
            shadowedReached += v == 0;
        } else if (ground) {
            ++unreachedGround;  // outside the cone: the ground faces the light everywhere
            litUnreachedGround += v != 0;
        }
    }
    EXPECT_EQ(reached, l.receiverPixels);
    EXPECT_GT(shadowedReached, 500u) << "the ball's shadow inside the cone";
    EXPECT_GT(unreachedGround, 5000u) << "ground outside the cone";
    EXPECT_EQ(litUnreachedGround, 0u) << "unreached points are stored as 0, like shadowed ones";
    EXPECT_EQ(shadowedReached, l.referenceShadowedPixels);  // hard light: shadowed means visibility 0
}

TEST_F(CompareGLTest, ReferenceImageUsesExactVisibility) {
    const Scene scene = sphereOverPlane();
    Renderer renderer(test::glContext());
    const Comparison c = compareAt(renderer, scene, 160, 90);
    const auto& vis = c.lights[0].referenceVisibility.pixels;
    const SurfaceBuffer& s = c.surfaces;
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

// The viewer's path: the job traced on another thread while this one goes
// on (progress rising to 1) gives exactly compareWithReference's result; a
// cancelled job's trace() throws and finish() refuses.
TEST_F(CompareGLTest, JobTracedOnAnotherThreadMatchesTheOneCall) {
    const Scene scene = sphereOverPlane();
    Renderer renderer(test::glContext());
    const Comparison whole = compareAt(renderer, scene, 320, 180);

    CompareOptions options;
    options.width = 320;
    options.height = 180;
    ComparisonJob job(renderer, scene, options);
    EXPECT_EQ(job.progress(), 0.0);
    std::string failure;
    std::thread worker([&] {
        try {
            job.trace();
        } catch (const Error& e) {
            failure = e.what();
        }
    });
    worker.join();
    ASSERT_EQ(failure, "");
    EXPECT_EQ(job.progress(), 1.0);
    const Comparison split = job.finish(renderer);
    ASSERT_EQ(split.lights.size(), 1u);
    EXPECT_EQ(split.lights[0].receiverPixels, whole.lights[0].receiverPixels);
    EXPECT_EQ(split.lights[0].falseLit, whole.lights[0].falseLit);
    EXPECT_EQ(split.lights[0].referenceVisibility.pixels, whole.lights[0].referenceVisibility.pixels);
    EXPECT_EQ(split.lights[0].errorImage.pixels, whole.lights[0].errorImage.pixels);
    EXPECT_EQ(split.reference.pixels, whole.reference.pixels);

    ComparisonJob cancelled(renderer, scene, options);
    cancelled.cancel();
    EXPECT_THROW(cancelled.trace(), Error);
    EXPECT_LT(cancelled.progress(), 1.0);
    EXPECT_THROW(cancelled.finish(renderer), Error);
}
