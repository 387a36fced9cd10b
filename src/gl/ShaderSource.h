#pragma once
// Assembles GLSL sources from the embedded shader files: version line, a
// variant's #define preamble, and `#include "file"` expanded in place. Each
// file gets its own GLSL source-string number through `#line`, so a compile
// error can be mapped back to the file and line it came from.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::gl {

/// The text of an embedded shader file (shaders/ at build time), or nullopt.
std::optional<std::string_view> embeddedShader(std::string_view name);
/// Names of all embedded shader files.
std::vector<std::string_view> embeddedShaderNames();
/// Adds a shader file at run time (a test's technique, a plug-in). Throws
/// shadowlab::Error when the name is taken by an embedded or added file.
void addShaderFile(const std::string& name, std::string text);
/// An added file's text, else an embedded one's, or nullopt.
std::optional<std::string_view> shaderFile(std::string_view name);

struct AssembledSource {
    std::string text;
    /// GLSL source-string number -> file name; 0 is the generated preamble.
    std::vector<std::string> files;
    /// The text of a file given inline (empty when it was embedded), for messages.
    std::string inlineText;
};

/// `#include "@name"` lines resolve through these (alias, file) pairs: a
/// variant chooses which file fills a slot, e.g. "@shadow" -> "shadow_none.glsl".
/// `#include "@name?"` is optional: it expands to nothing when no pair names it.
using IncludeAliases = std::vector<std::pair<std::string, std::string>>;

/// Assembles `fileName` with `preamble` (lines of #define). When
/// `inlineText` is given it is the file's text (test-only or generated
/// shaders) and `fileName` only names it in messages. Throws
/// shadowlab::Error for a missing file, a missing include or alias, or an
/// include cycle.
AssembledSource assembleShader(std::string_view fileName, std::string_view preamble,
                               const IncludeAliases& aliases = {}, std::optional<std::string_view> inlineText = {});

/// Rewrites a driver's info log so that each message names the shader file,
/// the line and that line's text, e.g.
/// `lighting.frag:42: error: 'foo' undeclared | vec3 c = foo;`
/// Understands the "N:L(C):" (Mesa) and "N(L) :" (NVIDIA) forms; other lines pass through.
std::string describeShaderLog(std::string_view log, const AssembledSource& source);

} // namespace shadowlab::gl
