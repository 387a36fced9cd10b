// Cascaded shadow maps' light cameras (core/LightCamera: cascadeSplits,
// fitCascade), GPU-free: where the slices split, that each cascade holds its
// slice, and that a stabilised cascade's texel grid stays put in the world
// while the camera moves and turns (the cause of shimmer when it does not).
#include "geometry/Cascades.h"
#include "geometry/LightCamera.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace shadowlab;

namespace {

// A field: a 400 m ground and a row of boxes along -z, all casting and receiving.
struct Field {
    std::vector<DrawItem> items;
    std::vector<Bounds> bounds;
    std::vector<std::optional<glm::vec4>> planes;
    std::vector<std::vector<glm::vec4>> convex;
    Field() {
        Bounds ground;
        ground.add(glm::vec3(-200.0f, 0.0f, -200.0f));
        ground.add(glm::vec3(200.0f, 0.0f, 200.0f));
        bounds.push_back(ground);
        planes.emplace_back(glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
        for (int i = 0; i < 40; ++i) {
            Bounds box;
            const float z = -2.0f - 4.5f * static_cast<float>(i), x = (i % 2 ? 3.0f : -3.0f);
            box.add(glm::vec3(x - 0.5f, 0.0f, z - 0.5f));
            box.add(glm::vec3(x + 0.5f, 2.0f, z + 0.5f));
            bounds.push_back(box);
            planes.emplace_back(std::nullopt);
        }
        items.resize(bounds.size());
        for (std::size_t i = 0; i < items.size(); ++i) items[i].mesh = static_cast<int>(i);
        convex.resize(bounds.size());
    }
    FitInput input(const Camera& camera, float aspect) const {
        return FitInput{bounds, items, planes, convex, camera.clipFromView(aspect) * camera.viewFromWorld(), 2048, 1.0f};
    }
};

Camera walker(glm::vec3 position, float yawDeg) {
    Camera c;
    c.position = position;
    const float yaw = glm::radians(yawDeg);
    c.target = position + glm::vec3(std::sin(yaw), -0.1f, -std::cos(yaw));
    c.fovYDeg = 50.0f;
    c.nearPlane = 0.1f;
    c.farPlane = 400.0f;
    return c;
}

const glm::vec3 kSun = glm::normalize(glm::vec3(0.6f, -0.45f, 0.5f));
constexpr float kAspect = 16.0f / 9.0f;

// The light-space box of an orthographic camera: [lo, hi] in x and y.
void box(const LightCamera& c, glm::vec2& lo, glm::vec2& hi) {
    const glm::mat4 viewFromClip = glm::inverse(c.clipFromView);
    lo = glm::vec2(viewFromClip * glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f));
    hi = glm::vec2(viewFromClip * glm::vec4(1.0f, 1.0f, 0.0f, 1.0f));
}

// The eight corners of the view slice [near, far].
std::vector<glm::vec3> sliceCorners(const Camera& c, float near, float far) {
    const glm::mat4 worldFromClip = glm::inverse(glm::perspective(glm::radians(c.fovYDeg), kAspect, near, far) * c.viewFromWorld());
    std::vector<glm::vec3> out;
    for (int k = 0; k < 8; ++k) {
        const glm::vec4 p = worldFromClip * glm::vec4(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f, 1.0f);
        out.push_back(glm::vec3(p) / p.w);
    }
    return out;
}

} // namespace

TEST(CascadeTest, SplitsFollowThePracticalSchemeOrTheGivenDistances) {
    // lambda 0: uniform; lambda 1: logarithmic (each slice the same ratio far / near).
    const std::vector<float> uniform = cascadeSplits(1.0f, 101.0f, 4, 0.0f);
    ASSERT_EQ(uniform.size(), 4u);
    EXPECT_NEAR(uniform[0], 26.0f, 1e-4f);
    EXPECT_NEAR(uniform[1], 51.0f, 1e-4f);
    EXPECT_NEAR(uniform[2], 76.0f, 1e-4f);
    EXPECT_EQ(uniform[3], 101.0f);
    const std::vector<float> log = cascadeSplits(0.1f, 1000.0f, 4, 1.0f);
    EXPECT_NEAR(log[0], 1.0f, 1e-5f);
    EXPECT_NEAR(log[1], 10.0f, 1e-4f);
    EXPECT_NEAR(log[2], 100.0f, 1e-3f);
    // The blend in between, and the given distances as given.
    const std::vector<float> mixed = cascadeSplits(0.1f, 1000.0f, 4, 0.75f);
    EXPECT_NEAR(mixed[0], 0.75f * 1.0f + 0.25f * (0.1f + 999.9f / 4.0f), 1e-3f);
    EXPECT_EQ(cascadeSplits(0.1f, 100.0f, 3, 0.5f, {4.0f, 20.0f}), (std::vector<float>{4.0f, 20.0f, 100.0f}));
    // Distances past the far end are pulled inside it: no slice is empty or reversed.
    const std::vector<float> pulled = cascadeSplits(0.1f, 10.0f, 3, 0.5f, {50.0f, 60.0f});
    EXPECT_LT(pulled[0], pulled[1]);
    EXPECT_LT(pulled[1], pulled[2]);
    EXPECT_EQ(pulled[2], 10.0f);
}

TEST(CascadeTest, EachCascadeHoldsItsSliceOfTheView) {
    const Field field;
    const Camera camera = walker(glm::vec3(0.0f, 1.8f, 5.0f), 10.0f);
    const std::vector<float> far = cascadeSplits(camera.nearPlane, camera.farPlane, 4, 0.75f);
    for (bool stabilize : {true, false}) {
        float previousTexel = 0.0f;
        for (std::size_t c = 0; c < far.size(); ++c) {
            SCOPED_TRACE(std::string(stabilize ? "stabilised" : "tight") + ", cascade " + std::to_string(c));
            const float near = c == 0 ? camera.nearPlane : far[c - 1];
            const LightCamera cam = fitCascade(kSun, camera, kAspect, near, far[c], stabilize, field.input(camera, kAspect));
            EXPECT_FALSE(cam.perspective);
            glm::vec2 lo, hi;
            box(cam, lo, hi);
            if (stabilize) {
                // On each axis of the light's view the window holds the
                // whole slice (the sphere), above the ground too, or every
                // receiver a caster can shadow: the receivers' box cut
                // across the light to the boxes' (the ground, a plane under
                // everything, shadows nothing; receiversWindow), where that
                // is the narrower.
                Bounds slice, receivers, casters;
                for (const glm::vec3& p : sliceCorners(camera, near, far[c])) slice.add(glm::vec3(cam.viewFromWorld * glm::vec4(p, 1.0f)));
                for (std::size_t i = 0; i < field.items.size(); ++i) {
                    if (field.items[i].receivesShadows) receivers.add(field.bounds[i]);
                    if (!field.planes[i]) casters.add(field.bounds[i]);
                }
                receivers = receivers.transformed(cam.viewFromWorld);
                casters = casters.transformed(cam.viewFromWorld);
                for (int a = 0; a < 2; ++a) {
                    receivers.lo[a] = std::max(receivers.lo[a], casters.lo[a]);
                    receivers.hi[a] = std::min(receivers.hi[a], casters.hi[a]);
                }
                for (int a = 0; a < 2; ++a) {
                    const bool holdsSlice = lo[a] <= slice.lo[a] && hi[a] >= slice.hi[a];
                    const bool holdsReceivers = lo[a] <= receivers.lo[a] && hi[a] >= receivers.hi[a];
                    EXPECT_TRUE(holdsSlice || holdsReceivers) << "axis " << a << ": window " << lo[a] << ".." << hi[a] << ", slice " << slice.lo[a] << ".."
                                                              << slice.hi[a] << ", receivers " << receivers.lo[a] << ".." << receivers.hi[a];
                }
            } else {
                // Tight: within the slice's corners (which the stabilised
                // sphere holds), cut to its receivers and the casters over
                // them, so never wider than the stabilised box.
                const LightCamera sphere = fitCascade(kSun, camera, kAspect, near, far[c], true, field.input(camera, kAspect));
                glm::vec2 sphereLo, sphereHi;
                box(sphere, sphereLo, sphereHi);
                EXPECT_LE(hi.x - lo.x, sphereHi.x - sphereLo.x);
                EXPECT_LE(hi.y - lo.y, sphereHi.y - sphereLo.y);
            }
            // Stabilised, nearer cascades have finer texels, or the same
            // where both windows are the casters' footprint (tight ones are
            // also cut to the casters' footprint, which can make a far one smaller).
            if (stabilize) {
                EXPECT_GE(cam.texelSize, previousTexel);
            }
            previousTexel = cam.texelSize;
        }
    }
}

// The light pass takes a fragment's point in the first cascade's texture
// space and each cascade's from it by a scale and an offset per axis
// (LightPassVariant::cascadeAxes, MapBlock's cascadeScale): so every
// unwarped cascade, stabilised or tight, must share the first one's light
// view, its projection differing only by scale and offset. Tolerance: the
// off-diagonal terms of M_c M_0^-1 at most 1e-5 of the diagonal's (float
// matrices; a turned view would put terms of order 1 there).
TEST(CascadeTest, UnwarpedCascadesShareOneLightViewUpToScaleAndOffset) {
    const Field field;
    for (const float yaw : {10.0f, 75.0f, 200.0f})
        for (const bool stabilize : {true, false}) {
            const Camera camera = walker(glm::vec3(3.0f, 1.8f, 5.0f), yaw);
            const std::vector<float> far = cascadeSplits(camera.nearPlane, camera.farPlane, 4, 0.75f);
            glm::dmat4 first(1.0);
            for (std::size_t c = 0; c < far.size(); ++c) {
                SCOPED_TRACE(std::string(stabilize ? "stabilised" : "tight") + ", yaw " + std::to_string(yaw) + ", cascade " + std::to_string(c));
                const float near = c == 0 ? camera.nearPlane : far[c - 1];
                const LightCamera cam = fitCascade(kSun, camera, kAspect, near, far[c], stabilize, field.input(camera, kAspect));
                const glm::dmat4 m(cam.clipFromWorld());
                if (c == 0) first = m;
                const glm::dmat4 fromFirst = m * glm::inverse(first);
                // Each row's terms off its diagonal against the diagonal (w's row: against 1).
                for (int row = 0; row < 4; ++row) {
                    const double diagonal = row < 3 ? std::abs(fromFirst[row][row]) : 1.0;
                    EXPECT_GT(diagonal, 0.0);
                    for (int col = 0; col < 3; ++col) {
                        if (col != row) {
                            EXPECT_LE(std::abs(fromFirst[col][row]), 1e-5 * diagonal) << "column " << col << ", row " << row;
                        }
                    }
                }
                EXPECT_NEAR(fromFirst[3][3], 1.0, 1e-6);
            }
        }
}

TEST(CascadeTest, AStabilisedCascadeKeepsItsTexelGridWhileTheCameraMovesAndTurns) {
    const Field field;
    const Camera start = walker(glm::vec3(0.0f, 1.8f, 5.0f), 0.0f);
    const LightCamera first = fitCascade(kSun, start, kAspect, 0.1f, 20.0f, true, field.input(start, kAspect));
    const float texel = first.texelSize;
    glm::vec2 lo0, hi0;
    box(first, lo0, hi0);
    int shifted = 0, depthMoves = 0;
    float previousNear = first.nearPlane, previousFar = first.farPlane;
    for (int step = 1; step <= 60; ++step) {
        // 3 mm and 0.05 degrees a step: sub-texel (a texel is about 2 cm here).
        const Camera camera = walker(glm::vec3(0.003f * static_cast<float>(step), 1.8f, 5.0f - 0.002f * static_cast<float>(step)),
                                     0.05f * static_cast<float>(step));
        const LightCamera cam = fitCascade(kSun, camera, kAspect, 0.1f, 20.0f, true, field.input(camera, kAspect));
        SCOPED_TRACE("step " + std::to_string(step));
        // The same light view and texel size, a depth range that moves by
        // whole steps of 1/32 of the box (64 texels) or not at all...
        EXPECT_EQ(cam.viewFromWorld, first.viewFromWorld);
        EXPECT_EQ(cam.texelSize, texel);
        const float depthStep = 64.0f * texel;
        for (const float moved : {(cam.nearPlane - first.nearPlane) / depthStep, (cam.farPlane - first.farPlane) / depthStep})
            EXPECT_NEAR(moved, std::round(moved), 1e-2f);
        depthMoves += cam.nearPlane != previousNear || cam.farPlane != previousFar;
        previousNear = cam.nearPlane;
        previousFar = cam.farPlane;
        // ... and a box moved by whole texels only: the grid of texel
        // centres is the same in the world. 1e-2 texel: the box's edges are
        // floats of at most a few hundred light-space units, whose rounding
        // (under 3e-5 units) is a thousandth of this cascade's 2 cm texel.
        glm::vec2 lo, hi;
        box(cam, lo, hi);
        const glm::vec2 moved = (lo - lo0) / texel;
        EXPECT_NEAR(moved.x, std::round(moved.x), 1e-2f);
        EXPECT_NEAR(moved.y, std::round(moved.y), 1e-2f);
        EXPECT_NEAR((hi.x - lo.x) / texel, 2048.0f, 1e-2f);
        shifted += moved != glm::vec2(0.0f);
    }
    EXPECT_GT(shifted, 0) << "the path must move the box at least once for the test to mean something";
    EXPECT_LE(depthMoves, 3) << "the depth range moves rarely";
}

// A stabilised cascade's depth range is its slice's within the scene, not
// the whole scene's along the light (moments could not part a caster's foot
// from the ground under it in the 400 m field's 500 m): every point of the
// slice inside the scene's box lies between the near and far planes, and
// the first slice's range is a small part of the scene's.
TEST(CascadeTest, AStabilisedCascadesDepthRangeIsItsSlices) {
    const Field field;
    const Camera camera = walker(glm::vec3(0.0f, 1.8f, 5.0f), 10.0f);
    const FitInput in = field.input(camera, kAspect);
    Bounds scene;
    for (const Bounds& b : field.bounds) scene.add(b);
    const LightCamera whole = fitDirectional(kSun, LightFit::Scene, in);
    for (const auto& [near, far] : {std::pair{0.1f, 20.0f}, std::pair{20.0f, 100.0f}, std::pair{100.0f, 400.0f}}) {
        SCOPED_TRACE("slice " + std::to_string(near) + " to " + std::to_string(far));
        const LightCamera cam = fitCascade(kSun, camera, kAspect, near, far, true, in);
        const glm::mat4 worldFromClip = glm::inverse(glm::perspective(glm::radians(camera.fovYDeg), kAspect, near, far) * camera.viewFromWorld());
        int inside = 0;
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j)
                for (int k = 0; k <= 10; ++k) {
                    const glm::vec3 ndc = 0.2f * glm::vec3(glm::ivec3(i, j, k)) - 1.0f;  // a grid over the clip cube
                    const glm::vec4 h = worldFromClip * glm::vec4(ndc, 1.0f);
                    const glm::vec3 p = glm::vec3(h) / h.w;
                    if (glm::any(glm::lessThan(p, scene.lo)) || glm::any(glm::greaterThan(p, scene.hi))) continue;
                    ++inside;
                    const float depth = -(cam.viewFromWorld * glm::vec4(p, 1.0f)).z;
                    EXPECT_GE(depth, cam.nearPlane);
                    EXPECT_LE(depth, cam.farPlane);
                }
        EXPECT_GT(inside, 0) << "the slice must cross the scene for the test to mean something";
        if (far <= 20.0f) {
            EXPECT_LT(cam.farPlane - cam.nearPlane, 0.1f * (whole.farPlane - whole.nearPlane));
        }
    }
}

// Whether a caster's shadow may fall in a slice (shadowMayReach): the sun
// is 30 degrees high and shines towards +z, back at a camera looking down
// -z, so a 2 m box's shadow runs 3.5 m towards the camera. A box 7 m ahead
// casts nothing into the slice from 20 to 100 m; one 22 m ahead, outside
// the slice from 0.1 to 20 m, still shadows it (its shadow reaches 18.5 m);
// one 35 m ahead shadows the far slice, not the near one.
TEST(CascadeTest, ACastersShadowReachesTheSlicesItFallsIn) {
    const Camera camera = walker(glm::vec3(0.0f, 1.8f, 5.0f), 0.0f);
    Bounds scene;
    scene.add(glm::vec3(-200.0f, 0.0f, -200.0f));
    scene.add(glm::vec3(200.0f, 2.0f, 200.0f));
    const auto boxAt = [](float z) {
        Bounds b;
        b.add(glm::vec3(-0.5f, 0.0f, z - 0.5f));
        b.add(glm::vec3(0.5f, 2.0f, z + 0.5f));
        return b;
    };
    const auto slice = [&](float near, float far) {
        return glm::perspective(glm::radians(camera.fovYDeg), kAspect, near, far) * camera.viewFromWorld();
    };
    const glm::vec3 sun = glm::normalize(glm::vec3(0.0f, -0.5f, 0.866f));
    EXPECT_FALSE(shadowMayReach(boxAt(-2.0f), sun, scene, 0.05f, false, slice(20.0f, 100.0f)));
    EXPECT_TRUE(shadowMayReach(boxAt(-2.0f), sun, scene, 0.05f, false, slice(0.1f, 20.0f)));
    EXPECT_TRUE(shadowMayReach(boxAt(-17.0f), sun, scene, 0.05f, false, slice(0.1f, 20.0f)));
    EXPECT_TRUE(shadowMayReach(boxAt(-30.0f), sun, scene, 0.05f, false, slice(20.0f, 100.0f)));
    EXPECT_FALSE(shadowMayReach(boxAt(-30.0f), sun, scene, 0.05f, false, slice(0.1f, 20.0f)));
    // Swept both ways (a filter that compares against the receiver's plane
    // beyond the caster) in a scene 40 m tall, the box 7 m ahead reaches
    // back towards the sun, away from the camera, into the far slice.
    Bounds tall = scene;
    tall.add(glm::vec3(0.0f, 40.0f, 0.0f));
    EXPECT_FALSE(shadowMayReach(boxAt(-2.0f), sun, tall, 0.05f, false, slice(20.0f, 100.0f)));
    EXPECT_TRUE(shadowMayReach(boxAt(-2.0f), sun, tall, 0.05f, true, slice(20.0f, 100.0f)));
}

// A stabilised cascade keeps only the casters whose shadow can reach what
// its lookups read (LightCamera.cpp: castersOverSlice): the boxes along the
// view axis, the first slice (0.1 to 10 m) keeps those near it and drops
// the ones 100 m and more down the row; the last slice (to 200 m) keeps
// them; a box 50 m behind the camera, whose shadow falls away from the
// view, is dropped by both; the ground, a plane with nothing below it,
// stays out as castersThatMatter says.
TEST(Cascade, AStabilisedCascadeKeepsOnlyTheCastersOverItsSlice) {
    Field field;
    Bounds behind;  // the sun shines towards +z: its shadow runs away from the view (-z)
    behind.add(glm::vec3(-1.0f, 0.0f, 49.0f));
    behind.add(glm::vec3(1.0f, 2.0f, 51.0f));
    field.bounds.push_back(behind);
    field.planes.emplace_back(std::nullopt);
    field.convex.emplace_back();
    field.items.emplace_back();
    field.items.back().mesh = static_cast<int>(field.items.size()) - 1;
    const Camera camera = walker(glm::vec3(0.0f, 1.8f, 0.0f), 0.0f);
    const FitInput in = field.input(camera, kAspect);
    const LightCamera first = fitCascade(kSun, camera, kAspect, 0.1f, 10.0f, true, in);
    const LightCamera last = fitCascade(kSun, camera, kAspect, 10.0f, 200.0f, true, in, 0.1f);
    ASSERT_EQ(first.casts.size(), field.items.size());
    ASSERT_EQ(last.casts.size(), field.items.size());
    EXPECT_EQ(first.casts[0], 0) << "the ground";
    EXPECT_EQ(first.casts[1], 1) << "the box 2 m ahead";
    EXPECT_EQ(first.casts[30], 0) << "the box 137 m ahead";
    EXPECT_EQ(last.casts[30], 1) << "the box 137 m ahead, in the last slice";
    EXPECT_EQ(first.casts.back(), 0) << "the box behind the camera";
    EXPECT_EQ(last.casts.back(), 0) << "the box behind the camera";
}

// A cascade's casters are those over where its lookups start: the slice
// before it reads it only in its blend share, at its far end
// (MapCameras: castsFrom). The box 2 m ahead, whose shadow falls within
// the first 10 m, is kept by the second slice (10 to 200 m) while that is
// read from the near plane on, and dropped once it is read from 9 m (the
// first slice's last tenth); the box 137 m ahead stays.
TEST(Cascade, ACascadeKeepsTheCastersOverItsBlendShareNotTheSliceBefore) {
    Field field;
    const Camera camera = walker(glm::vec3(0.0f, 1.8f, 0.0f), 0.0f);
    const FitInput in = field.input(camera, kAspect);
    const LightCamera all = fitCascade(kSun, camera, kAspect, 10.0f, 200.0f, true, in, 0.1f);
    const LightCamera banded = fitCascade(kSun, camera, kAspect, 10.0f, 200.0f, true, in, 0.1f, nullptr, 9.0f);
    ASSERT_EQ(banded.casts.size(), field.items.size());
    EXPECT_EQ(all.casts[1], 1) << "the box 2 m ahead, read from the near plane on";
    EXPECT_EQ(banded.casts[1], 0) << "the box 2 m ahead, read from 9 m on";
    EXPECT_EQ(banded.casts[30], 1) << "the box 137 m ahead";
    // The map itself is the same: its box and depth range come from readFrom.
    EXPECT_EQ(all.clipFromView, banded.clipFromView);
    EXPECT_EQ(all.viewFromWorld, banded.viewFromWorld);
}
