#pragma once
/// @file Error.h
/// The exception types shadowlab throws at its boundary: Error, and
/// InputError, an Error that blames a value the caller gave.
///
/// Every runtime failure (bad scene file, missing mesh, shader compile error,
/// no OpenGL 4.5, incomplete framebuffer) throws shadowlab::Error whose what()
/// is a single line naming the file or flag, the JSON path or line, and what
/// was expected, e.g. `scene.json: lights[1].direction: expected 3 numbers, got 2`.
#include <shadowlab/Export.h>
#include <stdexcept>
#include <string>

namespace shadowlab {

class SHADOWLAB_API Error : public std::runtime_error {
public:
    /// A NUL byte in `message` (quoted from a user's file) is kept as the
    /// text `\x00`, so that what(), a C string, is not cut there.
    explicit Error(const std::string& message) : std::runtime_error(visibleNul(message)) {}

private:
    static std::string visibleNul(std::string s) {
        for (std::size_t at = s.find('\0'); at != std::string::npos; at = s.find('\0', at + 4)) s.replace(at, 1, "\\x00");
        return s;
    }
};

/// An Error found while drawing that blames a value of the scene or of the
/// call, not the system: a map past the memory budget, a shadow atlas too
/// small for its tiles, a planar receiver that is not there, a frame past
/// the GPU's size limit. what() starts with the value's scene path
/// (`shadowAtlas.size: ...`, `lights[0].shadow.map: ...`), so that
/// withValueSource (SceneFile.h) can name the file or override that set it.
/// Errors in reading a scene are plain Errors (they name their source
/// themselves); GL and system failures are plain Errors too.
class SHADOWLAB_API InputError : public Error {
public:
    using Error::Error;
};

/// An InputError for a combination a light's technique cannot draw (a spot
/// light with cascades, an atlas tile with a soft filter): every value is
/// valid alone. Bench's skipUnsupported leaves such runs out.
class SHADOWLAB_API UnsupportedError : public InputError {
public:
    using InputError::InputError;
};

} // namespace shadowlab
