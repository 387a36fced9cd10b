// Technique "map": moment maps' constants and blur (MapMoments.h).
#include "techniques/map/MapMoments.h"

#include "techniques/map/MapVariants.h"

#include <cmath>

namespace shadowlab::map {

MomentConstants MomentConstants::of(MapMomentFormat format) {
    if (format == MapMomentFormat::Rgba16f) return {5.54, 5.54, 1e-3, 1e-4};
    return {};
}

glm::vec4 farMoments(const ArrayKey& k) {
    const MomentConstants c = MomentConstants::of(k.momentFormat);
    const auto positive = static_cast<float>(c.evsmPositive), negative = static_cast<float>(c.evsmNegative);
    switch (k.representation) {
    case MapRepresentation::Evsm2:
    case MapRepresentation::Evsm4:
        return {std::exp(positive), std::exp(2.0f * positive), -std::exp(-negative), std::exp(-2.0f * negative)};
    default: return glm::vec4(1.0f);
    }
}

void blurLayer(TechniqueHost& host, MapBlock& block, const MapArray& g, int layer, int radius, const gl::Framebuffer& fbo) {
    const auto scope = host.timeScope("blur");
    host.apply(gl::RenderState{.depthTest = false, .depthWrite = false});
    for (int axis = 0; axis < 2; ++axis) {
        block.setBlur(static_cast<float>(radius), static_cast<float>(axis), static_cast<float>(layer));
        glBindFramebuffer(GL_FRAMEBUFFER, axis == 0 ? g.blurFbo.id() : fbo.id());
        glBindTextureUnit(SL_UNIT_SHADOW_FIRST, axis == 0 ? g.moments.id() : g.blurScratch.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST, 0);
        const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_blur.frag"}},
                                                   BlurVariant{axis == 0}.defines()});
        glUseProgram(program.id());
        host.drawFullscreenTriangle();
    }
    glBindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
}

} // namespace shadowlab::map
