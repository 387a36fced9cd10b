// Technique "map": the shadow passes' floors (floors/Floors.h).
#include "techniques/map/floors/Floors.h"

#include "gl/Calls.h"
#include "techniques/map/Variants.h"
#include "techniques/map/fit/Cameras.h"
#include "techniques/map/passes/CasterDraw.h"

namespace shadowlab::map {

namespace {

// As drawLookup reads a floor's map: nearest, no comparison, depth 1 (lit) outside.
void nearestWithBorder(const gl::Texture& t) {
    gl::textureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::textureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::textureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    gl::textureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    gl::textureParameterfv(t.id(), GL_TEXTURE_BORDER_COLOR, white);
}

} // namespace

void MapFloors::ensureTarget(const MapArray& g) {
    if (!target_ || size_ != g.size() || format_ != g.format()) {
        target_ = gl::Texture(GL_TEXTURE_2D);
        gl::textureStorage2D(target_.id(), 1, depthFormat(g.format()), g.size(), g.size());
        nearestWithBorder(target_);
        fbo_ = gl::Framebuffer();
        gl::namedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, target_.id(), 0);
        gl::namedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
        size_ = g.size();
        format_ = g.format();
    }
}

void MapFloors::ensureCube(const MapArray& g) {
    if (!cube_ || cubeSize_ != g.size() || cubeFormat_ != g.format()) {
        cube_ = gl::Texture(GL_TEXTURE_CUBE_MAP);
        gl::textureStorage2D(cube_.id(), 1, depthFormat(g.format()), g.size(), g.size());
        nearestWithBorder(cube_);
        cubeFbo_ = gl::Framebuffer();
        gl::namedFramebufferDrawBuffer(cubeFbo_.id(), GL_NONE);
        cubeSize_ = g.size();
        cubeFormat_ = g.format();
    }
}

// The floor's target for `g`, bound, and its bare depth-only program.
const gl::Program& MapFloors::bind(TechniqueHost& host, const MapArray& g) {
    ensureTarget(g);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, g.size(), g.size());
    return host.program(
        {{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_depth.frag"}}, DepthPassVariant{}.defines()});
}

// Clears a floor's target `fbo` (all writes on), or only texels `part` of
// the 2D target, then leaves depth-only writes there (the state returned).
gl::RenderState MapFloors::clear(TechniqueHost& host, const gl::Framebuffer& fbo, bool depthClamp, const std::optional<TexelRect>& part) {
    gl::RenderState state;
    host.apply(state);
    const float one = 1.0f;
    if (!part) {
        gl::clearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
    } else if (!part->empty()) {
        gl::clearTexSubImage(target_.id(), 0, part->x0, part->y0, 0, part->x1 - part->x0, part->y1 - part->y0, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    }
    state.noColor();
    state.depthClamp = depthClamp;
    if (part) state.scissor = std::array<GLint, 4>{part->x0, part->y0, part->x1 - part->x0, part->y1 - part->y0};
    host.apply(state);
    return state;
}

void MapFloors::draw(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p) {
    {
        const auto scope = host.timeScope("floor");
        const gl::Program& bare = bind(host, g);
        for (std::size_t c = 0; c < p.cameras().size(); ++c) {
            const LightCamera& camera = p.cameras()[c];
            // The texels the pass draws, as it does (MapCameras: drawnTexels).
            const std::optional<TexelRect> part = drawnTexels(frame, g, p, camera);
            const gl::RenderState state = clear(host, fbo_, !camera.perspective, part);
            if (part && part->empty()) continue;
            block.setCamera(p, c);
            // The casters the pass draws, without the far sides it leaves out, at its levels.
            drawDepthCasters(
                host, frame, true, [&](bool) -> const gl::Program& { return bare; },
                [&](std::size_t i, const gl::Program&) { return castsInto(camera, frame, i, g.hasMoments()); }, state,
                [&](std::size_t i) { return seesWhole(camera, frame.itemBounds[i]); }, casterDetail(p.gpuFit() ? 0.0f : p.options.lodTexels, camera, frame));
        }
    }
    // The target holds the last camera's casters (a cascade's: the farthest),
    // and the block its camera.
    if (!p.cameras().empty()) drawLookup(host, frame, std::nullopt);
}

void MapFloors::drawLookup(TechniqueHost& host, const FrameInfo& frame, const std::optional<glm::vec3>& cubeCentre) {
    const bool cube = cubeCentre.has_value();
    const auto scope = host.timeScope("lookupFloor");
    if (!viewFbo_ || viewSize_ != frame.viewport) {
        viewSize_ = frame.viewport;
        viewColor_ = gl::Texture(GL_TEXTURE_2D);
        gl::textureStorage2D(viewColor_.id(), 1, GL_RGBA8, viewSize_.x, viewSize_.y);
        viewDepth_ = gl::Texture(GL_TEXTURE_2D);
        gl::textureStorage2D(viewDepth_.id(), 1, GL_DEPTH_COMPONENT32F, viewSize_.x, viewSize_.y);
        viewFbo_ = gl::Framebuffer();
        gl::namedFramebufferTexture(viewFbo_.id(), GL_COLOR_ATTACHMENT0, viewColor_.id(), 0);
        gl::namedFramebufferTexture(viewFbo_.id(), GL_DEPTH_ATTACHMENT, viewDepth_.id(), 0);
        gl::checkFramebuffer(viewFbo_, "lookup floor framebuffer");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, viewFbo_.id());
    glViewport(0, 0, viewSize_.x, viewSize_.y);
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, cube ? cube_.id() : target_.id());
    glBindSampler(SL_UNIT_SHADOW_FIRST, 0);
    for (const bool fetch : {false, true}) {
        const auto part = host.timeScope(fetch ? "fetch" : "bare");
        host.apply(gl::RenderState{});
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, one = 1.0f;
        gl::clearNamedFramebufferfv(viewFbo_.id(), GL_COLOR, 0, zero);
        gl::clearNamedFramebufferfv(viewFbo_.id(), GL_DEPTH, 0, &one);
        const gl::Program& program = host.program(
            {{{GL_VERTEX_SHADER, "shadow_map_lookup_floor.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_lookup_floor.frag"}},
             LookupFloorVariant{fetch, cube}.defines()});
        if (cube) gl::programUniform3fv(program.id(), 0, 1, &(*cubeCentre)[0]);
        host.drawItems(ItemFilter::Opaque, program);
    }
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
}

void MapFloors::drawCube(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p,
                         const std::array<bool, 6>& used) {
    {
        const auto scope = host.timeScope("floor");
        ensureCube(g);
        glBindFramebuffer(GL_FRAMEBUFFER, cubeFbo_.id());
        glViewport(0, 0, g.size(), g.size());
        const gl::Program& bare = host.program(
            {{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_depth.frag"}}, DepthPassVariant{}.defines()});
        for (int f = 0; f < 6; ++f) {
            // The faces the light's pass draws, as it does (the lookup floor
            // reads what the others held: its cost is the same).
            if (!used[static_cast<std::size_t>(f)]) continue;
            gl::namedFramebufferTextureLayer(cubeFbo_.id(), GL_DEPTH_ATTACHMENT, cube_.id(), 0, f);
            const gl::RenderState state = clear(host, cubeFbo_, false);
            // The bare vertex shader reads map.lightClipFromWorld: this face's camera.
            block.writeWithLightClip(p.cubeCamera().faceClipFromWorld[static_cast<std::size_t>(f)]);
            // The casters the pass draws, without the far sides it leaves out.
            drawDepthCasters(
                host, frame, true, [&](bool) -> const gl::Program& { return bare; },
                [&](std::size_t i, const gl::Program&) { return (p.faceMask(i) & (1u << f)) != 0; }, state,
                [&](std::size_t i) { return seesWhole(p.cubeCamera(), frame.itemBounds[i]); }, casterDetail(p.options.lodTexels, p.cubeCamera(), g.size(), frame));
        }
        block.restore();
    }
    drawLookup(host, frame, p.cubeCamera().position);
}

} // namespace shadowlab::map
