#pragma once
// A linked GLSL program built from embedded shader files and a variant
// preamble, and the cache that compiles each distinct program once per context.
#include "gl/Object.h"
#include "gl/ShaderSource.h"

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::gl {

struct ShaderStage {
    GLenum type;           ///< GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER ...
    std::string file;      ///< embedded file name, e.g. "scene.vert"
    /// When not empty, the stage's GLSL text itself (tests, generated code);
    /// `file` then only names it in messages.
    std::string inlineText = {};
};

/// Everything that makes one program: its stages, the variant's `#define`
/// preamble and the files that fill `#include "@slot"` lines.
struct ProgramKey {
    std::vector<ShaderStage> stages;
    std::string preamble;
    IncludeAliases aliases = {};

    /// A string unique per distinct program (stages, texts, preamble, aliases).
    std::string id() const;
};

class Program {
public:
    explicit Program(NoCreateT) noexcept : handle_(NoCreate) {}
    /// Compiles and links. Throws shadowlab::Error whose message names the
    /// shader file, the failing line and its text.
    Program(const std::vector<ShaderStage>& stages, std::string_view preamble, const IncludeAliases& aliases = {});
    explicit Program(const ProgramKey& key) : Program(key.stages, key.preamble, key.aliases) {}

    GLuint id() const noexcept { return handle_.id(); }
    void use() const { glUseProgram(handle_.id()); }
    /// Uniform location, -1 if the uniform is inactive in this variant.
    GLint uniform(const char* name) const { return glGetUniformLocation(handle_.id(), name); }

private:
    ProgramHandle handle_;
};

/// Programs by ProgramKey::id(), compiled on first use. One lives in each
/// Context (Context::Impl) and is shared by every Renderer and technique on
/// it, so `bench` compiles a variant once for all its combinations.
class ProgramCache {
public:
    const Program& get(const ProgramKey& key);
    std::size_t size() const { return programs_.size(); }
    /// Programs compiled since creation (a cache hit compiles nothing).
    std::size_t compiles() const { return compiles_; }

private:
    std::map<std::string, std::unique_ptr<Program>, std::less<>> programs_;
    std::size_t compiles_ = 0;
};

} // namespace shadowlab::gl
