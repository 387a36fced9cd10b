// Camera and node transforms: the math every pass and the reference share.
#include <shadowlab/Error.h>
#include <shadowlab/Scene.h>

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

using namespace shadowlab;

namespace {
glm::vec3 project(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}
} // namespace

TEST(Camera, TargetProjectsToTheImageCentre) {
    Camera cam;
    cam.position = {3, 4, 5};
    cam.target = {-1, 0.5f, 2};
    const glm::mat4 clipFromWorld = cam.clipFromView(16.0f / 9.0f) * cam.viewFromWorld();
    const glm::vec3 ndc = project(clipFromWorld, cam.target);
    EXPECT_NEAR(ndc.x, 0.0f, 1e-5f);
    EXPECT_NEAR(ndc.y, 0.0f, 1e-5f);
}

TEST(Camera, NearAndFarMapToTheDepthRangeEnds) {
    Camera cam;  // at (0,4,10) looking at the origin
    const glm::vec3 forward = glm::normalize(cam.target - cam.position);
    const glm::mat4 m = cam.clipFromView(1.0f) * cam.viewFromWorld();
    EXPECT_NEAR(project(m, cam.position + forward * cam.nearPlane).z, -1.0f, 1e-4f);
    EXPECT_NEAR(project(m, cam.position + forward * cam.farPlane).z, 1.0f, 1e-4f);
}

TEST(Camera, VerticalFieldOfViewSpansTheImageHeight) {
    Camera cam;
    cam.position = {0, 0, 0};
    cam.target = {0, 0, -1};
    cam.fovYDeg = 60.0f;
    const glm::mat4 m = cam.clipFromView(2.0f) * cam.viewFromWorld();
    // A point 30 degrees above the axis lies on the top edge; x scales by the aspect.
    EXPECT_NEAR(project(m, {0, std::tan(glm::radians(30.0f)), -1}).y, 1.0f, 1e-5f);
    EXPECT_NEAR(project(m, {2.0f * std::tan(glm::radians(30.0f)), 0, -1}).x, 1.0f, 1e-5f);
    EXPECT_GT(project(m, {-1, 0, -5}).x, -1.0f);  // left of the axis is negative x
    EXPECT_LT(project(m, {-1, 0, -5}).x, 0.0f);
}

TEST(Node, TransformIsTranslationRotationScale) {
    Node n;
    n.translation = {1, 2, 3};
    n.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    n.scale = {2, 2, 2};
    // (1,0,0) scaled to (2,0,0), turned 90 degrees about Y to (0,0,-2), moved by (1,2,3).
    const glm::vec3 p = glm::vec3(n.parentFromLocal() * glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(p, glm::vec3(1, 2, 1)), 0.0f, 1e-5f);
}

TEST(Scene, EmptySceneHasInfiniteEmptyBounds) {
    const Scene s;
    const auto [lo, hi] = s.worldBounds();
    EXPECT_GT(lo.x, hi.x);
}

TEST(Camera, InfiniteFarIsTheLimitOfFarPlanes) {
    Camera cam;
    const glm::vec3 forward = glm::normalize(cam.target - cam.position);
    const glm::mat4 infinite = cam.clipFromViewInfiniteFar(1.5f) * cam.viewFromWorld();
    // The near plane still maps to depth -1 (NDC), and nothing finite reaches +1.
    EXPECT_NEAR(project(infinite, cam.position + cam.nearPlane * forward).z, -1.0f, 1e-5f);
    const glm::vec4 far = infinite * glm::vec4(cam.position + 1e6f * forward, 1.0f);
    EXPECT_LT(far.z / far.w, 1.0f);
    // Points at infinity (w = 0 directions) land exactly on depth 1.
    const glm::vec4 atInfinity = infinite * glm::vec4(forward, 0.0f);
    EXPECT_NEAR(atInfinity.z / atInfinity.w, 1.0f, 1e-6f);
    // A large finite far plane gives almost the same matrix.
    cam.farPlane = 1e7f;
    const glm::mat4 big = cam.clipFromView(1.5f), inf = cam.clipFromViewInfiniteFar(1.5f);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(big[c][r], inf[c][r], 1e-6f) << c << "," << r;
}

TEST(Camera, FromASpotLightLooksAlongItsAxisThroughItsCone) {
    Scene scene;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1, 5, 2};
    spot.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.1f));
    spot.outerConeDeg = 25.0f;
    const Camera cam = cameraFromLight(scene, spot);
    EXPECT_EQ(cam.position, spot.position);
    EXPECT_NEAR(glm::length(glm::normalize(cam.target - cam.position) - spot.direction), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(cam.fovYDeg, 50.0f);
    Light point;
    point.type = LightType::Point;
    EXPECT_THROW(cameraFromLight(scene, point), Error);
}
