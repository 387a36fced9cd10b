// Procedural meshes (see Shapes.h).
//
// Conventions shared by every shape:
//  - counter-clockwise front faces seen from outside, i.e. for a triangle
//    (a, b, c) the geometric normal cross(b - a, c - a) points outwards;
//  - angles around Y run from +X towards -Z, so u increases to the right
//    when a surface is seen from outside;
//  - uv v = 0 is the top of the image (glTF convention; ImageRGBA8 rows are
//    stored top to bottom), so v grows downwards on the surface.
#include <shadowlab/Shapes.h>

#include <shadowlab/Error.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

namespace shadowlab::shapes {
namespace {

constexpr float kTwoPi = glm::two_pi<float>();
constexpr float kPi = glm::pi<float>();

void requireSize(const char* shape, const char* what, float value) {
    if (!std::isfinite(value) || value <= 0.0f) {
        std::ostringstream msg;
        msg << shape << ": " << what << " must be finite and > 0, got " << value;
        throw Error(msg.str());
    }
}

void requireSegments(const char* shape, const char* what, int value, int minimum) {
    if (value < minimum) {
        throw Error(std::string(shape) + ": " + what + " must be >= " + std::to_string(minimum) +
                    ", got " + std::to_string(value));
    }
}

/// Accumulates vertices and triangles into a Mesh.
struct Builder {
    Mesh mesh;

    explicit Builder(std::string name) { mesh.name = std::move(name); }

    std::uint32_t vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
        mesh.positions.push_back(p);
        mesh.normals.push_back(glm::normalize(n));
        mesh.uvs.push_back(uv);
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    }

    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }

    /// Flat rectangle centred at `c` spanning c +- s +- t; front side faces
    /// cross(s, t). `s` points right and `t` up when seen from the front.
    void rectangle(const glm::vec3& c, const glm::vec3& s, const glm::vec3& t) {
        const glm::vec3 n = glm::cross(s, t);
        const std::uint32_t i0 = vertex(c - s - t, n, {0.0f, 1.0f});
        const std::uint32_t i1 = vertex(c + s - t, n, {1.0f, 1.0f});
        const std::uint32_t i2 = vertex(c + s + t, n, {1.0f, 0.0f});
        const std::uint32_t i3 = vertex(c - s + t, n, {0.0f, 0.0f});
        triangle(i0, i1, i2);
        triangle(i0, i2, i3);
    }

    /// Flat disc (triangle fan) of `segments` sides at height y, facing +Y
    /// (up = true) or -Y. uvs are a planar projection seen from the front.
    void disc(float radius, float y, int segments, bool up) {
        const glm::vec3 n{0.0f, up ? 1.0f : -1.0f, 0.0f};
        // Seen from above, image up is -Z; seen from below it is +Z.
        const float vSign = up ? 1.0f : -1.0f;
        const std::uint32_t centre = vertex({0.0f, y, 0.0f}, n, {0.5f, 0.5f});
        const std::uint32_t first = static_cast<std::uint32_t>(mesh.positions.size());
        for (int i = 0; i < segments; ++i) {
            const glm::vec2 d = direction(i, segments);
            vertex({radius * d.x, y, radius * d.y}, n, {0.5f + 0.5f * d.x, 0.5f + 0.5f * vSign * d.y});
        }
        for (int i = 0; i < segments; ++i) {
            const std::uint32_t a = first + static_cast<std::uint32_t>(i);
            const std::uint32_t b = first + static_cast<std::uint32_t>((i + 1) % segments);
            // Ring order turns from +X towards -Z: counter-clockwise seen from +Y.
            if (up) triangle(centre, a, b);
            else triangle(centre, b, a);
        }
    }

    /// Unit direction in XZ (as x, z) of segment boundary i of n: angle 2*pi*i/n
    /// measured from +X towards -Z.
    /// Direction of segment i of n around a circle; i == n is i == 0 exactly
    /// (the seam's positions coincide bit for bit, so the mesh is closed).
    static glm::vec2 direction(int i, int n) {
        const float phi = kTwoPi * static_cast<float>(i % n) / static_cast<float>(n);
        return {std::cos(phi), -std::sin(phi)};
    }
};

float ratio(int i, int n) { return static_cast<float>(i) / static_cast<float>(n); }

} // namespace

Mesh plane(float width, float depth) {
    requireSize("plane", "width", width);
    requireSize("plane", "depth", depth);
    Builder b("plane");
    // Seen from above: right = +X, up = -Z, so the normal is X x -Z = +Y.
    b.rectangle({0.0f, 0.0f, 0.0f}, {0.5f * width, 0.0f, 0.0f}, {0.0f, 0.0f, -0.5f * depth});
    return std::move(b.mesh);
}

Mesh disc(float radius, int segments) {
    requireSize("disc", "radius", radius);
    requireSegments("disc", "segments", segments, 3);
    Builder b("disc");
    b.disc(radius, 0.0f, segments, true);
    return std::move(b.mesh);
}

Mesh box(const glm::vec3& size) {
    requireSize("box", "size.x", size.x);
    requireSize("box", "size.y", size.y);
    requireSize("box", "size.z", size.z);
    const glm::vec3 h = 0.5f * size;
    Builder b("box");
    // One rectangle per face: centre, right, up with right x up = outward normal.
    b.rectangle({h.x, 0, 0}, {0, 0, -h.z}, {0, h.y, 0});  // +X
    b.rectangle({-h.x, 0, 0}, {0, 0, h.z}, {0, h.y, 0});  // -X
    b.rectangle({0, h.y, 0}, {h.x, 0, 0}, {0, 0, -h.z});  // +Y
    b.rectangle({0, -h.y, 0}, {h.x, 0, 0}, {0, 0, h.z});  // -Y
    b.rectangle({0, 0, h.z}, {h.x, 0, 0}, {0, h.y, 0});   // +Z
    b.rectangle({0, 0, -h.z}, {-h.x, 0, 0}, {0, h.y, 0}); // -Z
    return std::move(b.mesh);
}

Mesh sphere(float radius, int segments, int rings) {
    requireSize("sphere", "radius", radius);
    requireSegments("sphere", "segments", segments, 3);
    requireSegments("sphere", "rings", rings, 2);
    Builder b("sphere");
    // Latitude theta in [0, pi] from the north pole; u = segment, v = ring.
    // Each pole gets one vertex per segment so its fan triangles get their own u.
    const std::uint32_t north = static_cast<std::uint32_t>(b.mesh.positions.size());
    for (int s = 0; s < segments; ++s)
        b.vertex({0, radius, 0}, {0, 1, 0}, {(static_cast<float>(s) + 0.5f) / static_cast<float>(segments), 0.0f});
    const std::uint32_t firstRing = static_cast<std::uint32_t>(b.mesh.positions.size());
    for (int r = 1; r < rings; ++r) {
        const float theta = kPi * ratio(r, rings);
        for (int s = 0; s <= segments; ++s) { // s == segments duplicates s == 0 (uv seam)
            const glm::vec2 d = Builder::direction(s, segments);
            const glm::vec3 n{std::sin(theta) * d.x, std::cos(theta), std::sin(theta) * d.y};
            b.vertex(radius * n, n, {ratio(s, segments), ratio(r, rings)});
        }
    }
    const std::uint32_t south = static_cast<std::uint32_t>(b.mesh.positions.size());
    for (int s = 0; s < segments; ++s)
        b.vertex({0, -radius, 0}, {0, -1, 0}, {(static_cast<float>(s) + 0.5f) / static_cast<float>(segments), 1.0f});

    const auto at = [&](int r, int s) { // ring r in [1, rings-1]
        return firstRing + static_cast<std::uint32_t>((r - 1) * (segments + 1) + s);
    };
    const auto u32 = [](int i) { return static_cast<std::uint32_t>(i); };
    for (int s = 0; s < segments; ++s) {
        // Quad (a, b = below a, c = below-right, d = right); right is -Z at +X,
        // and (below) x (right) = (-Y) x (-Z) = +X points outwards.
        b.triangle(north + u32(s), at(1, s), at(1, s + 1));
        for (int r = 1; r < rings - 1; ++r) {
            b.triangle(at(r, s), at(r + 1, s), at(r + 1, s + 1));
            b.triangle(at(r, s), at(r + 1, s + 1), at(r, s + 1));
        }
        b.triangle(at(rings - 1, s), south + u32(s), at(rings - 1, s + 1));
    }
    return std::move(b.mesh);
}

Mesh torus(float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
    requireSize("torus", "majorRadius", majorRadius);
    requireSize("torus", "minorRadius", minorRadius);
    if (!(majorRadius > minorRadius)) {
        std::ostringstream msg;
        msg << "torus: majorRadius (" << majorRadius << ") must be greater than minorRadius (" << minorRadius << ")";
        throw Error(msg.str());
    }
    requireSegments("torus", "majorSegments", majorSegments, 3);
    requireSegments("torus", "minorSegments", minorSegments, 3);
    Builder b("torus");
    // Point = tube centre R*radial + r*n with n = cos(theta)*radial + sin(theta)*Y,
    // theta measured from the outer equator upwards; n is the exact normal.
    for (int i = 0; i <= majorSegments; ++i) {
        const glm::vec2 d = Builder::direction(i, majorSegments);
        const glm::vec3 radial{d.x, 0.0f, d.y};
        for (int j = 0; j <= minorSegments; ++j) {
            const float theta = kTwoPi * ratio(j % minorSegments, minorSegments);  // j == minorSegments is j == 0 exactly
            const glm::vec3 n = std::cos(theta) * radial + glm::vec3(0.0f, std::sin(theta), 0.0f);
            b.vertex(majorRadius * radial + minorRadius * n, n, {ratio(i, majorSegments), ratio(j, minorSegments)});
        }
    }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (minorSegments + 1) + j); };
    for (int i = 0; i < majorSegments; ++i) {
        for (int j = 0; j < minorSegments; ++j) {
            // At the outer equator i+1 is towards -Z and j+1 towards +Y:
            // (-Z) x (+Y) = +X points out of the tube.
            b.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            b.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
    return std::move(b.mesh);
}

namespace {
// A solid of revolution about +Y (cylinder, cone): its sizes checked, and
// its bottom and top heights, centred on the origin.
struct Revolution {
    float y0, y1;
    Revolution(const char* shape, float radius, float height, int segments) : y0(-0.5f * height), y1(0.5f * height) {
        requireSize(shape, "radius", radius);
        requireSize(shape, "height", height);
        requireSegments(shape, "segments", segments, 3);
    }
};
} // namespace

Mesh cylinder(float radius, float height, int segments) {
    const auto [y0, y1] = Revolution("cylinder", radius, height, segments);
    Builder b("cylinder");
    // Side: two rows of segments+1 vertices (seam duplicated), radial normals.
    for (int s = 0; s <= segments; ++s) {
        const glm::vec2 d = Builder::direction(s, segments);
        const glm::vec3 n{d.x, 0.0f, d.y};
        b.vertex({radius * d.x, y0, radius * d.y}, n, {ratio(s, segments), 1.0f});
        b.vertex({radius * d.x, y1, radius * d.y}, n, {ratio(s, segments), 0.0f});
    }
    for (int s = 0; s < segments; ++s) {
        const auto bottom = [](int k) { return static_cast<std::uint32_t>(2 * k); };
        const auto top = [](int k) { return static_cast<std::uint32_t>(2 * k + 1); };
        b.triangle(bottom(s), bottom(s + 1), top(s + 1));
        b.triangle(bottom(s), top(s + 1), top(s));
    }
    b.disc(radius, y1, segments, true);
    b.disc(radius, y0, segments, false);
    return std::move(b.mesh);
}

Mesh cone(float radius, float height, int segments) {
    const auto [y0, y1] = Revolution("cone", radius, height, segments);
    Builder b("cone");
    // The side surface of a cone of radius R and height h makes the slant
    // (-R, h) in the (radial, y) plane; the outward normal is perpendicular:
    // (h, R) normalised, i.e. h*radial + R*Y.
    const auto slantNormal = [&](float phi) {
        return glm::vec3(height * std::cos(phi), radius, -height * std::sin(phi));
    };
    const std::uint32_t base = static_cast<std::uint32_t>(b.mesh.positions.size());
    for (int s = 0; s <= segments; ++s) {
        const glm::vec2 d = Builder::direction(s, segments);
        b.vertex({radius * d.x, y0, radius * d.y}, slantNormal(kTwoPi * ratio(s, segments)), {ratio(s, segments), 1.0f});
    }
    // The apex normal is undefined; one apex vertex per segment carries the
    // normal of the segment's mid angle, which keeps shading smooth around.
    const std::uint32_t apex = static_cast<std::uint32_t>(b.mesh.positions.size());
    for (int s = 0; s < segments; ++s) {
        const float mid = (static_cast<float>(s) + 0.5f) / static_cast<float>(segments);
        b.vertex({0.0f, y1, 0.0f}, slantNormal(kTwoPi * mid), {mid, 0.0f});
    }
    for (int s = 0; s < segments; ++s) {
        const std::uint32_t i = static_cast<std::uint32_t>(s);
        b.triangle(base + i, base + i + 1, apex + i);
    }
    b.disc(radius, y0, segments, false);
    return std::move(b.mesh);
}

Mesh pyramid(float baseWidth, float height) {
    requireSize("pyramid", "baseWidth", baseWidth);
    requireSize("pyramid", "height", height);
    Builder b("pyramid");
    const float h = 0.5f * baseWidth;
    const float y0 = -0.5f * height;
    const glm::vec3 apex{0.0f, 0.5f * height, 0.0f};
    // Base: two triangles with their own vertices (6), facing -Y.
    {
        const glm::vec3 n{0, -1, 0};
        const glm::vec3 p0{-h, y0, -h}, p1{h, y0, -h}, p2{h, y0, h}, p3{-h, y0, h};
        // Seen from below, right = +X and up = +Z (so uv v = 0 at +Z).
        const auto uv = [&](const glm::vec3& p) { return glm::vec2(0.5f + 0.5f * p.x / h, 0.5f - 0.5f * p.z / h); };
        const std::uint32_t a = b.vertex(p0, n, uv(p0)), c = b.vertex(p1, n, uv(p1)), d = b.vertex(p2, n, uv(p2));
        b.triangle(a, c, d);
        const std::uint32_t e = b.vertex(p0, n, uv(p0)), f = b.vertex(p2, n, uv(p2)), g = b.vertex(p3, n, uv(p3));
        b.triangle(e, f, g);
    }
    // Sides: for outward direction `out`, the base edge runs left -> right
    // seen from outside (right = Y x out); flat normal cross(right edge, to apex).
    for (const glm::vec3 out : {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(-1, 0, 0)}) {
        const glm::vec3 right = glm::cross(glm::vec3(0, 1, 0), out);
        const glm::vec3 left = glm::vec3(0, y0, 0) + h * out - h * right;
        const glm::vec3 rightCorner = glm::vec3(0, y0, 0) + h * out + h * right;
        const glm::vec3 n = glm::cross(rightCorner - left, apex - left);
        const std::uint32_t i0 = b.vertex(left, n, {0.0f, 1.0f});
        const std::uint32_t i1 = b.vertex(rightCorner, n, {1.0f, 1.0f});
        const std::uint32_t i2 = b.vertex(apex, n, {0.5f, 0.0f});
        b.triangle(i0, i1, i2);
    }
    return std::move(b.mesh);
}

} // namespace shadowlab::shapes
