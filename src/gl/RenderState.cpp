#include "gl/RenderState.h"

namespace shadowlab::gl {

namespace {
void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

void stencilFace(GLenum face, const StencilFace& s) {
    glStencilFuncSeparate(face, s.func, s.ref, s.readMask);
    glStencilOpSeparate(face, s.stencilFail, s.depthFail, s.depthPass);
    glStencilMaskSeparate(face, s.writeMask);
}
} // namespace

void apply(const RenderState& s) {
    enable(GL_DEPTH_TEST, s.depthTest);
    glDepthFunc(s.depthFunc);
    glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
    enable(GL_STENCIL_TEST, s.stencilTest);
    stencilFace(GL_FRONT, s.stencilFront);
    stencilFace(GL_BACK, s.stencilBack);
    enable(GL_CULL_FACE, s.cull != Cull::None);
    glCullFace(s.cull == Cull::Front ? GL_FRONT : GL_BACK);
    glColorMask(s.colorWrite[0], s.colorWrite[1], s.colorWrite[2], s.colorWrite[3]);
    enable(GL_BLEND, s.blend);
    glBlendFunc(s.blendSrc, s.blendDst);
    glBlendEquation(s.blendEquation);
    for (int i = 0; i < kBlendTargets; ++i) {
        const std::optional<TargetBlend>& t = s.targetBlend[static_cast<std::size_t>(i)];
        if (!t) continue;
        glEnablei(GL_BLEND, static_cast<GLuint>(i));
        glBlendFunci(static_cast<GLuint>(i), t->src, t->dst);
        glBlendEquationi(static_cast<GLuint>(i), t->equation);
    }
    enable(GL_POLYGON_OFFSET_FILL, s.polygonOffset);
    glPolygonOffset(s.offsetFactor, s.offsetUnits);
    enable(GL_DEPTH_CLAMP, s.depthClamp);
    glClipControl(GL_LOWER_LEFT, s.zeroToOneDepth ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    enable(GL_FRAMEBUFFER_SRGB, s.framebufferSrgb);
    for (int i = 0; i < kClipDistances; ++i) enable(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i), i < s.clipDistances);
    enable(GL_TEXTURE_CUBE_MAP_SEAMLESS, s.seamlessCubeMaps);
    enable(GL_SCISSOR_TEST, s.scissor.has_value());
    if (s.scissor) glScissor((*s.scissor)[0], (*s.scissor)[1], (*s.scissor)[2], (*s.scissor)[3]);
}

} // namespace shadowlab::gl
