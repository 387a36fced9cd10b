#pragma once
// The offscreen targets of one frame size: colour (8-bit sRGB, lit passes
// add in linear light through GL_FRAMEBUFFER_SRGB), a depth+stencil buffer
// shared by every framebuffer of the frame, the surface targets compare
// reads (only when asked for), and the visibility targets.
#include "gl/Object.h"

#include <glm/glm.hpp>

namespace shadowlab {

struct FrameTargets {
    glm::ivec2 size{0};
    bool surfaces = false;                  ///< position and normal attached
    gl::Texture color{gl::NoCreate};        ///< SRGB8_ALPHA8
    gl::Texture depthStencil{gl::NoCreate}; ///< DEPTH24_STENCIL8
    gl::Texture position{gl::NoCreate};     ///< RGBA32F: world position, w = 1 on geometry (surfaces only)
    gl::Texture normal{gl::NoCreate};       ///< RGBA16F: geometric normal, w = receives shadows (surfaces only)
    gl::Texture visibilityOut{gl::NoCreate};///< RGBA32F: a technique's visibility per pixel (compare)
    gl::Texture visibilityIn{gl::NoCreate}; ///< R32F: the reference's visibility, read by SCREEN_VISIBILITY
    gl::Framebuffer frame{gl::NoCreate};    ///< colour (+ position, normal) + depth/stencil
    gl::Framebuffer visibility{gl::NoCreate}; ///< visibilityOut + the same depth/stencil

    FrameTargets(glm::ivec2 size, bool surfaces);
    /// Draw buffers of `frame`: colour only, or colour, position and normal.
    void drawBuffers(bool withSurfaces) const;
};

} // namespace shadowlab
