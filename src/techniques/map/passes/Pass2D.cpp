// Technique "map": the shadow pass of a directional or spot light, one map
// or a cascade per layer (passes/Pass2D.h). Wolberg's lecture and
// Ganovelli et al. §8.2-8.4: the casters drawn from the light camera, colour writes off
// (or depth packed into RGBA8, or moments), a polygon offset against acne.
#include "techniques/map/passes/Pass2D.h"

#include "gl/Calls.h"
#include "techniques/map/Variants.h"
#include "techniques/map/fit/Cameras.h"
#include "techniques/map/moments/Moments.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/CasterDraw.h"
#include "techniques/map/passes/Translucent.h"

#include <string>

namespace shadowlab::map {

namespace {

// Clears the layer `fbo` holds (all writes on): depth 1, and the colour
// the pass writes, a packed depth of 1 (moments are made from the depth
// afterwards, every texel: makeMoments).
void clearLayer(TechniqueHost& host, const MapArray& g, const gl::Framebuffer& fbo) {
    host.apply(gl::RenderState{});
    const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    gl::clearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, one);
    if (isPacked(g.format())) gl::clearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, one);
}

// The casters' draw state: depth (and the colour the map is, if any), the
// light's polygon offset and culling. Back faces (cullFront) are drawn where
// they are: they lie behind the lit surfaces already, and an offset pushes
// them past the receivers at a caster's foot (light leaks there). An open
// caster (`open`: it has no back face) is drawn whole with the offset even
// then. Moments are made from the depth as drawn, so it takes no offset
// (moments bound the depths' spread instead).
gl::RenderState casterState(const MapArray& g, const MapOptions& o, const LightCamera& camera, bool open = false) {
    gl::RenderState state;
    if (!isPacked(g.format())) state.noColor();
    const bool backFaces = o.cullFront && !open;
    state.polygonOffset = !backFaces && !g.hasMoments() && (o.slopeBias != 0.0f || o.offsetUnits != 0.0f);
    state.offsetFactor = o.slopeBias;
    state.offsetUnits = o.offsetUnits;
    state.cull = backFaces ? gl::Cull::Front : gl::Cull::None;
    // An orthographic light pancakes casters nearer than its near plane onto it.
    state.depthClamp = !camera.perspective;
    return state;
}

// Clears texels `r` of layer `layer` (depth 1) with no framebuffer, which
// neither scissor nor masks touch: a clear of only those texels.
void clearTexels(const MapArray& g, int layer, const TexelRect& r) {
    const float one = 1.0f;
    if (!r.empty()) gl::clearTexSubImage(g.depth.id(), 0, r.x0, r.y0, layer, r.x1 - r.x0, r.y1 - r.y0, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
}

} // namespace

void renderMapPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, MapLight& p) {
    const MapArray& g = res.arrays[p.array];
    const bool packed = isPacked(g.format());
    res.block.upload(p, g, view.light, res.translucent);
    const auto program = [&](bool holes) -> const gl::Program& {
        return host.program({{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_depth.frag"}},
                             DepthPassVariant{g.hasMoments() ? MapFormat::Depth32F : g.format(), holes}.defines()});
    };
    std::size_t drawn = 0;
    const std::span<const LightCamera> cameras = p.cameras();
    for (std::size_t c = 0; c < cameras.size(); ++c) {
        const LightCamera& camera = cameras[c];
        const gl::Framebuffer& fbo = p.cascadeCount() == 0 ? p.targets.fbo : p.cascadeSet()->fbos[c];
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, g.size(), g.size());
        const std::optional<TexelRect> part = drawnTexels(frame, g, p, camera);
        if (part)
            clearTexels(g, p.layer + static_cast<int>(c), *part);
        else
            clearLayer(host, g, fbo);
        gl::RenderState state = casterState(g, p.options, camera);
        gl::RenderState open = casterState(g, p.options, camera, true);
        if (part) state.scissor = open.scissor = std::array<GLint, 4>{part->x0, part->y0, part->x1 - part->x0, part->y1 - part->y0};
        host.apply(state);
        // This cascade's camera for the depth pass (the block's first member).
        res.block.setCamera(p, c);
        // Casters that cannot reach the light's frustum are not drawn, nor
        // the far sides of closed ones it sees whole, and dense ones are
        // drawn from a coarser level within lodTexels (passes/CasterDraw.h; not
        // for a map fitted on the GPU, whose texels are not known here).
        std::size_t drawnHere = 0;
        if (!part || !part->empty())
            drawnHere = drawDepthCasters(
                host, frame, res.holes, program, [&](std::size_t i, const gl::Program&) { return castsInto(camera, frame, i, g.hasMoments()); },
                state, [&](std::size_t i) { return seesWhole(camera, frame.itemBounds[i]); }, casterDetail(p.gpuFit() ? 0.0f : p.options.lodTexels, camera, frame),
                &open);
        if (cameras.size() > 1) {
            host.count("cascade" + std::to_string(c) + ".triangles", static_cast<double>(drawnHere));
            // The share of the layer's texels the pass cleared and drew.
            const double texels = part ? static_cast<double>(part->x1 - part->x0) * static_cast<double>(part->y1 - part->y0) : static_cast<double>(g.size()) * g.size();
            host.count("cascade" + std::to_string(c) + ".drawnShare", texels / (static_cast<double>(g.size()) * g.size()));
        }
        drawn += drawnHere;
        if (g.storesMoments()) makeMoments(host, res.block, g, p.layer + static_cast<int>(c), p.options.blur, p.spot());
        if (res.translucent) drawTranslucent(host, res.block, frame, g, p, c);
    }
    host.count("triangles", static_cast<double>(drawn));
    // The memory of this light's layers (the map the light pass reads and what its pass needs beside it).
    host.count("mapBytes", texelBytes(g.key) * static_cast<double>(g.size()) * static_cast<double>(g.size()) * static_cast<double>(cameras.size()));
    if (g.mipmaps()) {
        // Every level from the map: averaged depths or moments (of all layers; each light's pass refreshes them).
        const auto scope = host.timeScope("mipmaps");
        gl::generateTextureMipmap(packed ? g.packed.id() : g.storesMoments() ? g.moments.id() : g.depth.id());
    }
    if (frame.measureFloors) res.floors.draw(host, res.block, frame, g, p);
}

} // namespace shadowlab::map
