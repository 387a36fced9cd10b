#pragma once
// A linked GLSL program built from embedded shader files and a variant preamble.
#include "gl/Object.h"

#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::gl {

struct ShaderStage {
    GLenum type;           ///< GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER ...
    std::string file;      ///< embedded file name, e.g. "scene.vert"
};

class Program {
public:
    explicit Program(NoCreateT) noexcept : handle_(NoCreate) {}
    /// Compiles and links. Throws shadowlab::Error whose message names the
    /// shader file, the failing line and its text.
    Program(const std::vector<ShaderStage>& stages, std::string_view preamble);

    GLuint id() const noexcept { return handle_.id(); }
    void use() const { glUseProgram(handle_.id()); }
    /// Uniform location, -1 if the uniform is inactive in this variant.
    GLint uniform(const char* name) const { return glGetUniformLocation(handle_.id(), name); }

private:
    ProgramHandle handle_;
};

} // namespace shadowlab::gl
