#pragma once
/// @file Error.h
/// The one exception type shadowlab throws at its boundary.
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
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

} // namespace shadowlab
