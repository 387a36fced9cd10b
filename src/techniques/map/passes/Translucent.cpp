// Technique "map": translucent casters' transmittance layers (passes/Translucent.h).
#include "techniques/map/passes/Translucent.h"

#include "gl/Calls.h"
#include "techniques/map/Variants.h"
#include "techniques/map/fit/Cameras.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/CasterDraw.h"

#include <string>

namespace shadowlab::map {

namespace {

// The target of the translucent casters for one layer (a 2D map's, or a
// cube face's): its transmittance and nearest-depth layers as colours,
// cleared to white, over the opaque depth of `depthLayer`, tested, not
// written; transmittances multiply (dst x src), depths keep the least.
gl::Framebuffer bindTranslucentTarget(TechniqueHost& host, const MapArray& g, int layer, int depthLayer, bool depthClamp, bool reversedDepth) {
    gl::Framebuffer fbo;
    gl::namedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, g.transmit.id(), 0, layer);
    gl::namedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT1, g.transmitDepth.id(), 0, layer);
    gl::namedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, g.depth.id(), 0, depthLayer);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl::namedFramebufferDrawBuffers(fbo.id(), 2, buffers);
    gl::checkFramebuffer(fbo, "translucent casters framebuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, g.size(), g.size());
    gl::RenderState state;
    host.apply(state);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    gl::clearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, white);
    gl::clearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, white);
    state.depthWrite = false;
    state.depthClamp = depthClamp;
    if (reversedDepth) {  // a cube of window depth (cubeWindowDepth): nearer is greater
        state.zeroToOneDepth = true;
        state.depthFunc = GL_GREATER;
    }
    state.targetBlend[0] = gl::TargetBlend{GL_ZERO, GL_SRC_COLOR, GL_FUNC_ADD};
    state.targetBlend[1] = gl::TargetBlend{GL_ONE, GL_ONE, GL_MIN};
    host.apply(state);
    return fbo;
}

} // namespace

bool translucentCaster(const FrameInfo& frame, std::size_t i) { return casterSurface(frame, i) == CasterSurface::Translucent; }

bool hasTranslucentCasters(const FrameInfo& frame) {
    bool translucent = false;
    for (std::size_t i = 0; i < frame.items.size(); ++i) translucent = translucent || (frame.items[i].castsShadows && translucentCaster(frame, i));
    return translucent;
}

void drawTranslucent(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p, std::size_t c) {
    const auto scope = host.timeScope("translucent");
    const LightCamera& camera = p.cameras()[c];
    const int layer = p.layer + static_cast<int>(c);
    const gl::Framebuffer fbo = bindTranslucentTarget(host, g, layer, sharedDepthBuffer(g.key) ? 0 : layer, !camera.perspective, false);
    block.setCamera(p, c);
    const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_transmit.frag"}},
                                               TranslucentVariant{}.defines()});
    host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) { return translucentCaster(frame, i) && castsInto(camera, frame, i, true); });
}

void drawCubeTranslucent(TechniqueHost& host, const FrameInfo& frame, const MapArray& g, const MapLight& p) {
    const auto scope = host.timeScope("translucent");
    const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "shadow_map_cube.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_cube_transmit.frag"}},
                                               CubePassVariant{.format = g.format(), .onePass = false, .windowDepth = cubeWindowDepth(p.options)}.defines()});
    for (int f = 0; f < 6; ++f) {
        const int layer = 6 * p.layer + f;
        const gl::Framebuffer fbo = bindTranslucentTarget(host, g, layer, layer, false, cubeWindowDepth(p.options));
        gl::programUniform1i(program.id(), 1, f);
        host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) { return translucentCaster(frame, i) && (p.faceMask(i) & (1u << f)) != 0; });
    }
}

} // namespace shadowlab::map
