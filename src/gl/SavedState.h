#pragma once
// The GL state a caller's context had before a shadowlab call, put back
// after it (Context::adoptCurrent: shadowlab draws into a context it does
// not own, and the caller's next draw must not notice). What is kept:
// framebuffer, program, vertex array and buffer bindings (the indexed
// uniform and storage buffers shadowlab binds), the textures and samplers
// of the units it may use, the active unit, viewport and scissor,
// depth/stencil/blend/cull/polygon-offset state and masks, colour masks,
// clip distances, depth clamp, seamless cube maps, clip control, sRGB
// writes, pixel-store alignment and row lengths, clear values.
#include <epoxy/gl.h>

#include <array>
#include <optional>

namespace shadowlab::gl {

/// Units whose textures and samplers are kept (shadowlab's units are below it).
inline constexpr int kSavedTextureUnits = 32;
/// Indexed uniform and storage buffer bindings kept (shadowlab's are below it).
inline constexpr int kSavedBufferBindings = 16;

class SavedState {
public:
    /// Reads the state of the current context, then sets what shadowlab's
    /// passes take as GL's defaults without setting it themselves: no
    /// pixel pack or unpack buffer, pixel-store alignment 4 and no row
    /// lengths or skips, no program pipeline, filled polygons, no
    /// rasterizer discard or primitive restart (a caller's pack buffer
    /// turned read-backs into out-of-bounds buffer writes).
    SavedState();
    /// Sets it back.
    ~SavedState();
    SavedState(const SavedState&) = delete;
    SavedState& operator=(const SavedState&) = delete;

private:
    void readBindings();
    void readFixedFunction();
    void readPixelStore();
    void assumeDefaults();
    void writeBindings();
    void writeFixedFunction();
    void writePixelStore();

    struct IndexedBuffer {
        GLint buffer = 0;
        GLint64 start = 0, size = 0;
    };
    struct StencilFace {
        GLint func = 0, ref = 0, valueMask = 0, writeMask = 0, fail = 0, depthFail = 0, depthPass = 0;
    };
    struct BlendTarget {
        GLboolean enabled = GL_FALSE;
        GLint srcRgb = 0, dstRgb = 0, srcAlpha = 0, dstAlpha = 0, equationRgb = 0, equationAlpha = 0;
        std::array<GLboolean, 4> colorMask{};
    };
    static constexpr int kTargets = 6;  // 2D, 2D array, cube, cube array, 3D, 2D multisample

    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, program_ = 0, pipeline_ = 0, vertexArray_ = 0;
    GLint arrayBuffer_ = 0, uniformBuffer_ = 0, storageBuffer_ = 0, packBuffer_ = 0, unpackBuffer_ = 0;
    GLint drawIndirect_ = 0, dispatchIndirect_ = 0, copyRead_ = 0, copyWrite_ = 0;
    std::array<IndexedBuffer, kSavedBufferBindings> uniformBuffers_{}, storageBuffers_{};
    GLint activeTexture_ = 0;
    std::array<std::array<GLint, kTargets>, kSavedTextureUnits> textures_{};
    std::array<GLint, kSavedTextureUnits> samplers_{};
    std::array<GLint, 4> viewport_{}, scissorBox_{};
    GLboolean scissorTest_ = GL_FALSE;
    GLboolean depthTest_ = GL_FALSE, depthMask_ = GL_TRUE, depthClamp_ = GL_FALSE;
    GLint depthFunc_ = 0;
    GLboolean stencilTest_ = GL_FALSE;
    StencilFace front_{}, back_{};
    std::array<BlendTarget, 4> blend_{};
    std::array<GLfloat, 4> blendColor_{};
    GLboolean cull_ = GL_FALSE;
    GLint cullFace_ = 0, frontFace_ = 0;
    GLboolean offsetFill_ = GL_FALSE, offsetLine_ = GL_FALSE, offsetPoint_ = GL_FALSE;
    GLfloat offsetFactor_ = 0.0f, offsetUnits_ = 0.0f;
    std::array<GLboolean, 8> clipDistances_{};
    GLboolean seamless_ = GL_FALSE, framebufferSrgb_ = GL_FALSE, rasterizerDiscard_ = GL_FALSE;
    GLboolean primitiveRestart_ = GL_FALSE, primitiveRestartFixed_ = GL_FALSE;
    GLint clipOrigin_ = 0, clipDepthMode_ = 0, polygonMode_ = 0;
    GLint packAlignment_ = 4, unpackAlignment_ = 4, packRowLength_ = 0, unpackRowLength_ = 0, unpackImageHeight_ = 0;
    GLint packSkipPixels_ = 0, packSkipRows_ = 0, unpackSkipPixels_ = 0, unpackSkipRows_ = 0, unpackSkipImages_ = 0;
    std::array<GLfloat, 4> clearColor_{};
    GLfloat clearDepth_ = 1.0f;
    GLint clearStencil_ = 0;
};

/// A SavedState on the caller's context (Context::adoptCurrent), none on
/// shadowlab's own (every pass sets its whole RenderState): the Renderer's
/// public calls hold one.
class CallerState {
public:
    explicit CallerState(bool adopted) {
        if (adopted) saved_.emplace();
    }

private:
    std::optional<SavedState> saved_;
};

} // namespace shadowlab::gl
