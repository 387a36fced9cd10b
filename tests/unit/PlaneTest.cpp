// Planar meshes and which casters a shadow map must draw (geometry/Plane.h,
// castersThatMatter in geometry/LightCamera.h).
#include "geometry/LightCamera.h"
#include "geometry/Plane.h"

#include <shadowlab/Shapes.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace shadowlab;

TEST(PlaneTest, APlaneShapeIsPlanarABoxAndASphereAreNot) {
    const auto floor = meshPlane(shapes::plane(4.0f, 4.0f));
    ASSERT_TRUE(floor.has_value());
    EXPECT_NEAR(std::abs(floor->y), 1.0f, 1e-6f);  // y = 0
    EXPECT_NEAR(floor->w, 0.0f, 1e-6f);
    EXPECT_FALSE(meshPlane(shapes::box(glm::vec3(1.0f))).has_value());
    EXPECT_FALSE(meshPlane(shapes::sphere(1.0f)).has_value());
    Mesh degenerate;
    degenerate.positions = {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f)};
    degenerate.indices = {0, 1, 2};
    EXPECT_FALSE(meshPlane(degenerate).has_value()) << "no triangle of non-zero area";
    EXPECT_FALSE(meshPlane(Mesh{}).has_value());
}

TEST(PlaneTest, APlaneMovesWithItsTransform) {
    // The floor (y = 0) turned 90 degrees about z and moved to x = 3: the plane x = 3.
    const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 0.0f, 0.0f)), glm::radians(90.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::vec4 p = transformPlane(glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), m);
    EXPECT_NEAR(std::abs(p.x), 1.0f, 1e-5f);
    EXPECT_NEAR(p.x * 3.0f + p.w, 0.0f, 1e-5f);
}

TEST(PlaneTest, OnlyWhatLiesBehindThePlaneFromTheLightCanBeShadowedByIt) {
    const glm::vec4 floor(0.0f, 1.0f, 0.0f, 0.0f);
    Bounds above, straddling, below;
    above.add(glm::vec3(-1.0f, 0.0f, -1.0f));  // resting on the floor
    above.add(glm::vec3(1.0f, 2.0f, 1.0f));
    straddling.add(glm::vec3(-1.0f, -0.5f, -1.0f));
    straddling.add(glm::vec3(1.0f, 0.5f, 1.0f));
    below.add(glm::vec3(-1.0f, -3.0f, -1.0f));
    below.add(glm::vec3(1.0f, -2.0f, 1.0f));
    const glm::vec4 sun(0.3f, 1.0f, 0.2f, 0.0f);  // towards a light above
    EXPECT_FALSE(reachesBehind(floor, sun, above, 1e-4f));
    EXPECT_TRUE(reachesBehind(floor, sun, straddling, 1e-4f));
    EXPECT_TRUE(reachesBehind(floor, sun, below, 1e-4f));
    // A light below the floor: the sides swap (the plane's orientation does not matter).
    const glm::vec4 lamp(0.0f, -5.0f, 0.0f, 1.0f);
    EXPECT_TRUE(reachesBehind(floor, lamp, above, 1e-4f));
    EXPECT_TRUE(reachesBehind(-floor, lamp, above, 1e-4f));
    EXPECT_FALSE(reachesBehind(floor, lamp, below, 1e-4f));
}

TEST(PlaneTest, AFloorUnderEverythingIsNotACasterButOneOverSomethingVisibleIs) {
    // Items: 0 a floor at y = 0, 1 a box resting on it, 2 a box under it.
    std::vector<DrawItem> items(3);
    for (int i = 0; i < 3; ++i) items[static_cast<std::size_t>(i)].mesh = i;
    std::vector<Bounds> bounds(3);
    bounds[0].add(glm::vec3(-10.0f, 0.0f, -10.0f));
    bounds[0].add(glm::vec3(10.0f, 0.0f, 10.0f));
    bounds[1].add(glm::vec3(-1.0f, 0.0f, -1.0f));
    bounds[1].add(glm::vec3(1.0f, 2.0f, 1.0f));
    bounds[2].add(glm::vec3(-1.0f, -3.0f, -1.0f));
    bounds[2].add(glm::vec3(1.0f, -1.0f, 1.0f));
    std::vector<std::optional<glm::vec4>> planes = {glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), std::nullopt, std::nullopt};
    const std::vector<std::vector<glm::vec4>> noConvex(3);
    // A camera that sees everything.
    const glm::mat4 camera = glm::ortho(-20.0f, 20.0f, -20.0f, 20.0f, -20.0f, 20.0f);
    const glm::vec3 direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    const glm::mat4 lightView = glm::lookAt(-10.0f * direction, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));

    items[2].receivesShadows = false;  // the box below receives nothing: the floor shadows nothing visible
    std::vector<std::uint8_t> casts = castersThatMatter(glm::vec4(-direction, 0.0f), lightView, FitInput{bounds, items, planes, noConvex, camera});
    EXPECT_EQ(casts, (std::vector<std::uint8_t>{0, 1, 1}));

    items[2].receivesShadows = true;   // now the floor shadows it
    casts = castersThatMatter(glm::vec4(-direction, 0.0f), lightView, FitInput{bounds, items, planes, noConvex, camera});
    EXPECT_EQ(casts, (std::vector<std::uint8_t>{1, 1, 1}));

    // The same from a spot light above.
    casts = castersThatMatter(glm::vec4(0.0f, 8.0f, 0.0f, 1.0f), lightView, FitInput{bounds, items, planes, noConvex, camera});
    EXPECT_EQ(casts, (std::vector<std::uint8_t>{1, 1, 1}));
    items[2].receivesShadows = false;
    casts = castersThatMatter(glm::vec4(0.0f, 8.0f, 0.0f, 1.0f), lightView, FitInput{bounds, items, planes, noConvex, camera});
    EXPECT_EQ(casts, (std::vector<std::uint8_t>{0, 1, 1}));
}

TEST(PlaneTest, ABoxIsConvexATorusIsNot) {
    const std::vector<glm::vec4> box = convexPlanes(shapes::box(glm::vec3(2.0f)));
    ASSERT_EQ(box.size(), 6u);
    for (const glm::vec4& p : box) EXPECT_NEAR(p.w, -1.0f, 1e-5f) << "unit cube half-size 1: every face at distance 1, normal outwards";
    EXPECT_TRUE(strictlyInside(box, glm::vec3(0.5f, -0.5f, 0.9f), 1e-4f));
    EXPECT_FALSE(strictlyInside(box, glm::vec3(0.5f, -0.5f, 1.0f), 1e-4f)) << "on a face is not strictly inside";
    Bounds resting;  // touching the floor of the box
    resting.add(glm::vec3(-0.2f, -1.0f, -0.2f));
    resting.add(glm::vec3(0.2f, -0.6f, 0.2f));
    EXPECT_TRUE(boxInside(box, resting, 1e-4f));
    resting.add(glm::vec3(0.0f, 1.5f, 0.0f));
    EXPECT_FALSE(boxInside(box, resting, 1e-4f));
    EXPECT_TRUE(convexPlanes(shapes::torus(1.0f, 0.3f, 24, 12)).empty());
    EXPECT_TRUE(convexPlanes(shapes::plane(1.0f, 1.0f)).empty()) << "planar meshes have their own rule";
    EXPECT_TRUE(convexPlanes(shapes::sphere(1.0f, 48, 24), 100).empty()) << "past maxTriangles: not checked";
}

TEST(PlaneTest, ARoomAroundALightCastsNothingOnWhatIsInsideIt) {
    // Items: 0 a room (convex box of half-size 5), 1 a crate inside it.
    std::vector<DrawItem> items(2);
    std::vector<Bounds> bounds(2);
    bounds[0].add(glm::vec3(-5.0f));
    bounds[0].add(glm::vec3(5.0f));
    bounds[1].add(glm::vec3(-1.0f, -5.0f, -1.0f));
    bounds[1].add(glm::vec3(1.0f, -4.0f, 1.0f));
    const std::vector<std::optional<glm::vec4>> planes(2);
    std::vector<std::vector<glm::vec4>> convex(2);
    for (const glm::vec4& p : convexPlanes(shapes::box(glm::vec3(10.0f)))) convex[0].push_back(p);
    const glm::mat4 camera = glm::ortho(-20.0f, 20.0f, -20.0f, 20.0f, -20.0f, 20.0f);
    const glm::vec4 lamp(0.0f, 2.0f, 1.0f, 1.0f);
    EXPECT_EQ(castersThatMatter(lamp, glm::mat4(1.0f), FitInput{bounds, items, planes, convex, camera}), (std::vector<std::uint8_t>{0, 1}));
    // The crate pokes through the wall: the room may now shadow its outer part.
    bounds[1].add(glm::vec3(6.0f, -4.0f, 0.0f));
    EXPECT_EQ(castersThatMatter(lamp, glm::mat4(1.0f), FitInput{bounds, items, planes, convex, camera}), (std::vector<std::uint8_t>{1, 1}));
    // A lamp outside the room: the room is an ordinary caster.
    bounds[1] = Bounds{};
    bounds[1].add(glm::vec3(-1.0f, -5.0f, -1.0f));
    bounds[1].add(glm::vec3(1.0f, -4.0f, 1.0f));
    EXPECT_EQ(castersThatMatter(glm::vec4(0.0f, 9.0f, 0.0f, 1.0f), glm::mat4(1.0f), FitInput{bounds, items, planes, convex, camera}),
              (std::vector<std::uint8_t>{1, 1}));
}
