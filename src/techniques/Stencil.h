#pragma once
// What the stencil techniques (planar, volume) share.
#include "techniques/Technique.h"

namespace shadowlab {

/// Clears the bound framebuffer's stencil to 0 (all stencil writes on,
/// colour and depth writes off): before a light's stencil work, and after
/// it, as the next light expects it.
inline void clearStencil(TechniqueHost& host) {
    gl::RenderState s;
    s.depthWrite = false;
    s.noColor();
    s.stencil({GL_ALWAYS, 0, 0xFF, 0xFF});
    host.apply(s);
    const GLint zero = 0;
    glClearBufferiv(GL_STENCIL, 0, &zero);
}

} // namespace shadowlab
