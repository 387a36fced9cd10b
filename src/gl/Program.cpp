#include "gl/Program.h"

#include "gl/ShaderSource.h"

#include <shadowlab/Error.h>

namespace shadowlab::gl {

namespace {
std::string infoLog(GLuint id, bool program) {
    GLint length = 0;
    if (program) glGetProgramiv(id, GL_INFO_LOG_LENGTH, &length);
    else glGetShaderiv(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    if (program) glGetProgramInfoLog(id, length, nullptr, log.data());
    else glGetShaderInfoLog(id, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}
} // namespace

Program::Program(const std::vector<ShaderStage>& stages, std::string_view preamble, const IncludeAliases& aliases) {
    std::vector<Shader> shaders;
    std::string names;
    for (const ShaderStage& stage : stages) {
        const AssembledSource source =
            assembleShader(stage.file, preamble, aliases,
                           stage.inlineText.empty() ? std::nullopt : std::optional<std::string_view>(stage.inlineText));
        Shader shader(stage.type);
        const char* text = source.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE)
            throw Error("shader compile failed: " + describeShaderLog(infoLog(shader.id(), false), source));
        glAttachShader(handle_.id(), shader.id());
        names += (names.empty() ? "" : "+") + stage.file;
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(handle_.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(handle_.id(), GL_LINK_STATUS, &ok);
    for (const Shader& shader : shaders) glDetachShader(handle_.id(), shader.id());
    if (ok != GL_TRUE) throw Error("shader link failed (" + names + "): " + infoLog(handle_.id(), true));
}

std::string ProgramKey::id() const {
    std::string out = preamble;
    for (const ShaderStage& s : stages) {
        out += "\n@stage " + std::to_string(s.type) + " " + s.file;
        if (!s.inlineText.empty()) out += "\n@text " + std::to_string(s.inlineText.size()) + "\n" + s.inlineText;
    }
    for (const auto& [slot, file] : aliases) out += "\n@alias " + slot + "=" + file;
    return out;
}

const Program& ProgramCache::get(const ProgramKey& key) {
    std::string id = key.id();
    auto it = programs_.find(id);
    if (it == programs_.end()) {
        auto program = std::make_unique<Program>(key);
        ++compiles_;
        it = programs_.emplace(std::move(id), std::move(program)).first;
    }
    return *it->second;
}

} // namespace shadowlab::gl
