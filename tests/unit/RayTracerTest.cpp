// Tests of the Embree reference (src/reference/RayTracer) against closed-form
// shadows (src/core/AnalyticShadow.h) and geometric facts.
#include "core/AnalyticShadow.h"
#include "reference/RayTracer.h"

#include <shadowlab/Error.h>
#include <shadowlab/Scene.h>
#include <shadowlab/Shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <utility>
#include <vector>

namespace {

using shadowlab::Light;
using shadowlab::LightType;
using shadowlab::Mesh;
using shadowlab::Node;
using shadowlab::Scene;
using shadowlab::reference::RayTracer;
using shadowlab::reference::SurfaceSample;
using shadowlab::reference::VisibilityOptions;

constexpr float kPi = std::numbers::pi_v<float>;

// UV sphere centred on the origin: `segments` around Y, `rings` pole to pole,
// vertices exactly on the sphere (so the mesh is inscribed in it). The
// degenerate triangles at the poles are left out.
Mesh makeUvSphere(float radius, int segments, int rings) {
    Mesh mesh;
    mesh.name = "sphere";
    for (int j = 0; j <= rings; ++j) {
        const float theta = kPi * static_cast<float>(j) / static_cast<float>(rings);
        for (int i = 0; i <= segments; ++i) {
            const float phi = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(radius * n);
            mesh.normals.push_back(n);
        }
    }
    const auto at = [segments](int j, int i) { return static_cast<std::uint32_t>(j * (segments + 1) + i); };
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const std::uint32_t a = at(j, i), d = at(j, i + 1), b = at(j + 1, i), c = at(j + 1, i + 1);
            if (j != rings - 1) mesh.indices.insert(mesh.indices.end(), {a, b, c});
            if (j != 0) mesh.indices.insert(mesh.indices.end(), {a, c, d});
        }
    return mesh;
}

// Square in the plane y = 0, centred on the origin, normal +Y.
Mesh makeQuad(float halfSize) {
    Mesh mesh;
    mesh.name = "quad";
    mesh.positions = {{-halfSize, 0, -halfSize}, {-halfSize, 0, halfSize}, {halfSize, 0, halfSize}, {halfSize, 0, -halfSize}};
    mesh.normals.assign(4, glm::vec3(0, 1, 0));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

void addInstance(Scene& scene, Mesh mesh, glm::vec3 translation, bool castsShadows = true) {
    scene.meshes.push_back(std::move(mesh));
    Node node;
    node.name = scene.meshes.back().name;
    node.mesh = static_cast<int>(scene.meshes.size()) - 1;
    node.translation = translation;
    node.castsShadows = castsShadows;
    scene.nodes.push_back(node);
}

SurfaceSample groundSample(float x, float z) { return {{x, 0.0f, z}, {0.0f, 1.0f, 0.0f}, true}; }

Light directionalLight(glm::vec3 direction, float sizeDeg = 0.0f) {
    Light light;
    light.name = "sun";
    light.type = LightType::Directional;
    light.direction = glm::normalize(direction);
    light.size = sizeDeg;
    return light;
}

Light pointLight(glm::vec3 position, float size = 0.0f) {
    Light light;
    light.name = "bulb";
    light.type = LightType::Point;
    light.position = position;
    light.size = size;
    return light;
}

// The sphere of the ground-shadow scenes: radius 1 at height 2, 64 x 32.
constexpr float kRadius = 1.0f;
const glm::vec3 kCentre(0.0f, 2.0f, 0.0f);
constexpr int kSegments = 64;
constexpr int kRings = 32;

Scene sphereOverGround(float groundHalfSize = 50.0f) {
    Scene scene;
    addInstance(scene, makeQuad(groundHalfSize), glm::vec3(0.0f));
    addInstance(scene, makeUvSphere(kRadius, kSegments, kRings), kCentre);
    return scene;
}

struct Pinhole {
    glm::vec3 position, forward, right, up;
    float tanHalfY, aspect;
    int width, height;
    Pinhole(glm::vec3 eye, glm::vec3 target, float fovYDeg, int w, int h)
        : position(eye), forward(glm::normalize(target - eye)),
          right(glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)))), up(glm::cross(right, forward)),
          tanHalfY(std::tan(glm::radians(fovYDeg) * 0.5f)),
          aspect(static_cast<float>(w) / static_cast<float>(h)), width(w), height(h) {}
    // Ray through the centre of pixel (x, y), rows top to bottom.
    glm::vec3 direction(int x, int y) const {
        const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width) - 1.0f) * tanHalfY * aspect;
        const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height)) * tanHalfY;
        return glm::normalize(forward + sx * right + sy * up);
    }
};

double raysPerSecond(std::size_t rays, std::chrono::steady_clock::duration elapsed) {
    return static_cast<double>(rays) / std::chrono::duration<double>(elapsed).count();
}

} // namespace

// The hard shadow of a tessellated sphere on the ground agrees with the exact
// projected ellipse everywhere except within one pixel of its edge.
TEST(RayTracer, SphereShadowOnGroundMatchesAnalyticEllipse) {
    const float groundHalf = 50.0f;
    const Scene scene = sphereOverGround(groundHalf);
    const RayTracer tracer(scene);
    EXPECT_EQ(tracer.triangleCount(), 2u + 2u * kSegments * (kRings - 1));

    const Light sun = directionalLight({0.4f, -1.0f, 0.3f});
    const Pinhole camera({-1.0f, 7.0f, 8.0f}, {0.6f, 0.0f, 0.4f}, 45.0f, 320, 240);
    const int w = camera.width, h = camera.height;

    // Per pixel: the camera ray's hit with y = 0 (analytic), its exact shadow
    // class, and whether the sphere hides the ground there.
    enum Kind { Sky, Ground, Sphere };
    std::vector<Kind> kind(static_cast<std::size_t>(w * h), Sky);
    std::vector<bool> inShadow(kind.size(), false);
    std::vector<SurfaceSample> samples(kind.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * w + x);
            const glm::vec3 d = camera.direction(x, y);
            if (d.y >= 0.0f) continue;
            const glm::vec3 p = camera.position + (-camera.position.y / d.y) * d; // t = -o.y / d.y
            if (std::abs(p.x) > groundHalf || std::abs(p.z) > groundHalf) continue;
            inShadow[i] = shadowlab::inSphereShadowOnGround(p, kCentre, kRadius, sun.direction);
            // The sphere lies entirely above y = 0 and the camera above it, so
            // any hit of the (true) sphere is in front of the ground. The mesh
            // is inscribed in the sphere, so a ray missing the sphere misses it.
            if (shadowlab::rayHitsSphere(camera.position, d, kCentre, kRadius)) {
                kind[i] = Sphere;
                continue;
            }
            kind[i] = Ground;
            samples[i] = {p, {0.0f, 1.0f, 0.0f}, true};
        }

    // Why a 1-pixel band is enough: every facet's plane is at distance >=
    // r*cos(a/2)*cos(b/2) from the centre (a = 2 pi/segments, b = pi/rings),
    // so the mesh lies between the spheres of radius r' = r*cos^2(pi/64) and
    // r, and its shadow between their ellipses. The ellipse's semi-axes are r
    // and r/|L.y| (L = unit light direction), so the shadow edge moves by at
    // most (r - r')/|L.y| on the ground -- checked here to be well under half
    // a pixel's footprint near the shadow. The exact edge is a smooth ellipse
    // with axes of ~25 pixels, so if it came within that distance of a pixel
    // centre it would separate that pixel from one of its 8 neighbours: the
    // pixel would be in the band. Outside the band the mesh's shadow class
    // equals the sphere's exactly; the 0.1 % tolerance is only for rounding.
    const float deviation = kRadius * (1.0f - std::pow(std::cos(kPi / kSegments), 2.0f)) / std::abs(sun.direction.y);
    const glm::vec3 shadowCentre = kCentre - (kCentre.y / sun.direction.y) * sun.direction;
    float footprint = 1e30f; // smallest pixel spacing on the ground around the shadow
    for (int y = 1; y < h; ++y)
        for (int x = 1; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * w + x);
            if (kind[i] != Ground || kind[i - 1] != Ground || kind[i - static_cast<std::size_t>(w)] != Ground) continue;
            if (glm::length(samples[i].position - shadowCentre) > 3.0f * kRadius) continue;
            footprint = std::min({footprint, glm::length(samples[i].position - samples[i - 1].position),
                                  glm::length(samples[i].position - samples[i - static_cast<std::size_t>(w)].position)});
        }
    ASSERT_LT(deviation, 0.5f * footprint) << "the 1-pixel band argument needs the facet error below half a pixel";

    const auto start = std::chrono::steady_clock::now();
    const std::vector<float> visibility = tracer.visibility(sun, samples);
    const auto elapsed = std::chrono::steady_clock::now() - start;
    ASSERT_EQ(visibility.size(), samples.size());

    std::size_t compared = 0, agree = 0, shadowed = 0, band = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * w + x);
            if (kind[i] == Sky) {
                EXPECT_EQ(visibility[i], 0.0f) << "invalid samples get 0";
                continue;
            }
            if (kind[i] != Ground) continue;
            EXPECT_TRUE(visibility[i] == 0.0f || visibility[i] == 1.0f) << "hard shadows are binary";
            bool inBand = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::size_t j = static_cast<std::size_t>(ny * w + nx);
                    if (kind[j] != Sky && inShadow[j] != inShadow[i]) inBand = true;
                }
            if (inBand) {
                ++band;
                continue;
            }
            ++compared;
            shadowed += inShadow[i] ? 1u : 0u;
            agree += ((visibility[i] < 0.5f) == inShadow[i]) ? 1u : 0u;
        }
    ASSERT_GT(shadowed, 1000u) << "the shadow must be well inside the image";
    ASSERT_GT(compared - shadowed, 10000u);
    const double agreement = static_cast<double>(agree) / static_cast<double>(compared);
    EXPECT_GE(agreement, 0.999) << agree << " of " << compared << " ground pixels agree";
    std::cout << "[ info ] analytic agreement " << agree << "/" << compared << " (" << shadowed
              << " in shadow, " << band << " in the edge band); facet error " << deviation
              << " vs pixel footprint " << footprint << "\n";

    // Timing (information only): hard rays in raster order, then soft.
    std::size_t rays = 0;
    std::chrono::steady_clock::duration total{};
    for (int repeat = 0; repeat < 20; ++repeat) {
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<float> v = tracer.visibility(sun, samples);
        total += std::chrono::steady_clock::now() - t0;
        rays += samples.size();
    }
    std::cout << "[ info ] hard: " << raysPerSecond(samples.size(), elapsed) / 1e6 << " M rays/s first call, "
              << raysPerSecond(rays, total) / 1e6 << " M rays/s over 20 calls (" << tracer.triangleCount()
              << " triangles, " << samples.size() << " samples)\n";
    VisibilityOptions soft;
    soft.softSamples = 64;
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<float> v = tracer.visibility(directionalLight(sun.direction, 5.0f), samples, soft);
    const auto softTime = std::chrono::steady_clock::now() - t0;
    std::size_t traced = 0;
    for (const SurfaceSample& s : samples) traced += s.valid ? 1u : 0u;
    std::cout << "[ info ] soft (64 per pixel, 5 deg sun): "
              << raysPerSecond(traced * 64u, softTime) / 1e6 << " M rays/s\n";
}

// Point light: an occluder between sample and light blocks it, one beside or
// beyond the light does not; range and invalid samples give 0.
TEST(RayTracer, PointLightOccluderBetweenBesideAndBeyond) {
    Scene scene;
    addInstance(scene, makeQuad(0.5f), {0.0f, 1.0f, 0.0f}); // between (0,0,0) and the light
    addInstance(scene, makeQuad(0.5f), {0.0f, 3.0f, 0.0f}); // beyond the light
    const RayTracer tracer(scene);
    EXPECT_EQ(tracer.triangleCount(), 4u);

    Light bulb = pointLight({0.0f, 2.0f, 0.0f});
    SurfaceSample invalid = groundSample(3.0f, 0.0f);
    invalid.valid = false;
    // (3,0,0): the ray crosses y = 1 at x = 1.5, beside the occluder.
    // (1.2,0,0): crosses y = 1 at x = 0.6, just beside (half size 0.5).
    const std::vector<SurfaceSample> samples = {groundSample(0.0f, 0.0f), groundSample(3.0f, 0.0f),
                                                groundSample(1.2f, 0.0f), groundSample(0.2f, 0.1f), invalid};
    EXPECT_EQ(tracer.visibility(bulb, samples), (std::vector<float>{0.0f, 1.0f, 1.0f, 0.0f, 0.0f}));

    bulb.range = 2.5f; // (3,0,0) is sqrt(13) = 3.6 away, (1.2,0,0) is 2.33 away
    EXPECT_EQ(tracer.visibility(bulb, samples), (std::vector<float>{0.0f, 0.0f, 1.0f, 0.0f, 0.0f}));

    const Light sun = directionalLight({0.0f, -1.0f, 0.0f});
    EXPECT_EQ(tracer.visibility(sun, samples), (std::vector<float>{0.0f, 1.0f, 1.0f, 0.0f, 0.0f}));
    const std::vector<SurfaceSample> onQuads = {{{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, true},
                                                {{0.1f, 3.0f, 0.1f}, {0.0f, 1.0f, 0.0f}, true}};
    // The lower quad's top sees the light even though the upper quad lies on
    // the ray's extension beyond it (tfar ends at the light); the upper
    // quad's top faces away from the light: unreached, 0.
    EXPECT_EQ(tracer.visibility(bulb, onQuads), (std::vector<float>{1.0f, 0.0f}));
}

// Spot light: samples outside the outer cone are 0, hard and soft.
TEST(RayTracer, SpotOutsideOuterConeIsZero) {
    Scene scene;
    addInstance(scene, makeQuad(10.0f), glm::vec3(0.0f), /*castsShadows=*/false);
    const RayTracer tracer(scene);
    EXPECT_EQ(tracer.triangleCount(), 0u) << "non-casters are not in the BVH";

    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.position = {0.0f, 5.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.innerConeDeg = 20.0f;
    spot.outerConeDeg = 30.0f;
    // Angles from the axis: 0, 21.8, 29.2, 31.0, 35.0 degrees.
    const std::vector<SurfaceSample> samples = {groundSample(0.0f, 0.0f), groundSample(2.0f, 0.0f),
                                                groundSample(0.0f, -2.8f), groundSample(3.0f, 0.0f),
                                                groundSample(-2.5f, 2.45f)};
    const std::vector<float> expected{1.0f, 1.0f, 1.0f, 0.0f, 0.0f};
    EXPECT_EQ(tracer.visibility(spot, samples), expected);
    spot.size = 0.3f;
    EXPECT_EQ(tracer.visibility(spot, samples), expected);
}

// Soft shadow of a sphere: exact 0 in the umbra and 1 where the whole light
// is visible, monotonic in between up to Monte-Carlo noise.
TEST(RayTracer, SoftShadowPenumbraIsMonotonic) {
    const Scene scene = sphereOverGround(20.0f);
    const RayTracer tracer(scene);
    VisibilityOptions options; // 256 samples per pixel
    std::vector<SurfaceSample> line;
    for (int i = 0; i <= 200; ++i) line.push_back(groundSample(0.02f * static_cast<float>(i), 0.0f));

    // Noise: a mean of n Bernoulli rays has sigma <= 0.5/sqrt(n) (stratifying
    // only lowers it), so two neighbours differ by noise with sigma <=
    // 0.71/sqrt(n); 3/sqrt(n) = 0.19 for n = 256 is over 4 sigma.
    const float tolerance = 3.0f / std::sqrt(static_cast<float>(options.softSamples));

    // Sun straight down, 10 degrees across (half angle 5), and a disk bulb of
    // radius 0.5 at height 6 (seen from the ground: ~4.8 degrees half angle).
    const float halfAngleDeg = 5.0f;
    const Light lights[] = {directionalLight({0.0f, -1.0f, 0.0f}, 2.0f * halfAngleDeg),
                            pointLight({0.0f, 6.0f, 0.0f}, 0.5f)};
    for (const Light& light : lights) {
        SCOPED_TRACE(light.name);
        const std::vector<float> v = tracer.visibility(light, line, options);
        EXPECT_EQ(v.front(), 0.0f) << "umbra under the sphere";
        EXPECT_EQ(v.back(), 1.0f) << "far from the sphere everything is lit";
        int penumbra = 0;
        for (std::size_t i = 0; i + 1 < v.size(); ++i) {
            EXPECT_GE(v[i + 1], v[i] - tolerance) << "at x = " << line[i + 1].position.x;
            if (v[i] > 0.0f && v[i] < 1.0f) ++penumbra;
        }
        EXPECT_GE(penumbra, 5) << "a light with size > 0 casts a penumbra";

        if (light.type == LightType::Directional) {
            // Exact umbra and lit regions: from (x,0,0) the sphere is a disk of
            // angular radius asin(r/D) around a direction atan(x/2) from the
            // zenith; the light is a disk of angular radius 5 degrees around
            // the zenith. 0.5 degree margin covers the facets (<= 0.1 degree).
            for (std::size_t i = 0; i < v.size(); ++i) {
                const float x = line[i].position.x;
                const float sphereDeg = glm::degrees(std::asin(kRadius / std::sqrt(x * x + 4.0f)));
                const float centreDeg = glm::degrees(std::atan(x / 2.0f));
                if (centreDeg + halfAngleDeg + 0.5f <= sphereDeg) {
                    EXPECT_EQ(v[i], 0.0f) << "umbra at x = " << x;
                }
                if (centreDeg - halfAngleDeg - 0.5f >= sphereDeg) {
                    EXPECT_EQ(v[i], 1.0f) << "lit at x = " << x;
                }
            }
        }
    }

    // A sample count that is not a square (3x3 grid + 1 random) stays exact at the ends.
    options.softSamples = 10;
    const std::vector<float> v = tracer.visibility(lights[0], line, options);
    EXPECT_EQ(v.front(), 0.0f);
    EXPECT_EQ(v.back(), 1.0f);
    for (float value : v) {
        EXPECT_GE(value, 0.0f);
        EXPECT_LE(value, 1.0f);
    }
}

// Samples on the sphere's own lit facets (interpolated positions, geometric
// normals) are never falsely occluded with the per-point origin offset.
TEST(RayTracer, NoFalseSelfOcclusionOnCurvedMesh) {
    Scene scene;
    addInstance(scene, makeUvSphere(kRadius, kSegments, kRings), kCentre);
    const RayTracer tracer(scene);

    const Mesh& mesh = scene.meshes[0];
    const Light lights[] = {directionalLight({0.4f, -1.0f, 0.3f}), pointLight({3.0f, 6.0f, 2.0f}),
                            directionalLight({1.0f, -0.05f, 0.0f})}; // nearly grazing sun
    const glm::vec3 barycentrics[] = {{1 / 3.f, 1 / 3.f, 1 / 3.f}, {0.98f, 0.01f, 0.01f}, {0.01f, 0.98f, 0.01f},
                                      {0.01f, 0.01f, 0.98f},       {0.49f, 0.49f, 0.02f}, {0.02f, 0.49f, 0.49f},
                                      {0.49f, 0.02f, 0.49f}};
    for (const Light& light : lights) {
        SCOPED_TRACE(light.name);
        std::vector<SurfaceSample> samples;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::vec3 a = mesh.positions[mesh.indices[3 * t]] + kCentre;
            const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]] + kCentre;
            const glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]] + kCentre;
            glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
            if (glm::dot(n, (a + b + c) / 3.0f - kCentre) < 0.0f) n = -n; // outward
            for (const glm::vec3& w : barycentrics) {
                const glm::vec3 p = w.x * a + w.y * b + w.z * c;
                const glm::vec3 toLight = light.type == LightType::Directional ? -light.direction
                                                                               : glm::normalize(light.position - p);
                if (glm::dot(n, toLight) > 0.0f) samples.push_back({p, n, true}); // lit side of its facet
            }
        }
        ASSERT_GT(samples.size(), 10000u);
        const std::vector<float> v = tracer.visibility(light, samples);
        const auto falseHits = static_cast<std::size_t>(std::count(v.begin(), v.end(), 0.0f));
        EXPECT_EQ(falseHits, 0u) << "of " << samples.size() << " lit samples";

        VisibilityOptions noOffset; // for comparison only: origins exactly on the surface
        noOffset.normalOffset = 0.0f;
        const std::vector<float> raw = tracer.visibility(light, samples, noOffset);
        std::cout << "[ info ] " << light.name << ": false self-occlusion " << falseHits << "/" << samples.size()
                  << " with the per-point offset, " << std::count(raw.begin(), raw.end(), 0.0f)
                  << " with no offset and tnear 0\n";
    }
}

// Same seed, same result (whatever the threads did); another seed differs
// only by noise inside the penumbra.
TEST(RayTracer, SoftShadowsAreDeterministicPerSeed) {
    const RayTracer tracer(sphereOverGround(20.0f));
    std::vector<SurfaceSample> samples;
    for (int z = 0; z < 40; ++z)
        for (int x = 0; x < 200; ++x)
            samples.push_back(groundSample(0.015f * static_cast<float>(x), 0.05f * static_cast<float>(z) - 1.0f));
    const Light sun = directionalLight({0.1f, -1.0f, 0.05f}, 10.0f);
    VisibilityOptions options;
    options.softSamples = 64;
    const std::vector<float> first = tracer.visibility(sun, samples, options);
    EXPECT_EQ(tracer.visibility(sun, samples, options), first);
    options.seed = 2;
    const std::vector<float> other = tracer.visibility(sun, samples, options);
    EXPECT_NE(other, first);

    // How far two seeds may differ. Each estimate is a mean over a jittered
    // 8x8 grid of strata (64 is a square), one ray per stratum: a stratum the
    // occluder's edge does not cross gives its exact value, a crossed one a
    // Bernoulli ray of variance <= 1/4. The edge seen from the ground is the
    // sphere's silhouette, ~30 degrees in radius against a light 5 degrees in
    // radius: nearly a straight chord, which crosses at most 2g = 16 of the g
    // x g strata. So var(estimate) <= 16 / (4 n^2), and the difference of two
    // independent estimates has sigma <= sqrt(2 * 16 / 4) / n = 0.044 (the
    // unstratified bound would be 1 / sqrt(2 n) = 0.088). The RMS difference
    // over the penumbra measures that sigma: at most the bound. A single
    // sample may differ by 6 sigma (0.27; Gaussian tail 2e-9 per sample, so
    // fewer than 1e-5 false failures over the few thousand penumbra samples).
    const int grid = 8;
    ASSERT_EQ(grid * grid, options.softSamples);
    const double n = options.softSamples;
    const double sigmaBound = std::sqrt(2.0 * (2.0 * grid) / 4.0) / n;
    const double tolerance = 6.0 * sigmaBound;
    double sumSq = 0.0, maxDiff = 0.0;
    std::size_t penumbra = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
        if ((first[i] == 0.0f || first[i] == 1.0f) && (other[i] == 0.0f || other[i] == 1.0f)) continue;
        ++penumbra;
        const double d = static_cast<double>(other[i]) - first[i];
        sumSq += d * d;
        maxDiff = std::max(maxDiff, std::abs(d));
        EXPECT_NEAR(other[i], first[i], tolerance) << "sample " << i;
    }
    ASSERT_GT(penumbra, 500u) << "the samples must cross the penumbra";
    const double rms = std::sqrt(sumSq / static_cast<double>(penumbra));
    EXPECT_LE(rms, sigmaBound) << "stratification must keep the seeds' difference below the stratified bound";
    std::cout << "[ info ] seeds 1 and 2 over " << penumbra << " penumbra samples: RMS difference " << rms
              << ", max " << maxDiff << " (sigma bound " << sigmaBound << ", tolerance " << tolerance << ")\n";
}

// The ray origin's offset depends on the point alone: it leaves the surface
// (strictly, in exact arithmetic) at every magnitude and stays within a few
// 2^-16 of the point's largest coordinate.
TEST(RayTracer, OffsetRayOriginLeavesTheSurfaceAtEveryMagnitude) {
    const glm::vec3 normals[] = {{0, 1, 0}, {0, 0, -1}, glm::normalize(glm::vec3(0.3f, 0.9f, -0.2f)),
                                 glm::normalize(glm::vec3(-1.0f, 0.02f, 0.01f))};
    for (float magnitude : {0.0f, 1e-3f, 0.03f, 1.0f, 7.5f, 30.0f, 1000.0f, 1e5f})
        for (const glm::vec3& direction : {glm::vec3(1, 1, 1), glm::vec3(-0.2f, 1, 0.7f), glm::vec3(3, -1, -2)})
            for (const glm::vec3& n : normals) {
                const glm::vec3 p = magnitude * glm::normalize(direction);
                const glm::vec3 o = shadowlab::reference::offsetRayOrigin(p, n);
                const glm::dvec3 moved = glm::dvec3(o) - glm::dvec3(p);
                const double along = glm::dot(moved, glm::dvec3(n));
                const double scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
                SCOPED_TRACE(testing::Message() << "p = (" << p.x << ", " << p.y << ", " << p.z << "), n = (" << n.x << ", "
                                                << n.y << ", " << n.z << ")");
                EXPECT_GT(along, 0.0) << "the origin must be strictly off the surface";
                // 256 ulps per coordinate (each <= 2^-23 |p_i|, so <= 2^-15 |p_i|)
                // plus the 2^-16 push: below 2^-13 of the scale with room to spare.
                EXPECT_LT(glm::length(moved), scale * 0x1.0p-13) << "the offset must stay small against the point";
            }
}

// The regression of issue 11: a 1 cm box 1000 units away, or a big node that
// casts no shadow, changed ~170 reference pixels because the old offset grew
// with the scene's bounding box. Now no sample's visibility changes.
TEST(RayTracer, FarAwayTinyBoxOrNonCasterChangesNoVisibility) {
    // Samples where an offset matters: a fine line across the shadow edge on
    // the ground, and the sphere's facets up to its terminator.
    std::vector<SurfaceSample> samples;
    for (int i = 0; i < 4000; ++i) samples.push_back(groundSample(-3.0f + 0.0015f * static_cast<float>(i), 0.1f));
    const Mesh sphere = makeUvSphere(kRadius, kSegments, kRings);
    for (std::size_t t = 0; t < sphere.triangleCount(); ++t) {
        const glm::vec3 a = sphere.positions[sphere.indices[3 * t]] + kCentre;
        const glm::vec3 b = sphere.positions[sphere.indices[3 * t + 1]] + kCentre;
        const glm::vec3 c = sphere.positions[sphere.indices[3 * t + 2]] + kCentre;
        glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        if (glm::dot(n, a - kCentre) < 0.0f) n = -n;
        samples.push_back({(a + b + c) / 3.0f, n, true});
    }
    const Light lights[] = {directionalLight({0.4f, -1.0f, 0.3f}), pointLight({3.0f, 6.0f, 2.0f}),
                            directionalLight({0.4f, -1.0f, 0.3f}, 4.0f)};
    VisibilityOptions options;
    options.softSamples = 16;

    const Scene base = sphereOverGround(20.0f);
    Scene withBox = base;
    Mesh box = shadowlab::shapes::box(glm::vec3(0.01f));
    box.name = "far box";
    addInstance(withBox, box, {1000.0f, 1.0f, -1000.0f});
    Scene withNonCaster = base;
    addInstance(withNonCaster, makeQuad(5000.0f), {0.0f, -200.0f, 0.0f}, /*castsShadows=*/false);

    // Every light's visibility from one scene's tracer.
    auto trace = [&](const Scene& scene) {
        const RayTracer tracer(scene);
        std::vector<std::vector<float>> out;
        for (const Light& light : lights) out.push_back(tracer.visibility(light, samples, options));
        return out;
    };
    auto changedSamples = [](const std::vector<std::vector<float>>& a, const std::vector<std::vector<float>>& b) {
        std::size_t changed = 0;
        for (std::size_t l = 0; l < a.size(); ++l)
            for (std::size_t i = 0; i < a[l].size(); ++i) changed += a[l][i] != b[l][i];
        return changed;
    };
    const auto expected = trace(base);
    EXPECT_EQ(changedSamples(trace(withBox), expected), 0u) << "a 1 cm box 1000 units away changed visibility";
    EXPECT_EQ(changedSamples(trace(withNonCaster), expected), 0u) << "a node that casts no shadow changed visibility";

    // The samples are sensitive: the old offset, 1e-4 of a bounding-box
    // diagonal that the far box stretches to ~1400, would move origins by
    // ~0.14; a tenth of that already changes some visibility.
    const RayTracer tracer(base);
    VisibilityOptions stretched = options;
    stretched.normalOffset = 0.014f;
    for (std::size_t l = 0; l < std::size(lights); ++l) {
        const std::vector<float> moved = tracer.visibility(lights[l], samples, stretched);
        std::size_t changed = 0;
        for (std::size_t i = 0; i < moved.size(); ++i) changed += moved[i] != expected[l][i];
        EXPECT_GT(changed, 0u) << lights[l].name << ": a scene-sized offset must change some of these samples";
        std::cout << "[ info ] " << lights[l].name << (lights[l].size > 0.0f ? " (soft)" : "") << ": " << changed
                  << " of " << samples.size() << " samples change with a 0.014 offset\n";
    }
}

// Reach: one definition (shaders/light_reach.h, plus facing the light) for
// the tracer and compare; unreached samples are 0 even with nothing in the way.
TEST(RayTracer, UnreachedSamplesAreZeroAndReachTellsThemApart) {
    Scene scene;
    addInstance(scene, makeQuad(10.0f), glm::vec3(0.0f), /*castsShadows=*/false); // nothing casts
    const RayTracer tracer(scene);
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.position = {0.0f, 5.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerConeDeg = 30.0f;
    spot.range = 6.2f;
    SurfaceSample facingAway = groundSample(0.5f, 0.0f);
    facingAway.normal = {0.0f, -1.0f, 0.0f};
    SurfaceSample invalid = groundSample(0.0f, 0.0f);
    invalid.valid = false;
    // In the cone; outside it (35 degrees, 6.1 away); in the cone but beyond
    // range (6.3 away at 18 degrees); facing away; background.
    const std::vector<SurfaceSample> samples = {groundSample(1.0f, 0.0f), groundSample(-2.5f, 2.45f),
                                                {{2.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, true}, facingAway, invalid};
    EXPECT_EQ(shadowlab::reference::lightReach(spot, samples), (std::vector<std::uint8_t>{1, 0, 0, 0, 0}));
    EXPECT_EQ(tracer.visibility(spot, samples), (std::vector<float>{1.0f, 0.0f, 0.0f, 0.0f, 0.0f}));
    const Light sun = directionalLight({0.2f, -1.0f, 0.0f});
    EXPECT_EQ(shadowlab::reference::lightReach(sun, samples), (std::vector<std::uint8_t>{1, 1, 1, 0, 0}));
    EXPECT_EQ(tracer.visibility(sun, samples), (std::vector<float>{1.0f, 1.0f, 1.0f, 0.0f, 0.0f}));
}

TEST(RayTracer, MoveOnlyAndOptionErrors) {
    RayTracer a(sphereOverGround());
    const std::size_t triangles = a.triangleCount();
    RayTracer b(std::move(a));
    EXPECT_EQ(b.triangleCount(), triangles);
    const std::vector<SurfaceSample> samples = {groundSample(0.0f, 0.0f), groundSample(30.0f, 0.0f)};
    const Light sun = directionalLight({0.0f, -1.0f, 0.0f});
    EXPECT_EQ(b.visibility(sun, samples), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_THROW(a.visibility(sun, samples), shadowlab::Error); // NOLINT(bugprone-use-after-move)
    a = std::move(b);
    EXPECT_EQ(a.visibility(sun, samples), (std::vector<float>{0.0f, 1.0f}));

    VisibilityOptions bad;
    bad.softSamples = 0;
    EXPECT_THROW(a.visibility(directionalLight({0.0f, -1.0f, 0.0f}, 1.0f), samples, bad), shadowlab::Error);
    Light zero = sun;
    zero.direction = glm::vec3(0.0f);
    EXPECT_THROW(a.visibility(zero, samples), shadowlab::Error);
    EXPECT_TRUE(a.visibility(sun, {}).empty());
}
