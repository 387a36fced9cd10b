#pragma once
// The whole fixed-function state of a pass as one value. Every pass applies
// a complete RenderState, so nothing (stencil, colour mask, polygon offset,
// culling, ...) leaks from one pass into the next.
#include <epoxy/gl.h>

namespace shadowlab::gl {

/// One face's stencil test and operations (glStencilFuncSeparate / OpSeparate).
struct StencilFace {
    GLenum func = GL_ALWAYS;
    GLint ref = 0;
    GLuint readMask = 0xFF;
    GLuint writeMask = 0xFF;
    GLenum stencilFail = GL_KEEP;
    GLenum depthFail = GL_KEEP;
    GLenum depthPass = GL_KEEP;
};

enum class Cull { None, Back, Front };

/// Defaults: depth test LESS with writes, no stencil, no culling, all colour
/// channels written, no blending, no polygon offset, no depth clamp.
struct RenderState {
    bool depthTest = true;
    GLenum depthFunc = GL_LESS;
    bool depthWrite = true;
    bool stencilTest = false;
    StencilFace stencilFront;
    StencilFace stencilBack;
    Cull cull = Cull::None;
    bool colorWrite[4] = {true, true, true, true};
    bool blend = false;
    GLenum blendSrc = GL_ONE;
    GLenum blendDst = GL_ONE;
    GLenum blendEquation = GL_FUNC_ADD;
    bool polygonOffset = false;
    float offsetFactor = 0.0f;   ///< glPolygonOffset factor (slope), units of max depth slope
    float offsetUnits = 0.0f;    ///< glPolygonOffset units (constant), units of minimum resolvable depth
    bool depthClamp = false;
    bool framebufferSrgb = false; ///< linear-to-sRGB conversion on writes to sRGB targets

    /// The same stencil test and operations on both faces.
    RenderState& stencil(const StencilFace& both) {
        stencilTest = true;
        stencilFront = stencilBack = both;
        return *this;
    }
    RenderState& noColor() {
        colorWrite[0] = colorWrite[1] = colorWrite[2] = colorWrite[3] = false;
        return *this;
    }
};

/// Sets every part of `state` on the current context.
void apply(const RenderState& state);

} // namespace shadowlab::gl
