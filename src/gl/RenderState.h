#pragma once
// The whole fixed-function state of a pass as one value. Every pass applies
// a complete RenderState, so nothing (stencil, colour mask, polygon offset,
// culling, ...) leaks from one pass into the next.
#include <epoxy/gl.h>

#include <array>
#include <optional>

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

/// One colour attachment's blending (glBlendFunci / glBlendEquationi).
struct TargetBlend {
    GLenum src = GL_ONE;
    GLenum dst = GL_ONE;
    GLenum equation = GL_FUNC_ADD;
};

/// Colour attachments a state can blend one by one (the frame has three).
constexpr int kBlendTargets = 4;
/// Clip distances a state can enable (GL guarantees at least 8).
constexpr int kClipDistances = 8;

/// Defaults: depth test LESS with writes, no stencil, no culling, all colour
/// channels written, no blending, no polygon offset, no depth clamp, GL's
/// -1..1 depth, no clip distances, seamless cube-map filtering.
struct RenderState {
    bool depthTest = true;
    GLenum depthFunc = GL_LESS;
    bool depthWrite = true;
    bool stencilTest = false;
    StencilFace stencilFront{};
    StencilFace stencilBack{};
    Cull cull = Cull::None;
    bool colorWrite[4] = {true, true, true, true};
    bool blend = false;
    GLenum blendSrc = GL_ONE;
    GLenum blendDst = GL_ONE;
    GLenum blendEquation = GL_FUNC_ADD;
    /// Colour attachments blended unlike the rest (blending on, with their
    /// own function and equation: translucent casters multiply one target
    /// and keep the least of another); the others as blend/blendSrc/... say.
    std::array<std::optional<TargetBlend>, kBlendTargets> targetBlend{};
    bool polygonOffset = false;
    float offsetFactor = 0.0f;   ///< glPolygonOffset factor (slope), units of max depth slope
    float offsetUnits = 0.0f;    ///< glPolygonOffset units (constant), units of minimum resolvable depth
    bool depthClamp = false;
    /// Clip-space depth 0..w straight to window depth 0..1 (glClipControl
    /// GL_ZERO_TO_ONE; false: GL's -w..w halved and shifted). A reversed
    /// depth (near 1, far 0) keeps a float's relative precision only so.
    bool zeroToOneDepth = false;
    bool framebufferSrgb = false; ///< linear-to-sRGB conversion on writes to sRGB targets
    int clipDistances = 0;        ///< GL_CLIP_DISTANCE0 .. this - 1 on (the vertex stage writes gl_ClipDistance), 0..kClipDistances
    bool seamlessCubeMaps = true; ///< cube-map filters read across face edges (a context-wide switch in GL)
    /// Fragments only inside this box (glScissor: x, y, width, height in
    /// pixels from the lower left); none: everywhere. Clears obey it too.
    std::optional<std::array<GLint, 4>> scissor = std::nullopt;

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
