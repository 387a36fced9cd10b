#include "render/FrameTargets.h"

#include "gl/Calls.h"
#include "shadowlab_shared.h"

namespace shadowlab {

namespace {
gl::Texture makeTarget(GLenum format, glm::ivec2 size) {
    gl::Texture t(GL_TEXTURE_2D);
    gl::textureStorage2D(t.id(), 1, format, size.x, size.y);
    gl::textureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::textureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}
} // namespace

FrameTargets::FrameTargets(glm::ivec2 s, bool withSurfaces) : size(s), surfaces(withSurfaces) {
    color = makeTarget(GL_SRGB8_ALPHA8, size);
    depthStencil = makeTarget(GL_DEPTH24_STENCIL8, size);
    frame = gl::Framebuffer();
    gl::namedFramebufferTexture(frame.id(), GL_COLOR_ATTACHMENT0 + SL_TARGET_COLOR, color.id(), 0);
    gl::namedFramebufferTexture(frame.id(), GL_DEPTH_STENCIL_ATTACHMENT, depthStencil.id(), 0);
    if (surfaces) {
        position = makeTarget(GL_RGBA32F, size);
        normal = makeTarget(GL_RGBA16F, size);
        gl::namedFramebufferTexture(frame.id(), GL_COLOR_ATTACHMENT0 + SL_TARGET_POSITION, position.id(), 0);
        gl::namedFramebufferTexture(frame.id(), GL_COLOR_ATTACHMENT0 + SL_TARGET_NORMAL, normal.id(), 0);
    }
    drawBuffers(false);
    gl::checkFramebuffer(frame, "frame framebuffer");
    visibilityOut = makeTarget(GL_RGBA32F, size);
    visibilityIn = makeTarget(GL_R32F, size);
    visibility = gl::Framebuffer();
    gl::namedFramebufferTexture(visibility.id(), GL_COLOR_ATTACHMENT0, visibilityOut.id(), 0);
    gl::namedFramebufferTexture(visibility.id(), GL_DEPTH_STENCIL_ATTACHMENT, depthStencil.id(), 0);
    gl::checkFramebuffer(visibility, "visibility framebuffer");
}

void FrameTargets::drawBuffers(bool withSurfaces) const {
    const GLenum all[] = {GL_COLOR_ATTACHMENT0 + SL_TARGET_COLOR, GL_COLOR_ATTACHMENT0 + SL_TARGET_POSITION,
                          GL_COLOR_ATTACHMENT0 + SL_TARGET_NORMAL};
    gl::namedFramebufferDrawBuffers(frame.id(), withSurfaces && surfaces ? 3 : 1, all);
}

} // namespace shadowlab
