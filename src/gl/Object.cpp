#include "gl/Object.h"

#include <shadowlab/Context.h>
#include <shadowlab/Error.h>

#include "gl/Debug.h"

#include <algorithm>
#include <string>

namespace shadowlab::gl {

void reserveBuffer(Buffer& buffer, std::size_t& capacity, std::size_t bytes) {
    if (bytes <= capacity && buffer.id() != 0) return;
    capacity = std::max(bytes, capacity * 2);
    buffer = Buffer();
    glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void checkFramebuffer(const Framebuffer& fb, const char* what) {
    GLenum status = GL_FRAMEBUFFER_COMPLETE;
    {
        QuietDebugOutput quiet;  // the driver's reason is not the user's: the error below says it
        status = glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER);
    }
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        // An attachment the GPU had no memory for is the usual cause.
        throwIfOutOfMemory((std::string("making the ") + what).c_str());
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", status);
        throw Error(std::string(what) + ": framebuffer incomplete (status " + hex + ")");
    }
}

} // namespace shadowlab::gl

namespace shadowlab {

long liveGlObjects() { return gl::liveObjects.load(); }

} // namespace shadowlab
