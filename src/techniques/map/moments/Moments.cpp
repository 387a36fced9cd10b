// Technique "map": a layer's moments made and blurred (moments/Moments.h).
#include "techniques/map/moments/Moments.h"

#include "gl/Calls.h"
#include "techniques/map/Variants.h"

#include <cmath>

namespace shadowlab::map {

void makeMoments(TechniqueHost& host, MapBlock& block, const MapArray& g, int layer, int radius, bool spot) {
    const auto scope = host.timeScope("moments");
    host.apply(gl::RenderState{.depthTest = false, .depthWrite = false});
    // The layer as the only target (the depth it is made from stays unattached: it is read).
    gl::namedFramebufferTextureLayer(g.momentFbo.id(), GL_COLOR_ATTACHMENT0, g.moments.id(), 0, layer);
    block.setBlur(static_cast<float>(radius), 0.0f, static_cast<float>(layer));
    const BlurVariant across{true, radius, spot, g.key.representation, g.key.momentFormat};
    const BlurVariant down{false, radius};
    glBindFramebuffer(GL_FRAMEBUFFER, radius > 0 ? g.blurFbo.id() : g.momentFbo.id());
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, g.depth.id());
    glBindSampler(SL_UNIT_SHADOW_FIRST, 0);
    glUseProgram(host.program({{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_blur.frag"}}, across.defines()}).id());
    host.drawFullscreenTriangle();
    if (radius > 0) {
        glBindFramebuffer(GL_FRAMEBUFFER, g.momentFbo.id());
        gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, g.blurScratch.id());
        glUseProgram(host.program({{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_blur.frag"}}, down.defines()}).id());
        host.drawFullscreenTriangle();
    }
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
}

} // namespace shadowlab::map
