// Technique "map": a point light's cube-map pass (Lawonn's lecture;
// passes/CubePass.h). The six faces are six layers of a cube-map array, drawn
// in one geometry-shader pass (gl_Layer picks the faces each triangle
// touches) or in six; only the texels that held casters or will are cleared.
#include "techniques/map/passes/CubePass.h"

#include "gl/Calls.h"
#include "techniques/map/Variants.h"
#include "techniques/map/fit/Cameras.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/CasterDraw.h"
#include "techniques/map/passes/Translucent.h"

#include <cmath>
#include <string>

namespace shadowlab::map {

namespace {

// What the frame's casters need of each face: whether it is drawn, the
// texels they may cover, their triangles.
struct FaceUse {
    std::array<bool, 6> used{};
    std::array<TexelRect, 6> covered{};
    std::array<double, 6> triangles{};  ///< the meshes' own, whatever level the pass draws (lodTexels)
};

FaceUse faceUse(const FrameInfo& frame, const MapLight& p, int size) {
    FaceUse use;
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        const std::uint8_t mask = p.faceMask(i);
        if (!mask || !frame.items[i].castsShadows) continue;
        const auto triangles = static_cast<double>(frame.scene.meshes[static_cast<std::size_t>(frame.items[i].mesh)].triangleCount());
        for (std::size_t f = 0; f < 6; ++f)
            if (mask & (1u << f)) {
                use.used[f] = true;
                use.triangles[f] += triangles;
                use.covered[f] = use.covered[f].united(projectedRect(p.cubeCamera().faceClipFromWorld[f], frame.itemBounds[i], size));
            }
    }
    return use;
}

// Clears, per face, only the texels that held casters or will: the rest is still clear.
void clearFaces(TechniqueHost& host, const MapArray& g, MapLight& p, const FaceUse& use) {
    const auto scope = host.timeScope("clear");
    const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const float far = cubeWindowDepth(p.options) ? 0.0f : 1.0f;  // the reversed window depth's far plane is 0
    for (int f = 0; f < 6; ++f) {
        const auto face = static_cast<std::size_t>(f);
        const TexelRect r = p.cubeMap().faceDirty[face].clamped(g.size()).united(use.covered[face]);
        p.cubeMap().faceDirty[face] = use.covered[face];
        if (r.empty()) continue;
        gl::clearTexSubImage(g.depth.id(), 0, r.x0, r.y0, 6 * p.layer + f, r.x1 - r.x0, r.y1 - r.y0, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
        if (isPacked(g.format()))
            gl::clearTexSubImage(g.packed.id(), 0, r.x0, r.y0, 6 * p.layer + f, r.x1 - r.x0, r.y1 - r.y0, 1, GL_RGBA, GL_FLOAT, one);
    }
}

// A cube of reversed window depth (MapSettings: cubeWindowDepth): 0..1
// clip depth, nearer is greater, and the slope bias as a polygon offset
// pushing depths towards the far plane, 0 (the written depth's measure:
// the largest change to a neighbouring texel times slopeBias), with
// cullFront too, as the written depth had it. The constant offset
// (offsetUnits of the format's step in distance / far) is the lookup's
// (cubeStored): a polygon offset's units would be steps of the window
// depth, which near the far plane are a large share of it.
gl::RenderState windowDepthState(gl::RenderState state, const MapOptions& o) {
    state.zeroToOneDepth = true;
    state.depthFunc = GL_GREATER;
    state.polygonOffset = o.slopeBias != 0.0f;
    state.offsetFactor = -o.slopeBias;
    state.offsetUnits = 0.0f;
    return state;
}

// The casters into the cube: once through the geometry shader, or once per face they touch.
// Returns the triangles drawn (each caster once in one pass; once per
// face in six).
std::size_t drawCasters(TechniqueHost& host, const FrameInfo& frame, bool holes, const MapArray& g, const MapLight& p, const FaceUse& use,
                        const gl::RenderState& state) {
    const bool onePass = p.options.cubePasses == MapCubePasses::One;
    const auto seenWhole = [&](std::size_t i) { return seesWhole(p.cubeCamera(), frame.itemBounds[i]); };
    const CasterDetail detail = casterDetail(p.options.lodTexels, p.cubeCamera(), g.size(), frame);
    // cullFront: an open caster has no back face, so it is drawn whole (the
    // cube's slope bias is the same either way).
    gl::RenderState open = state;
    open.cull = gl::Cull::None;
    const auto defines = [&](bool cut) {
        return CubePassVariant{g.format(), onePass, p.options.faceCulling, cubeWindowDepth(p.options), cut}.defines();
    };
    glViewport(0, 0, g.size(), g.size());
    if (onePass) {
        const auto program = [&](bool cut) -> const gl::Program& {
            return host.program({{{GL_VERTEX_SHADER, "shadow_map_cube.vert"},
                                  {GL_GEOMETRY_SHADER, "shadow_map_cube.geom"},
                                  {GL_FRAGMENT_SHADER, "shadow_map_cube.frag"}},
                                 defines(cut)});
        };
        glBindFramebuffer(GL_FRAMEBUFFER, p.targets.fbo.id());
        return drawDepthCasters(
            host, frame, holes, program,
            [&](std::size_t i, const gl::Program& drawing) {
                if (!p.faceMask(i)) return false;
                gl::programUniform1ui(drawing.id(), 0, p.faceMask(i));
                return true;
            },
            state, seenWhole, detail, &open);
    }
    const auto program = [&](bool cut) -> const gl::Program& {
        return host.program({{{GL_VERTEX_SHADER, "shadow_map_cube.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_cube.frag"}}, defines(cut)});
    };
    std::size_t drawn = 0;
    for (int f = 0; f < 6; ++f) {
        if (!use.used[static_cast<std::size_t>(f)]) continue;
        glBindFramebuffer(GL_FRAMEBUFFER, p.cubeMap().faceFbos[static_cast<std::size_t>(f)].id());
        gl::programUniform1i(program(false).id(), 1, f);
        if (holes) gl::programUniform1i(program(true).id(), 1, f);
        drawn += drawDepthCasters(host, frame, holes, program, [&](std::size_t i, const gl::Program&) { return (p.faceMask(i) & (1u << f)) != 0; }, state,
                                  seenWhole, detail, &open);
    }
    return drawn;
}

} // namespace

void renderCubePass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, MapLight& p) {
    const MapArray& g = res.arrays[p.array];
    const FaceUse use = faceUse(frame, p, g.size());
    res.block.upload(p, g, view.light, res.translucent);
    gl::RenderState state;  // all writes on for the clears
    host.apply(state);
    clearFaces(host, g, p, use);
    if (!isPacked(g.format())) state.noColor();
    state.cull = p.options.cullFront ? gl::Cull::Front : gl::Cull::None;
    if (cubeWindowDepth(p.options)) state = windowDepthState(state, p.options);
    host.apply(state);
    const std::size_t drawn = drawCasters(host, frame, res.holes, g, p, use, state);
    static const char* faceNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    host.count("triangles", static_cast<double>(drawn));
    host.count("mapBytes", 6.0 * texelBytes(g.key) * static_cast<double>(g.size()) * static_cast<double>(g.size()));
    for (std::size_t f = 0; f < 6; ++f) host.count(std::string("faceTriangles.") + faceNames[f], use.triangles[f]);
    if (res.translucent) drawCubeTranslucent(host, frame, g, p);
    if (frame.measureFloors) res.floors.drawCube(host, res.block, frame, g, p, use.used);
}

} // namespace shadowlab::map
