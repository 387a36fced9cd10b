// Technique "map": the shadow passes' floors (MapFloors.h).
#include "techniques/map/MapFloors.h"

#include "techniques/map/MapCameras.h"
#include "techniques/map/MapVariants.h"

namespace shadowlab::map {

void MapFloors::ensureTarget(const MapArray& g) {
    if (!target_ || size_ != g.size() || format_ != g.format()) {
        target_ = gl::Texture(GL_TEXTURE_2D);
        glTextureStorage2D(target_.id(), 1, depthFormat(g.format()), g.size(), g.size());
        fbo_ = gl::Framebuffer();
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, target_.id(), 0);
        glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
        size_ = g.size();
        format_ = g.format();
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

// Clears the floor's target (all writes on), then leaves depth-only writes.
void MapFloors::clear(TechniqueHost& host, bool depthClamp) {
    gl::RenderState state;
    host.apply(state);
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    state.noColor();
    state.depthClamp = depthClamp;
    host.apply(state);
}

void MapFloors::draw(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p) {
    const auto scope = host.timeScope("floor");
    const gl::Program& bare = bind(host, g);
    for (const LightCamera& camera : p.cameras()) {
        clear(host, !camera.perspective);
        block.setLightClip(camera.clipFromWorld());
        host.drawItems(ItemFilter::Casters, bare, [&](std::size_t i) { return castsInto(camera, frame, i, g.hasMoments()); });
    }
}

void MapFloors::drawCube(TechniqueHost& host, MapBlock& block, const MapArray& g, const MapLight& p, const std::array<bool, 6>& used) {
    const auto scope = host.timeScope("floor");
    const gl::Program& bare = bind(host, g);
    for (int f = 0; f < 6; ++f) {
        if (!used[static_cast<std::size_t>(f)]) continue;
        clear(host, false);
        // The bare vertex shader reads map.lightClipFromWorld: this face's camera.
        block.writeWithLightClip(p.cubeCamera.faceClipFromWorld[static_cast<std::size_t>(f)]);
        host.drawItems(ItemFilter::Casters, bare, [&](std::size_t i) { return (p.faceMask(i) & (1u << f)) != 0; });
    }
    block.restore();
}

} // namespace shadowlab::map
