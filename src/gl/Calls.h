#pragma once
// The OpenGL calls shadowlab makes that OpenGL ES 3.0 (WebGL 2) lacks or
// spells differently: direct state access, program uniforms by program,
// texture clears and views, timer queries, compute, per-draw-buffer state,
// clip control, multi-draw, debug output. Outside src/gl, code calls these
// wrappers, never the GL functions themselves (tests/code/gl_calls.py checks
// it), so that a second GL flavour is a second body for each of them here.
// Each has the GL 4.5 function's parameters and calls it.
#include <epoxy/gl.h>

namespace shadowlab::gl {


// Textures bound to units.
inline void bindTextureUnit(GLuint unit, GLuint texture) { glBindTextureUnit(unit, texture); }

// Framebuffers, edited by name.
inline void namedFramebufferTexture(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level) { glNamedFramebufferTexture(framebuffer, attachment, texture, level); }
inline void namedFramebufferTextureLayer(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level, GLint layer) { glNamedFramebufferTextureLayer(framebuffer, attachment, texture, level, layer); }
inline void namedFramebufferDrawBuffer(GLuint framebuffer, GLenum buf) { glNamedFramebufferDrawBuffer(framebuffer, buf); }
inline void namedFramebufferDrawBuffers(GLuint framebuffer, GLsizei n, const GLenum * bufs) { glNamedFramebufferDrawBuffers(framebuffer, n, bufs); }
inline void namedFramebufferReadBuffer(GLuint framebuffer, GLenum src) { glNamedFramebufferReadBuffer(framebuffer, src); }
inline void clearNamedFramebufferfv(GLuint framebuffer, GLenum buffer, GLint drawbuffer, const GLfloat * value) { glClearNamedFramebufferfv(framebuffer, buffer, drawbuffer, value); }
inline void clearNamedFramebufferfi(GLuint framebuffer, GLenum buffer, GLint drawbuffer, GLfloat depth, GLint stencil) { glClearNamedFramebufferfi(framebuffer, buffer, drawbuffer, depth, stencil); }
inline void clearNamedFramebufferiv(GLuint framebuffer, GLenum buffer, GLint drawbuffer, const GLint * value) { glClearNamedFramebufferiv(framebuffer, buffer, drawbuffer, value); }
inline GLenum checkNamedFramebufferStatus(GLuint framebuffer, GLenum target) { return glCheckNamedFramebufferStatus(framebuffer, target); }
inline void blitNamedFramebuffer(GLuint readFramebuffer, GLuint drawFramebuffer, GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter) { glBlitNamedFramebuffer(readFramebuffer, drawFramebuffer, srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1, mask, filter); }

// Buffers, edited by name.
inline void namedBufferStorage(GLuint buffer, GLsizeiptr size, const void * data, GLbitfield flags) { glNamedBufferStorage(buffer, size, data, flags); }
inline void namedBufferSubData(GLuint buffer, GLintptr offset, GLsizeiptr size, const void * data) { glNamedBufferSubData(buffer, offset, size, data); }
inline void namedBufferData(GLuint buffer, GLsizeiptr size, const void * data, GLenum usage) { glNamedBufferData(buffer, size, data, usage); }
inline void copyNamedBufferSubData(GLuint readBuffer, GLuint writeBuffer, GLintptr readOffset, GLintptr writeOffset, GLsizeiptr size) { glCopyNamedBufferSubData(readBuffer, writeBuffer, readOffset, writeOffset, size); }
inline void getNamedBufferSubData(GLuint buffer, GLintptr offset, GLsizeiptr size, void * data) { glGetNamedBufferSubData(buffer, offset, size, data); }
inline void * mapNamedBufferRange(GLuint buffer, GLintptr offset, GLsizeiptr length, GLbitfield access) { return glMapNamedBufferRange(buffer, offset, length, access); }

// Textures: storage, parameters, uploads, read-back, clears, views.
inline void textureStorage2D(GLuint texture, GLsizei levels, GLenum internalformat, GLsizei width, GLsizei height) { glTextureStorage2D(texture, levels, internalformat, width, height); }
inline void textureStorage3D(GLuint texture, GLsizei levels, GLenum internalformat, GLsizei width, GLsizei height, GLsizei depth) { glTextureStorage3D(texture, levels, internalformat, width, height, depth); }
inline void textureParameteri(GLuint texture, GLenum pname, GLint param) { glTextureParameteri(texture, pname, param); }
inline void textureParameterfv(GLuint texture, GLenum pname, const GLfloat * param) { glTextureParameterfv(texture, pname, param); }
inline void textureSubImage2D(GLuint texture, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height, GLenum format, GLenum type, const void * pixels) { glTextureSubImage2D(texture, level, xoffset, yoffset, width, height, format, type, pixels); }
inline void getTextureSubImage(GLuint texture, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, GLsizei bufSize, void * pixels) { glGetTextureSubImage(texture, level, xoffset, yoffset, zoffset, width, height, depth, format, type, bufSize, pixels); }
inline void getTextureImage(GLuint texture, GLint level, GLenum format, GLenum type, GLsizei bufSize, void * pixels) { glGetTextureImage(texture, level, format, type, bufSize, pixels); }
inline void clearTexSubImage(GLuint texture, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void * data) { glClearTexSubImage(texture, level, xoffset, yoffset, zoffset, width, height, depth, format, type, data); }
inline void clearTexImage(GLuint texture, GLint level, GLenum format, GLenum type, const void * data) { glClearTexImage(texture, level, format, type, data); }
inline void generateTextureMipmap(GLuint texture) { glGenerateTextureMipmap(texture); }
inline void textureView(GLuint texture, GLenum target, GLuint origtexture, GLenum internalformat, GLuint minlevel, GLuint numlevels, GLuint minlayer, GLuint numlayers) { glTextureView(texture, target, origtexture, internalformat, minlevel, numlevels, minlayer, numlayers); }

// Vertex arrays, edited by name.
inline void vertexArrayAttribFormat(GLuint vaobj, GLuint attribindex, GLint size, GLenum type, GLboolean normalized, GLuint relativeoffset) { glVertexArrayAttribFormat(vaobj, attribindex, size, type, normalized, relativeoffset); }
inline void vertexArrayAttribBinding(GLuint vaobj, GLuint attribindex, GLuint bindingindex) { glVertexArrayAttribBinding(vaobj, attribindex, bindingindex); }
inline void enableVertexArrayAttrib(GLuint vaobj, GLuint index) { glEnableVertexArrayAttrib(vaobj, index); }
inline void vertexArrayVertexBuffer(GLuint vaobj, GLuint bindingindex, GLuint buffer, GLintptr offset, GLsizei stride) { glVertexArrayVertexBuffer(vaobj, bindingindex, buffer, offset, stride); }
inline void vertexArrayElementBuffer(GLuint vaobj, GLuint buffer) { glVertexArrayElementBuffer(vaobj, buffer); }

// Program uniforms, set by program (no glUseProgram).
inline void programUniform1i(GLuint program, GLint location, GLint v0) { glProgramUniform1i(program, location, v0); }
inline void programUniform1f(GLuint program, GLint location, GLfloat v0) { glProgramUniform1f(program, location, v0); }
inline void programUniform1ui(GLuint program, GLint location, GLuint v0) { glProgramUniform1ui(program, location, v0); }
inline void programUniform1fv(GLuint program, GLint location, GLsizei count, const GLfloat * value) { glProgramUniform1fv(program, location, count, value); }
inline void programUniform2i(GLuint program, GLint location, GLint v0, GLint v1) { glProgramUniform2i(program, location, v0, v1); }
inline void programUniform2f(GLuint program, GLint location, GLfloat v0, GLfloat v1) { glProgramUniform2f(program, location, v0, v1); }
inline void programUniform2fv(GLuint program, GLint location, GLsizei count, const GLfloat * value) { glProgramUniform2fv(program, location, count, value); }
inline void programUniform3fv(GLuint program, GLint location, GLsizei count, const GLfloat * value) { glProgramUniform3fv(program, location, count, value); }
inline void programUniform4fv(GLuint program, GLint location, GLsizei count, const GLfloat * value) { glProgramUniform4fv(program, location, count, value); }
inline void programUniform4d(GLuint program, GLint location, GLdouble v0, GLdouble v1, GLdouble v2, GLdouble v3) { glProgramUniform4d(program, location, v0, v1, v2, v3); }
inline void programUniformMatrix4fv(GLuint program, GLint location, GLsizei count, GLboolean transpose, const GLfloat * value) { glProgramUniformMatrix4fv(program, location, count, transpose, value); }

// Timer queries.
inline void queryCounter(GLuint id, GLenum target) { glQueryCounter(id, target); }
inline void getQueryObjectui64v(GLuint id, GLenum pname, GLuint64 * params) { glGetQueryObjectui64v(id, pname, params); }

// Compute.
inline void memoryBarrier(GLbitfield barriers) { glMemoryBarrier(barriers); }
inline void dispatchCompute(GLuint num_groups_x, GLuint num_groups_y, GLuint num_groups_z) { glDispatchCompute(num_groups_x, num_groups_y, num_groups_z); }

// Per-draw-buffer state (ES 3.2), clip control, multi-draw.
inline void enablei(GLenum target, GLuint index) { glEnablei(target, index); }
inline void disablei(GLenum target, GLuint index) { glDisablei(target, index); }
inline void blendFunci(GLuint buf, GLenum src, GLenum dst) { glBlendFunci(buf, src, dst); }
inline void blendEquationi(GLuint buf, GLenum mode) { glBlendEquationi(buf, mode); }
inline void clipControl(GLenum origin, GLenum depth) { glClipControl(origin, depth); }
inline void multiDrawElements(GLenum mode, const GLsizei * count, GLenum type, const void *const* indices, GLsizei drawcount) { glMultiDrawElements(mode, count, type, indices, drawcount); }

// Debug output.
inline void debugMessageControl(GLenum source, GLenum type, GLenum severity, GLsizei count, const GLuint * ids, GLboolean enabled) { glDebugMessageControl(source, type, severity, count, ids, enabled); }
inline void debugMessageCallback(GLDEBUGPROC callback, const void * userParam) { glDebugMessageCallback(callback, userParam); }

// Object creation (glCreate*: created with their state).
inline void createBuffers(GLsizei n, GLuint * buffers) { glCreateBuffers(n, buffers); }
inline void createVertexArrays(GLsizei n, GLuint * arrays) { glCreateVertexArrays(n, arrays); }
inline void createTextures(GLenum target, GLsizei n, GLuint * textures) { glCreateTextures(target, n, textures); }
inline void createSamplers(GLsizei n, GLuint * samplers) { glCreateSamplers(n, samplers); }
inline void createFramebuffers(GLsizei n, GLuint * framebuffers) { glCreateFramebuffers(n, framebuffers); }
inline void createQueries(GLenum target, GLsizei n, GLuint * ids) { glCreateQueries(target, n, ids); }

} // namespace shadowlab::gl
