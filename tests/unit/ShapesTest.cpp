// Measured properties of the procedural shapes: attribute sizes, index range,
// unit normals consistent with the winding, closedness, enclosed volume and
// bounding box, and argument validation.
#include <shadowlab/Error.h>
#include <shadowlab/Shapes.h>

#include "ErrorText.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using shadowlab::Mesh;
namespace shapes = shadowlab::shapes;

constexpr double kPi = 3.14159265358979323846;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

glm::dvec3 toD(const glm::vec3& v) { return glm::dvec3(v); }

glm::dvec3 faceNormal(const Mesh& m, std::size_t t) {
    const glm::dvec3 a = toD(m.positions[m.indices[t]]);
    const glm::dvec3 b = toD(m.positions[m.indices[t + 1]]);
    const glm::dvec3 c = toD(m.positions[m.indices[t + 2]]);
    return glm::cross(b - a, c - a);
}

/// Sizes, index range, unit normals, uvs in [0,1], no degenerate triangles,
/// and every vertex normal on the front side of its triangle (so normals and
/// counter-clockwise winding agree).
void expectWellFormed(const Mesh& m) {
    ASSERT_FALSE(m.positions.empty());
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    ASSERT_GT(m.triangleCount(), 0u);
    for (std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    for (std::size_t i = 0; i < m.normals.size(); ++i) {
        EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-5f) << "vertex " << i;
        EXPECT_GE(m.uvs[i].x, 0.0f) << "vertex " << i;
        EXPECT_LE(m.uvs[i].x, 1.0f) << "vertex " << i;
        EXPECT_GE(m.uvs[i].y, 0.0f) << "vertex " << i;
        EXPECT_LE(m.uvs[i].y, 1.0f) << "vertex " << i;
    }
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 n = faceNormal(m, t);
        ASSERT_GT(glm::length(n), 0.0) << "degenerate triangle " << t / 3;
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(glm::dot(glm::normalize(n), toD(m.normals[m.indices[t + k]])), 0.0)
                << "triangle " << t / 3 << " winding disagrees with the normal of corner " << k;
    }
}

/// Flat-shaded meshes: every vertex normal equals its triangle's geometric normal.
void expectFlatNormals(const Mesh& m) {
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 n = glm::normalize(faceNormal(m, t));
        for (int k = 0; k < 3; ++k)
            EXPECT_LT(glm::length(n - toD(m.normals[m.indices[t + k]])), 1e-5) << "triangle " << t / 3;
    }
}

/// Welds vertices closer than eps (seams, poles and caps duplicate positions),
/// returns the welded id of each vertex.
std::vector<int> weld(const Mesh& m, float eps) {
    std::vector<int> id(m.positions.size());
    std::vector<glm::vec3> unique;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        int found = -1;
        for (std::size_t u = 0; u < unique.size() && found < 0; ++u)
            if (glm::length(unique[u] - m.positions[i]) < eps) found = static_cast<int>(u);
        if (found < 0) {
            found = static_cast<int>(unique.size());
            unique.push_back(m.positions[i]);
        }
        id[i] = found;
    }
    return id;
}

/// Closed, consistently oriented 2-manifold: after welding by position, every
/// directed edge (a,b) occurs exactly once and its reverse (b,a) exactly once,
/// i.e. every edge is shared by exactly two triangles that traverse it in
/// opposite directions.
void expectClosed(const Mesh& m) {
    const std::vector<int> id = weld(m, 1e-4f);
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            const int a = id[m.indices[t + k]], b = id[m.indices[t + (k + 1) % 3]];
            ASSERT_NE(a, b) << "triangle " << t / 3 << " collapses after welding";
            ++directed[{a, b}];
        }
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "->" << edge.second << " used " << count << " times";
        const auto reverse = directed.find({edge.second, edge.first});
        EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
            << "edge " << edge.first << "->" << edge.second << " has no unique opposite (hole or flipped triangle)";
    }
}

/// Enclosed volume by the divergence theorem: sum over triangles of
/// dot(a, cross(b, c)) / 6. Positive iff the closed mesh's faces point outwards.
double signedVolume(const Mesh& m) {
    double v = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
        v += glm::dot(toD(m.positions[m.indices[t]]),
                      glm::cross(toD(m.positions[m.indices[t + 1]]), toD(m.positions[m.indices[t + 2]])));
    return v / 6.0;
}

std::pair<glm::vec3, glm::vec3> bounds(const Mesh& m) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {lo, hi};
}

void expectBounds(const Mesh& m, const glm::vec3& halfExtent) {
    const auto [lo, hi] = bounds(m);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(lo[k], -halfExtent[k], 1e-5f) << "axis " << k;
        EXPECT_NEAR(hi[k], halfExtent[k], 1e-5f) << "axis " << k;
    }
}

/// Area of a regular n-gon inscribed in the unit circle: (n/2) sin(2 pi / n).
double inscribedPolygonArea(int n) { return 0.5 * n * std::sin(2.0 * kPi / n); }

/// 1 - sin(x)/x <= x^2/6: bound on the relative area deficit of an inscribed
/// regular polygon with central angle x = 2 pi / n (area ratio = sin(x)/x).
double polygonDeficitBound(int n) {
    const double x = 2.0 * kPi / n;
    return x * x / 6.0;
}

/// Float positions carry ~1e-7 relative error; volumes sum thousands of
/// such terms, so exact-geometry comparisons use 1e-5 relative tolerance.
constexpr double kRoundoff = 1e-5;

#define EXPECT_ERROR_CONTAINS(expr, text)                                                                   \
    do {                                                                                                    \
        const std::string msg_ = errorOf([&] { (void)(expr); });                                            \
        EXPECT_NE(msg_.find(text), std::string::npos) << "message: " << msg_ << "\nexpected to contain: " << (text); \
    } while (0)

// ---------------------------------------------------------------------------

TEST(ShapesTest, PlaneIsFlatUpFacingSquare) {
    const Mesh m = shapes::plane(4.0f, 2.0f);
    expectWellFormed(m);
    expectFlatNormals(m);
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.triangleCount(), 2u);
    for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
    expectBounds(m, {2.0f, 0.0f, 1.0f});
    double area = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) area += 0.5 * faceNormal(m, t).y; // > 0: faces +Y
    EXPECT_NEAR(area, 8.0, 8.0 * kRoundoff);
}

TEST(ShapesTest, BoxIsClosedFlatAndHasExactVolume) {
    const glm::vec3 size(2.0f, 3.0f, 0.5f);
    const Mesh m = shapes::box(size);
    expectWellFormed(m);
    expectFlatNormals(m);
    expectClosed(m);
    EXPECT_EQ(m.positions.size(), 24u);
    EXPECT_EQ(m.triangleCount(), 12u);
    expectBounds(m, 0.5f * size);
    EXPECT_NEAR(signedVolume(m), 3.0, 3.0 * kRoundoff);
    // Each of the 6 axis directions appears on exactly 4 vertices.
    std::map<std::tuple<float, float, float>, int> normals;
    for (const glm::vec3& n : m.normals) ++normals[{n.x, n.y, n.z}];
    EXPECT_EQ(normals.size(), 6u);
    for (const auto& [n, count] : normals) EXPECT_EQ(count, 4);
}

/// Exact volume of the UV-sphere polyhedron: ring quads are planar isosceles
/// trapezoids, so each band between rings is a frustum of a regular n-gon
/// pyramid with circumradius varying linearly in y:
/// V_band = A_n * dy * (r1^2 + r1 r2 + r2^2) / 3 with A_n the unit n-gon area.
double uvSpherePolyhedronVolume(double radius, int segments, int rings) {
    double v = 0.0;
    for (int r = 0; r < rings; ++r) {
        const double t0 = kPi * r / rings, t1 = kPi * (r + 1) / rings;
        const double r0 = radius * std::sin(t0), r1 = radius * std::sin(t1);
        const double dy = radius * (std::cos(t0) - std::cos(t1));
        v += inscribedPolygonArea(segments) * dy * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
    }
    return v;
}

TEST(ShapesTest, SphereIsClosedSmoothAndInscribed) {
    const float radius = 1.5f;
    for (const auto& [segments, rings] : {std::pair{48, 24}, std::pair{3, 2}, std::pair{7, 5}}) {
        SCOPED_TRACE("segments " + std::to_string(segments) + " rings " + std::to_string(rings));
        const Mesh m = shapes::sphere(radius, segments, rings);
        expectWellFormed(m);
        expectClosed(m);
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            EXPECT_NEAR(glm::length(m.positions[i]), radius, 1e-5f);
            EXPECT_LT(glm::length(m.normals[i] - m.positions[i] / radius), 1e-5f) << "smooth normal = radial direction";
        }
        const double volume = signedVolume(m);
        const double exact = uvSpherePolyhedronVolume(radius, segments, rings);
        EXPECT_NEAR(volume, exact, exact * kRoundoff);
        // Against the analytic ball: the mesh is convex with every vertex on
        // the sphere, so it lies inside the ball (V <= 4/3 pi R^3) and contains
        // the ball of radius d = the smallest distance from the centre to a
        // face plane (V >= 4/3 pi d^3).
        double d = radius;
        for (std::size_t t = 0; t < m.indices.size(); t += 3)
            d = std::min(d, glm::dot(glm::normalize(faceNormal(m, t)), toD(m.positions[m.indices[t]])));
        EXPECT_GT(d, 0.0);
        EXPECT_LE(volume, 4.0 / 3.0 * kPi * std::pow(radius, 3) * (1.0 + kRoundoff));
        EXPECT_GE(volume, 4.0 / 3.0 * kPi * d * d * d * (1.0 - kRoundoff));
    }
    // Default tessellation: 7.5 degree facets, the deficit is under 1 %.
    const Mesh m = shapes::sphere(radius);
    EXPECT_NEAR(signedVolume(m) / (4.0 / 3.0 * kPi * std::pow(radius, 3)), 1.0, 0.01);
    expectBounds(m, glm::vec3(radius)); // 48 segments and 24 rings hit all six extremes
}

TEST(ShapesTest, TorusIsClosedSmoothAndHasPappusVolume) {
    const float R = 2.0f, r = 0.5f;
    for (const auto& [major, minor] : {std::pair{64, 32}, std::pair{3, 3}, std::pair{10, 7}}) {
        SCOPED_TRACE("segments " + std::to_string(major) + "x" + std::to_string(minor));
        const Mesh m = shapes::torus(R, r, major, minor);
        expectWellFormed(m);
        expectClosed(m);
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            // Smooth normal: from the nearest point of the core circle to the vertex.
            const glm::vec3 p = m.positions[i];
            const glm::vec3 core = R * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
            EXPECT_NEAR(glm::length(p - core), r, 1e-5f);
            EXPECT_LT(glm::length(m.normals[i] - (p - core) / r), 1e-4f);
        }
        // The cross-section is a regular `minor`-gon (area r^2 A_minor, centroid at
        // R), swept along a `major`-gon: each wedge replaces arcs by chords, scaling
        // horizontal slices by sin(x)/x, x = 2 pi / major. By Pappus:
        // V = sin(x)/x * 2 pi R * r^2 A_minor.
        const double x = 2.0 * kPi / major;
        const double exact = std::sin(x) / x * 2.0 * kPi * R * r * r * inscribedPolygonArea(minor);
        const double volume = signedVolume(m);
        EXPECT_NEAR(volume, exact, exact * kRoundoff);
        // Analytic torus 2 pi^2 R r^2: the deficit is at most the two polygon deficits.
        const double analytic = 2.0 * kPi * kPi * R * r * r;
        EXPECT_LT(volume, analytic);
        EXPECT_GT(volume, analytic * (1.0 - polygonDeficitBound(major) - polygonDeficitBound(minor)));
    }
    expectBounds(shapes::torus(R, r), {R + r, r, R + r});
}

TEST(ShapesTest, CylinderIsClosedWithSmoothSideAndFlatCaps) {
    const float radius = 0.75f, height = 2.0f;
    for (int segments : {48, 3, 5}) {
        SCOPED_TRACE("segments " + std::to_string(segments));
        const Mesh m = shapes::cylinder(radius, height, segments);
        expectWellFormed(m);
        expectClosed(m);
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const glm::vec3 p = m.positions[i], n = m.normals[i];
            if (std::abs(n.y) > 0.5f) { // cap: flat +-Y on the matching end
                EXPECT_EQ(n, glm::vec3(0.0f, std::copysign(1.0f, p.y), 0.0f));
                EXPECT_NEAR(std::abs(p.y), height / 2, 1e-6f);
            } else { // side: radial
                EXPECT_LT(glm::length(n - glm::vec3(p.x, 0.0f, p.z) / radius), 1e-5f);
            }
        }
        // Prism over an inscribed n-gon: V = A_n R^2 h exactly; the analytic
        // pi R^2 h is larger by the polygon deficit (<= x^2/6).
        const double volume = signedVolume(m);
        const double exact = inscribedPolygonArea(segments) * radius * radius * height;
        EXPECT_NEAR(volume, exact, exact * kRoundoff);
        const double analytic = kPi * radius * radius * height;
        EXPECT_LT(volume, analytic);
        EXPECT_GT(volume, analytic * (1.0 - polygonDeficitBound(segments)));
    }
    expectBounds(shapes::cylinder(radius, height), {radius, height / 2, radius});
}

TEST(ShapesTest, ConeIsClosedWithSlantedNormals) {
    const float radius = 1.0f, height = 3.0f;
    for (int segments : {48, 3, 6}) {
        SCOPED_TRACE("segments " + std::to_string(segments));
        const Mesh m = shapes::cone(radius, height, segments);
        expectWellFormed(m);
        expectClosed(m);
        // The side makes slope (-R, h) in the (radial, y) plane, so its unit
        // normal has y = R / sqrt(R^2 + h^2) and a radial horizontal part.
        const float ny = radius / std::sqrt(radius * radius + height * height);
        int apexVertices = 0;
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            const glm::vec3 p = m.positions[i], n = m.normals[i];
            if (n.y < -0.5f) { // base cap
                EXPECT_EQ(n, glm::vec3(0, -1, 0));
                EXPECT_NEAR(p.y, -height / 2, 1e-6f);
                continue;
            }
            EXPECT_NEAR(n.y, ny, 1e-5f);
            if (p.y > 0.0f) {
                ++apexVertices;
                EXPECT_EQ(p, glm::vec3(0.0f, height / 2, 0.0f));
            } else { // base ring: horizontal part of the normal points along p
                const glm::vec2 radial = glm::normalize(glm::vec2(p.x, p.z));
                EXPECT_LT(glm::length(glm::normalize(glm::vec2(n.x, n.z)) - radial), 1e-5f);
            }
        }
        EXPECT_EQ(apexVertices, segments) << "one apex vertex per segment";
        // Pyramid over an inscribed n-gon: V = A_n R^2 h / 3 exactly.
        const double volume = signedVolume(m);
        const double exact = inscribedPolygonArea(segments) * radius * radius * height / 3.0;
        EXPECT_NEAR(volume, exact, exact * kRoundoff);
        const double analytic = kPi * radius * radius * height / 3.0;
        EXPECT_LT(volume, analytic);
        EXPECT_GT(volume, analytic * (1.0 - polygonDeficitBound(segments)));
    }
    expectBounds(shapes::cone(radius, height), {radius, height / 2, radius});
}

TEST(ShapesTest, PyramidIsClosedFlatWithEighteenVertices) {
    const float width = 2.0f, height = 1.5f;
    const Mesh m = shapes::pyramid(width, height);
    expectWellFormed(m);
    expectFlatNormals(m);
    expectClosed(m);
    EXPECT_EQ(m.positions.size(), 18u);
    EXPECT_EQ(m.triangleCount(), 6u);
    expectBounds(m, {width / 2, height / 2, width / 2});
    EXPECT_NEAR(signedVolume(m), width * width * height / 3.0, kRoundoff);
    // Side normals tilt up: (0, w/2, h) normalised for the +Z face.
    const glm::vec3 side = glm::normalize(glm::vec3(0.0f, width / 2, height));
    int found = 0;
    for (const glm::vec3& n : m.normals) found += glm::length(n - side) < 1e-5f;
    EXPECT_EQ(found, 3);
}

TEST(ShapesTest, NamesAreSet) {
    EXPECT_EQ(shapes::plane(1, 1).name, "plane");
    EXPECT_EQ(shapes::box(glm::vec3(1)).name, "box");
    EXPECT_EQ(shapes::sphere(1).name, "sphere");
    EXPECT_EQ(shapes::torus(2, 1).name, "torus");
    EXPECT_EQ(shapes::cylinder(1, 1).name, "cylinder");
    EXPECT_EQ(shapes::cone(1, 1).name, "cone");
    EXPECT_EQ(shapes::pyramid(1, 1).name, "pyramid");
}

TEST(ShapesTest, BadSizesThrow) {
    for (float bad : {0.0f, -1.0f, kNaN, kInf, -kInf}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(shapes::plane(bad, 1), shadowlab::Error);
        EXPECT_THROW(shapes::plane(1, bad), shadowlab::Error);
        EXPECT_THROW(shapes::box({bad, 1, 1}), shadowlab::Error);
        EXPECT_THROW(shapes::box({1, bad, 1}), shadowlab::Error);
        EXPECT_THROW(shapes::box({1, 1, bad}), shadowlab::Error);
        EXPECT_THROW(shapes::sphere(bad), shadowlab::Error);
        EXPECT_THROW(shapes::torus(bad, 1), shadowlab::Error);
        EXPECT_THROW(shapes::torus(2, bad), shadowlab::Error);
        EXPECT_THROW(shapes::cylinder(bad, 1), shadowlab::Error);
        EXPECT_THROW(shapes::cylinder(1, bad), shadowlab::Error);
        EXPECT_THROW(shapes::cone(bad, 1), shadowlab::Error);
        EXPECT_THROW(shapes::cone(1, bad), shadowlab::Error);
        EXPECT_THROW(shapes::pyramid(bad, 1), shadowlab::Error);
        EXPECT_THROW(shapes::pyramid(1, bad), shadowlab::Error);
    }
    EXPECT_ERROR_CONTAINS(shapes::torus(2, -1), "torus: minorRadius must be finite and > 0, got -1");
    EXPECT_ERROR_CONTAINS(shapes::plane(1, kNaN), "plane: depth must be finite and > 0, got nan");
    EXPECT_ERROR_CONTAINS(shapes::box({1, 0, 1}), "box: size.y must be finite and > 0, got 0");
    EXPECT_ERROR_CONTAINS(shapes::cone(1, kInf), "cone: height must be finite and > 0, got inf");
    EXPECT_ERROR_CONTAINS(shapes::pyramid(-2, 1), "pyramid: baseWidth must be finite and > 0, got -2");
}

TEST(ShapesTest, TooFewSegmentsThrow) {
    EXPECT_ERROR_CONTAINS(shapes::sphere(1, 2, 4), "sphere: segments must be >= 3, got 2");
    EXPECT_ERROR_CONTAINS(shapes::sphere(1, 8, 1), "sphere: rings must be >= 2, got 1");
    EXPECT_ERROR_CONTAINS(shapes::torus(2, 1, 2, 8), "torus: majorSegments must be >= 3, got 2");
    EXPECT_ERROR_CONTAINS(shapes::torus(2, 1, 8, -5), "torus: minorSegments must be >= 3, got -5");
    EXPECT_ERROR_CONTAINS(shapes::cylinder(1, 1, 0), "cylinder: segments must be >= 3, got 0");
    EXPECT_ERROR_CONTAINS(shapes::cone(1, 1, 2), "cone: segments must be >= 3, got 2");
}

TEST(ShapesTest, TorusMajorRadiusMustExceedMinor) {
    EXPECT_ERROR_CONTAINS(shapes::torus(1, 1), "torus: majorRadius (1) must be greater than minorRadius (1)");
    EXPECT_ERROR_CONTAINS(shapes::torus(0.5f, 1), "torus: majorRadius (0.5) must be greater than minorRadius (1)");
}

} // namespace
