// Camera and node transforms: the math every pass and the reference share.
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
