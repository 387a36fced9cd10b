// A node's `shape` in a scene file: the procedural meshes (shapes::plane,
// box, sphere, torus, cylinder, cone, disc, pyramid), every parameter
// checked with its JSON path before the mesh is made.
#include "scene/SceneParts.h"

#include <shadowlab/Error.h>
#include <shadowlab/Shapes.h>

namespace shadowlab::scenefile {

using overrides::typeName;

namespace {

glm::vec2 sizeOf2(const Reader& r) {
    if (!r.value().is_array() || r.value().size() != 2)
        r.fail(std::string("expected 2 numbers [width, depth], got ") +
               (r.value().is_array() ? std::to_string(r.value().size()) : typeName(r.value())));
    const glm::vec2 s(r.element(0).number(), r.element(1).number());
    if (s.x <= 0 || s.y <= 0) r.fail("expected 2 numbers > 0");
    return s;
}

Mesh makeShape(const Reader& r) {
    r.requireObject();
    if (!r.has("type")) r.fail("missing key 'type' (plane, box, sphere, torus, cylinder, cone or pyramid)");
    const std::string type = r.child("type").string();
    // Segment counts stop at kMaxSegments: enough for any smooth shape, and
    // a typo like 1000000000 cannot exhaust memory.
    constexpr int kMaxSegments = 1024;
    // Parameters are validated here with their JSON paths; the shape
    // functions' own checks (segment minimums) then cannot fire, but if
    // one does its message is attached to this shape's path.
    auto build = [&](auto&& make) -> Mesh {
        try {
            return make();
        } catch (const Error& e) {
            r.fail(e.what());
        }
    };
    if (type == "plane") {
        r.checkKeys({"type", "size"});
        const glm::vec2 s = r.has("size") ? sizeOf2(r.child("size")) : glm::vec2(10.0f);
        return build([&] { return shapes::plane(s.x, s.y); });
    }
    if (type == "box") {
        r.checkKeys({"type", "size"});
        const glm::vec3 s = r.vec3("size", glm::vec3(1.0f));
        if (s.x <= 0 || s.y <= 0 || s.z <= 0) r.child("size").fail("expected 3 numbers > 0");
        return build([&] { return shapes::box(s); });
    }
    if (type == "sphere") {
        r.checkKeys({"type", "radius", "segments", "rings"});
        const float radius = r.positive("radius", 1.0f);
        const int segments = r.integer("segments", 48, 3, kMaxSegments), rings = r.integer("rings", 24, 2, kMaxSegments);
        return build([&] { return shapes::sphere(radius, segments, rings); });
    }
    if (type == "torus") {
        r.checkKeys({"type", "majorRadius", "minorRadius", "majorSegments", "minorSegments"});
        const float major = r.positive("majorRadius", 1.0f), minor = r.positive("minorRadius", 0.3f);
        if (minor >= major) r.fail("expected minorRadius < majorRadius");
        const int majorSegments = r.integer("majorSegments", 64, 3, kMaxSegments), minorSegments = r.integer("minorSegments", 32, 3, kMaxSegments);
        return build([&] { return shapes::torus(major, minor, majorSegments, minorSegments); });
    }
    if (type == "cylinder" || type == "cone") {
        r.checkKeys({"type", "radius", "height", "segments"});
        const float radius = r.positive("radius", 0.5f), height = r.positive("height", 1.0f);
        const int segments = r.integer("segments", 48, 3, kMaxSegments);
        return build([&] {
            return type == "cylinder" ? shapes::cylinder(radius, height, segments) : shapes::cone(radius, height, segments);
        });
    }
    if (type == "disc") {
        r.checkKeys({"type", "radius", "segments"});
        const float radius = r.positive("radius", 0.5f);
        const int segments = r.integer("segments", 128, 3, kMaxSegments);
        return build([&] { return shapes::disc(radius, segments); });
    }
    if (type == "pyramid") {
        r.checkKeys({"type", "baseWidth", "height"});
        const float width = r.positive("baseWidth", 1.0f), height = r.positive("height", 1.0f);
        return build([&] { return shapes::pyramid(width, height); });
    }
    r.child("type").fail("unknown shape '" + type + "' (expected plane, disc, box, sphere, torus, cylinder, cone or pyramid)");
}

} // namespace

Mesh readShape(const Reader& r, std::size_t& trianglesLeft) {
    // One shape is at most 2 x 1024 x 1024 triangles (kMaxSegments), about
    // 100 MB made: the budget is of the scene's shapes together.
    Mesh mesh = makeShape(r);
    const std::size_t triangles = mesh.triangleCount();
    if (triangles > trianglesLeft)
        r.fail("this shape makes " + std::to_string(triangles) + " triangles, past what a scene may hold in all (" + std::to_string(kMaxShapeTriangles) +
               " triangles of shapes and mesh files; " + std::to_string(trianglesLeft) + " left): fewer segments");
    trianglesLeft -= triangles;
    return mesh;
}

} // namespace shadowlab::scenefile
