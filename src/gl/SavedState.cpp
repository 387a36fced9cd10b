// The caller's GL state around a shadowlab call (SavedState.h).
#include "gl/SavedState.h"

namespace shadowlab::gl {

namespace {

constexpr GLenum kTextureTargets[] = {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_3D,
                                      GL_TEXTURE_2D_MULTISAMPLE};
constexpr GLenum kTextureBindings[] = {GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_2D_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP,
                                       GL_TEXTURE_BINDING_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_3D, GL_TEXTURE_BINDING_2D_MULTISAMPLE};

GLint integer(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

GLint integer(GLenum name, GLuint index) {
    GLint v = 0;
    glGetIntegeri_v(name, index, &v);
    return v;
}

void setEnabled(GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); }

} // namespace

SavedState::SavedState() {
    readBindings();
    readFixedFunction();
    readPixelStore();
    assumeDefaults();
}

SavedState::~SavedState() {
    writeBindings();
    writeFixedFunction();
    writePixelStore();
}

void SavedState::readBindings() {
    drawFramebuffer_ = integer(GL_DRAW_FRAMEBUFFER_BINDING);
    readFramebuffer_ = integer(GL_READ_FRAMEBUFFER_BINDING);
    program_ = integer(GL_CURRENT_PROGRAM);
    pipeline_ = integer(GL_PROGRAM_PIPELINE_BINDING);
    vertexArray_ = integer(GL_VERTEX_ARRAY_BINDING);
    arrayBuffer_ = integer(GL_ARRAY_BUFFER_BINDING);
    uniformBuffer_ = integer(GL_UNIFORM_BUFFER_BINDING);
    storageBuffer_ = integer(GL_SHADER_STORAGE_BUFFER_BINDING);
    packBuffer_ = integer(GL_PIXEL_PACK_BUFFER_BINDING);
    unpackBuffer_ = integer(GL_PIXEL_UNPACK_BUFFER_BINDING);
    drawIndirect_ = integer(GL_DRAW_INDIRECT_BUFFER_BINDING);
    dispatchIndirect_ = integer(GL_DISPATCH_INDIRECT_BUFFER_BINDING);
    copyRead_ = integer(GL_COPY_READ_BUFFER_BINDING);
    copyWrite_ = integer(GL_COPY_WRITE_BUFFER_BINDING);
    for (GLuint i = 0; i < kSavedBufferBindings; ++i) {
        IndexedBuffer& u = uniformBuffers_[i];
        u.buffer = integer(GL_UNIFORM_BUFFER_BINDING, i);
        glGetInteger64i_v(GL_UNIFORM_BUFFER_START, i, &u.start);
        glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, i, &u.size);
        IndexedBuffer& s = storageBuffers_[i];
        s.buffer = integer(GL_SHADER_STORAGE_BUFFER_BINDING, i);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, i, &s.start);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, i, &s.size);
    }
    activeTexture_ = integer(GL_ACTIVE_TEXTURE);
    for (int unit = 0; unit < kSavedTextureUnits; ++unit) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        for (int t = 0; t < kTargets; ++t) textures_[static_cast<std::size_t>(unit)][static_cast<std::size_t>(t)] = integer(kTextureBindings[t]);
        samplers_[static_cast<std::size_t>(unit)] = integer(GL_SAMPLER_BINDING);
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
}

void SavedState::readFixedFunction() {
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox_.data());
    scissorTest_ = glIsEnabled(GL_SCISSOR_TEST);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    depthFunc_ = integer(GL_DEPTH_FUNC);
    depthClamp_ = glIsEnabled(GL_DEPTH_CLAMP);
    stencilTest_ = glIsEnabled(GL_STENCIL_TEST);
    front_ = {integer(GL_STENCIL_FUNC), integer(GL_STENCIL_REF), integer(GL_STENCIL_VALUE_MASK), integer(GL_STENCIL_WRITEMASK),
              integer(GL_STENCIL_FAIL), integer(GL_STENCIL_PASS_DEPTH_FAIL), integer(GL_STENCIL_PASS_DEPTH_PASS)};
    back_ = {integer(GL_STENCIL_BACK_FUNC), integer(GL_STENCIL_BACK_REF), integer(GL_STENCIL_BACK_VALUE_MASK), integer(GL_STENCIL_BACK_WRITEMASK),
             integer(GL_STENCIL_BACK_FAIL), integer(GL_STENCIL_BACK_PASS_DEPTH_FAIL), integer(GL_STENCIL_BACK_PASS_DEPTH_PASS)};
    for (GLuint i = 0; i < blend_.size(); ++i) {
        BlendTarget& b = blend_[i];
        b.enabled = glIsEnabledi(GL_BLEND, i);
        b.srcRgb = integer(GL_BLEND_SRC_RGB, i);
        b.dstRgb = integer(GL_BLEND_DST_RGB, i);
        b.srcAlpha = integer(GL_BLEND_SRC_ALPHA, i);
        b.dstAlpha = integer(GL_BLEND_DST_ALPHA, i);
        b.equationRgb = integer(GL_BLEND_EQUATION_RGB, i);
        b.equationAlpha = integer(GL_BLEND_EQUATION_ALPHA, i);
        glGetBooleani_v(GL_COLOR_WRITEMASK, i, b.colorMask.data());
    }
    glGetFloatv(GL_BLEND_COLOR, blendColor_.data());
    cull_ = glIsEnabled(GL_CULL_FACE);
    cullFace_ = integer(GL_CULL_FACE_MODE);
    frontFace_ = integer(GL_FRONT_FACE);
    offsetFill_ = glIsEnabled(GL_POLYGON_OFFSET_FILL);
    offsetLine_ = glIsEnabled(GL_POLYGON_OFFSET_LINE);
    offsetPoint_ = glIsEnabled(GL_POLYGON_OFFSET_POINT);
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &offsetFactor_);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &offsetUnits_);
    for (int i = 0; i < 8; ++i) clipDistances_[static_cast<std::size_t>(i)] = glIsEnabled(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i));
    seamless_ = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    framebufferSrgb_ = glIsEnabled(GL_FRAMEBUFFER_SRGB);
    rasterizerDiscard_ = glIsEnabled(GL_RASTERIZER_DISCARD);
    primitiveRestart_ = glIsEnabled(GL_PRIMITIVE_RESTART);
    primitiveRestartFixed_ = glIsEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX);
    clipOrigin_ = integer(GL_CLIP_ORIGIN);
    clipDepthMode_ = integer(GL_CLIP_DEPTH_MODE);
    GLint modes[2] = {GL_FILL, GL_FILL};
    glGetIntegerv(GL_POLYGON_MODE, modes);
    polygonMode_ = modes[0];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor_.data());
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clearDepth_);
    clearStencil_ = integer(GL_STENCIL_CLEAR_VALUE);
}

void SavedState::readPixelStore() {
    packAlignment_ = integer(GL_PACK_ALIGNMENT);
    unpackAlignment_ = integer(GL_UNPACK_ALIGNMENT);
    packRowLength_ = integer(GL_PACK_ROW_LENGTH);
    unpackRowLength_ = integer(GL_UNPACK_ROW_LENGTH);
    unpackImageHeight_ = integer(GL_UNPACK_IMAGE_HEIGHT);
    packSkipPixels_ = integer(GL_PACK_SKIP_PIXELS);
    packSkipRows_ = integer(GL_PACK_SKIP_ROWS);
    unpackSkipPixels_ = integer(GL_UNPACK_SKIP_PIXELS);
    unpackSkipRows_ = integer(GL_UNPACK_SKIP_ROWS);
    unpackSkipImages_ = integer(GL_UNPACK_SKIP_IMAGES);
}

// What shadowlab's passes assume and do not set.
void SavedState::assumeDefaults() {
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    for (const GLenum name : {GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT}) glPixelStorei(name, 4);
    for (const GLenum name : {GL_PACK_ROW_LENGTH, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_ROWS,
                              GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_IMAGES})
        glPixelStorei(name, 0);
    glBindProgramPipeline(0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_PRIMITIVE_RESTART);
    glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
}

void SavedState::writeBindings() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glUseProgram(static_cast<GLuint>(program_));
    glBindProgramPipeline(static_cast<GLuint>(pipeline_));
    glBindVertexArray(static_cast<GLuint>(vertexArray_));
    // Indexed bindings first: glBindBufferBase sets the generic binding too.
    for (GLuint i = 0; i < kSavedBufferBindings; ++i) {
        for (const auto& [target, b] : {std::pair{GLenum(GL_UNIFORM_BUFFER), uniformBuffers_[i]}, std::pair{GLenum(GL_SHADER_STORAGE_BUFFER), storageBuffers_[i]}}) {
            if (b.buffer != 0 && b.size > 0)
                glBindBufferRange(target, i, static_cast<GLuint>(b.buffer), static_cast<GLintptr>(b.start), static_cast<GLsizeiptr>(b.size));
            else
                glBindBufferBase(target, i, static_cast<GLuint>(b.buffer));
        }
    }
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer_));
    glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniformBuffer_));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageBuffer_));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer_));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer_));
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, static_cast<GLuint>(drawIndirect_));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, static_cast<GLuint>(dispatchIndirect_));
    glBindBuffer(GL_COPY_READ_BUFFER, static_cast<GLuint>(copyRead_));
    glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(copyWrite_));
    for (int unit = 0; unit < kSavedTextureUnits; ++unit) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        for (int t = 0; t < kTargets; ++t) glBindTexture(kTextureTargets[t], static_cast<GLuint>(textures_[static_cast<std::size_t>(unit)][static_cast<std::size_t>(t)]));
        glBindSampler(static_cast<GLuint>(unit), static_cast<GLuint>(samplers_[static_cast<std::size_t>(unit)]));
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
}

void SavedState::writeFixedFunction() {
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glScissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
    setEnabled(GL_SCISSOR_TEST, scissorTest_);
    setEnabled(GL_DEPTH_TEST, depthTest_);
    glDepthMask(depthMask_);
    glDepthFunc(static_cast<GLenum>(depthFunc_));
    setEnabled(GL_DEPTH_CLAMP, depthClamp_);
    setEnabled(GL_STENCIL_TEST, stencilTest_);
    for (const auto& [face, s] : {std::pair{GLenum(GL_FRONT), front_}, std::pair{GLenum(GL_BACK), back_}}) {
        glStencilFuncSeparate(face, static_cast<GLenum>(s.func), s.ref, static_cast<GLuint>(s.valueMask));
        glStencilOpSeparate(face, static_cast<GLenum>(s.fail), static_cast<GLenum>(s.depthFail), static_cast<GLenum>(s.depthPass));
        glStencilMaskSeparate(face, static_cast<GLuint>(s.writeMask));
    }
    for (GLuint i = 0; i < blend_.size(); ++i) {
        const BlendTarget& b = blend_[i];
        b.enabled ? glEnablei(GL_BLEND, i) : glDisablei(GL_BLEND, i);
        glBlendFuncSeparatei(i, static_cast<GLenum>(b.srcRgb), static_cast<GLenum>(b.dstRgb), static_cast<GLenum>(b.srcAlpha), static_cast<GLenum>(b.dstAlpha));
        glBlendEquationSeparatei(i, static_cast<GLenum>(b.equationRgb), static_cast<GLenum>(b.equationAlpha));
        glColorMaski(i, b.colorMask[0], b.colorMask[1], b.colorMask[2], b.colorMask[3]);
    }
    glBlendColor(blendColor_[0], blendColor_[1], blendColor_[2], blendColor_[3]);
    setEnabled(GL_CULL_FACE, cull_);
    glCullFace(static_cast<GLenum>(cullFace_));
    glFrontFace(static_cast<GLenum>(frontFace_));
    setEnabled(GL_POLYGON_OFFSET_FILL, offsetFill_);
    setEnabled(GL_POLYGON_OFFSET_LINE, offsetLine_);
    setEnabled(GL_POLYGON_OFFSET_POINT, offsetPoint_);
    glPolygonOffset(offsetFactor_, offsetUnits_);
    for (int i = 0; i < 8; ++i) setEnabled(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i), clipDistances_[static_cast<std::size_t>(i)]);
    setEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS, seamless_);
    setEnabled(GL_FRAMEBUFFER_SRGB, framebufferSrgb_);
    setEnabled(GL_RASTERIZER_DISCARD, rasterizerDiscard_);
    setEnabled(GL_PRIMITIVE_RESTART, primitiveRestart_);
    setEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX, primitiveRestartFixed_);
    glClipControl(static_cast<GLenum>(clipOrigin_), static_cast<GLenum>(clipDepthMode_));
    glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygonMode_));
    glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
    glClearDepth(static_cast<GLdouble>(clearDepth_));
    glClearStencil(clearStencil_);
}

void SavedState::writePixelStore() {
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
    glPixelStorei(GL_PACK_ROW_LENGTH, packRowLength_);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, unpackRowLength_);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, unpackImageHeight_);
    glPixelStorei(GL_PACK_SKIP_PIXELS, packSkipPixels_);
    glPixelStorei(GL_PACK_SKIP_ROWS, packSkipRows_);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, unpackSkipPixels_);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, unpackSkipRows_);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, unpackSkipImages_);
}

} // namespace shadowlab::gl
