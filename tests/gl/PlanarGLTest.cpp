// Technique "planar" (projected planar shadows, Wolberg's lecture): the analytic
// shadow of a box, one darkening where shadows overlap, the receiver's
// edge, no anti-shadows, the two projections, the reference, bad options.
#include "GLTestContext.h"
#include "Comparisons.h"
#include "ImageArtifacts.h"
#include "geometry/Plane.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include <filesystem>

using namespace shadowlab;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

struct Frame {
    ImageRGBA8 color;
    std::vector<float> visibility;
    SurfaceBuffer surfaces;
};

Frame renderScene(const Scene& scene, int width = 480, int height = 270) {
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.surfaces = true;
    renderer.render(scene, options);
    return {renderer.readColor(), renderer.readVisibility(scene, 0), renderer.readSurfaces()};
}

Scene planarScene(const std::string& light, const std::string& nodes, const std::string& options = "") {
    return parseScene(R"({"camera": {"position": [0, 9, 7], "target": [0, 0, 0]}, "ambient": [0.2, 0.2, 0.2],
      "lights": [)" + light.substr(0, light.size() - 1) + R"(, "shadow": {"technique": "planar", "planar": {)" + options + R"(}}}],
      "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [16, 16]}})" + nodes + "]}",
                      "planar", ".");
}

// 2-D convex hull (monotone chain) and point-in-hull, in double precision.
using P2 = glm::dvec2;
double cross(P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }
std::vector<P2> hull(std::vector<P2> p) {
    std::sort(p.begin(), p.end(), [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<P2> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}
bool inside(const std::vector<P2>& h, P2 q) {
    for (std::size_t i = 0; i < h.size(); ++i)
        if (cross(h[i], h[(i + 1) % h.size()], q) < 0) return false;
    return true;
}

} // namespace

class PlanarGLTest : public GLTest {};

// The shadow of a box on the floor under a sun is the convex hull of its
// eight corners projected along the light onto y = 0. Every floor pixel
// whose 8 neighbours agree with it on that hull (away from the 1-pixel
// band) must be shadowed exactly when its centre's surface point is inside.
TEST_F(PlanarGLTest, ABoxShadowIsTheProjectionOfItsCorners) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.5, -1.0, -0.3));
    const glm::dvec3 centre(0.5, 1.2, -0.4), half(0.6, 0.7, 0.5);  // unrotated: corners are easy
    const Scene scene = planarScene(R"({"type": "directional", "direction": [0.5, -1, -0.3]})",
                                    R"(, {"name": "box", "shape": {"type": "box", "size": [1.2, 1.4, 1.0]}, "translation": [0.5, 1.2, -0.4]})");
    std::vector<P2> corners;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p = centre + glm::dvec3((c & 1) ? half.x : -half.x, (c & 2) ? half.y : -half.y, (c & 4) ? half.z : -half.z);
        const double t = -p.y / d.y;  // along the light to y = 0
        corners.push_back({p.x + t * d.x, p.z + t * d.z});
    }
    const std::vector<P2> shadow = hull(corners);
    const Frame f = renderScene(scene, 1280, 720);
    const int w = f.surfaces.width, h = f.surfaces.height;
    auto floorShadowed = [&](int x, int y, bool& onFloor) {
        const glm::vec4& p = f.surfaces.position[static_cast<std::size_t>(y) * w + x];
        onFloor = p.w > 0.5f && std::abs(p.y) < 1e-4f;
        return inside(shadow, {p.x, p.z});
    };
    std::size_t checked = 0, shadowed = 0, wrong = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            bool onFloor = false;
            const bool expected = floorShadowed(x, y, onFloor);
            if (!onFloor) continue;
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    bool neighbourOnFloor = false;
                    edge = edge || floorShadowed(x + dx, y + dy, neighbourOnFloor) != expected || !neighbourOnFloor;
                }
            if (edge) continue;
            ++checked;
            shadowed += expected;
            wrong += (f.visibility[static_cast<std::size_t>(y) * w + x] < 0.5f) != expected;
        }
    EXPECT_GT(checked, 50000u);
    EXPECT_GT(shadowed, 2000u) << "the shadow is in view";
    EXPECT_EQ(wrong, 0u);
}

// Two casters whose shadows overlap: with the stencil every shadowed floor
// pixel has the same colour (the ambient term alone, under a sun); the
// lecture's style darkens the overlap twice.
TEST_F(PlanarGLTest, OverlappingShadowsDarkenOnceWithTheStencilAndTwiceInTheLecturesStyle) {
    const std::string sun = R"({"type": "directional", "direction": [0, -1, 0.05]})";
    const std::string boxes = R"(, {"name": "a", "shape": {"type": "box", "size": [2, 0.5, 2]}, "translation": [-0.5, 2, 0]},
                                 {"name": "b", "shape": {"type": "box", "size": [2, 0.5, 2]}, "translation": [0.5, 3, 0.3]})";
    for (const char* style : {"stencil", "lecture"}) {
        SCOPED_TRACE(style);
        const Frame f = renderScene(planarScene(sun, boxes, std::string(R"("style": ")") + style + "\""));
        // Floor points under one box only, and under both (the boxes' x overlap is [-0.5, 0.5]).
        auto colourAt = [&](double x0, double x1, double z0, double z1) {
            double sum = 0.0;
            std::size_t n = 0;
            for (std::size_t i = 0; i < f.surfaces.position.size(); ++i) {
                const glm::vec4& p = f.surfaces.position[i];
                if (p.w < 0.5f || std::abs(p.y) > 1e-4f || p.x < x0 || p.x > x1 || p.z < z0 || p.z > z1) continue;
                sum += f.color.pixels[4 * i + 1];
                ++n;
            }
            EXPECT_GT(n, 50u);
            return n ? sum / static_cast<double>(n) : 0.0;
        };
        // The shadows fall a little towards +z (0.05 per unit of height).
        const double single = colourAt(-1.3, -0.7, -0.5, 0.8), both = colourAt(-0.3, 0.3, 0.0, 0.8), lit = colourAt(3.0, 5.0, 3.0, 5.0);
        EXPECT_LT(single, lit - 20.0) << "a shadow at all";
        if (std::string(style) == "stencil")
            // Under a sun a shadowed floor pixel is the ambient term alone, the
            // same 8-bit value everywhere; 0.5 of a level allows only rounding.
            EXPECT_NEAR(both, single, 0.5) << "the overlap darkened once";
        else
            EXPECT_LT(both, single - 10.0) << "the lecture's look: darkened twice";
    }
}

// A small floor under a large caster: the stencil keeps the shadow on the
// floor, so the background next to it is exactly as without a caster; the
// lecture's style (no stencil, the infinite plane) spills over it.
TEST_F(PlanarGLTest, TheShadowStopsAtTheReceiversEdge) {
    auto scene = [](const std::string& nodes, const std::string& options) {
        return parseScene(R"({"camera": {"position": [0, 9, 7], "target": [0, 0, 0]}, "background": [0.5, 0.5, 0.5],
          "lights": [{"type": "directional", "direction": [0.3, -1, 0.2], "shadow": {"technique": "planar", "planar": {)" + options + R"(}}}],
          "nodes": [{"name": "floor", "shape": {"type": "plane", "size": [2, 2]}})" + nodes + "]}",
                          "edge", ".");
    };
    const std::string caster = R"(, {"name": "slab", "shape": {"type": "box", "size": [5, 0.2, 5]}, "translation": [0, 3, 0], "receivesShadows": false}, {"name": "below", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [0, -5, 0]})";
    const Frame without = renderScene(scene("", ""));
    const Frame with = renderScene(scene(caster, ""));
    const Frame lecture = renderScene(scene(caster, R"("style": "lecture")"));
    std::size_t background = 0, changed = 0, spilled = 0, floorShadowed = 0;
    for (std::size_t i = 0; i < with.surfaces.position.size(); ++i) {
        const bool floorPixel = with.surfaces.position[i].w > 0.5f && std::abs(with.surfaces.position[i].y) < 1e-4f;
        if (floorPixel) floorShadowed += with.visibility[i] < 0.5f;
        if (with.surfaces.position[i].w > 0.5f || without.surfaces.position[i].w > 0.5f) continue;  // the background only
        ++background;
        changed += with.color.pixels[4 * i] != without.color.pixels[4 * i];
        spilled += lecture.color.pixels[4 * i] != without.color.pixels[4 * i];
    }
    EXPECT_GT(floorShadowed, 500u) << "the floor is in the slab's shadow";
    EXPECT_GT(background, 10000u);
    EXPECT_EQ(changed, 0u);
    EXPECT_GT(spilled, 1000u) << "the lecture's dark polygons cover the infinite plane";
}

// A pillar that reaches above the lamp would project its upper part
// through infinity to an anti-shadow on the far side, and a crate sunk
// half into the floor its lower half onto the floor's top: both parts are
// clipped (projected w < 0, and below the plane), so the floor's shadows
// match the reference exactly away from the edge band.
TEST_F(PlanarGLTest, NoAntiShadowsAndNothingFromBelowThePlane) {
    const Scene scene = planarScene(R"({"type": "point", "position": [0, 2, 0]})",
                                    R"(, {"name": "pillar", "shape": {"type": "box", "size": [0.4, 2, 0.4]}, "translation": [1, 2, 0], "receivesShadows": false},
                                       {"name": "sunk", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [-2, 0, 1], "rotation": [0, 30, 0], "receivesShadows": false})");
    const Comparison c = test::compareScene(scene, 640, 360);
    EXPECT_GT(c.lights[0].referenceShadowedPixels, 2000u);
    EXPECT_EQ(test::awayFromEdges(c.lights[0]), 0.0);
    if (HasFailure()) test::saveImagesIfFailed("anti-shadow", c.technique, c.reference);
}

// Against the ray-traced reference, on scenes whose only receivers are
// planes: no misclassified pixel away from the edge band; and the geometry
// shader's projection gives the very same image as the vertex shader's.
TEST_F(PlanarGLTest, PlanesOnlyMatchTheReferenceAndBothProjectionsAgree) {
    for (const char* name : {"two-boxes-sun", "room-point", "slide-projector"}) {
        SCOPED_TRACE(name);
        const fs::path file = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / (std::string(name) + ".json");
        const Scene plain = loadSceneFile(file);
        std::vector<std::string> overrides = {"lights[0].shadow.technique=planar"};
        for (std::size_t n = 0; n < plain.nodes.size(); ++n)
            if (plain.nodes[n].mesh >= 0 && !meshPlane(plain.meshes[static_cast<std::size_t>(plain.nodes[n].mesh)]))
                overrides.push_back("nodes[" + std::to_string(n) + "].receivesShadows=false");
        const Scene scene = loadSceneFile(file, overrides);
        const Comparison c = test::compareScene(scene, 640, 360);
        EXPECT_GT(c.lights[0].referenceShadowedPixels, 1000u);
        EXPECT_EQ(test::awayFromEdges(c.lights[0]), 0.0);
        overrides.push_back("lights[0].shadow.planar.projection=\"geometry\"");
        const Frame geometry = renderScene(loadSceneFile(file, overrides), 640, 360);
        const Frame vertex = renderScene(scene, 640, 360);
        EXPECT_EQ(geometry.color.pixels, vertex.color.pixels);
    }
}

TEST_F(PlanarGLTest, ReceiversMustBeNamedPlanarNodes) {
    const std::string light = R"({"type": "directional", "direction": [0, -1, 0]})";
    const std::string box = R"(, {"name": "box", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [0, 2, 0]})";
    try {
        renderScene(planarScene(light, box, R"("receivers": "floor, nowhere")"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "lights[0].shadow.planar.receivers: no node named 'nowhere'");
    }
    try {
        renderScene(planarScene(light, box, R"("receivers": "box")"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("node 'box' is not planar"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(renderScene(planarScene(light, box, R"("receivers": " floor ")")));
}

// A light whose technique finds nothing to work with says so in one note
// instead of silently casting no shadow: planar without a planar receiver,
// disc without a disc.
TEST_F(PlanarGLTest, NothingToShadowIsNoted) {
    for (const char* technique : {"planar", "disc"}) {
        SCOPED_TRACE(technique);
        const Scene scene = parseScene(std::string(R"({"lights": [{"type": "directional", "shadow": {"technique": ")") + technique + R"("}}],
                                        "nodes": [{"shape": {"type": "sphere"}}]})",
                                       "nothing.json", ".");
        Renderer renderer(test::glContext());
        renderer.upload(scene);
        const FrameStats stats = renderer.render(scene, {64, 36});
        ASSERT_EQ(stats.notes.size(), 1u);
        EXPECT_NE(stats.notes[0].find(std::string("lights[0].shadow.") + technique + ":"), std::string::npos) << stats.notes[0];
        EXPECT_NE(stats.notes[0].find("casts no shadow"), std::string::npos) << stats.notes[0];
    }
}
