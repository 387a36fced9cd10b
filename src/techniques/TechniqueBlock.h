#pragma once
// A technique's uniform block: the std140 struct `Block` (from the
// technique's shared header) in a GL buffer made on first use, bound at
// SL_BINDING_TECHNIQUE, where the technique's shaders read it.
#include "gl/Object.h"

#include "gl/Calls.h"
#include "shadowlab_shared.h"

#include <cstddef>

namespace shadowlab {

template <class Block>
class TechniqueBlock {
public:
    /// Writes the whole block and binds it at SL_BINDING_TECHNIQUE.
    void write(const Block& block) {
        writePart(0, sizeof block, &block);
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_TECHNIQUE, buffer_.id());
    }
    /// Writes `size` bytes at byte `offset` of the block (its binding unchanged).
    void writePart(std::size_t offset, std::size_t size, const void* data) {
        made();
        gl::namedBufferSubData(buffer_.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(size), data);
    }
    /// Copies `size` bytes at byte `from` of buffer `source` to byte
    /// `offset` of the block, on the GPU (what a shader wrote there).
    void copyPart(const gl::Buffer& source, std::size_t from, std::size_t offset, std::size_t size) {
        made();
        gl::copyNamedBufferSubData(source.id(), buffer_.id(), static_cast<GLintptr>(from), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(size));
    }

private:
    void made() {
        if (buffer_) return;
        buffer_ = gl::Buffer();
        gl::namedBufferStorage(buffer_.id(), sizeof(Block), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    gl::Buffer buffer_{gl::NoCreate};
};

} // namespace shadowlab
