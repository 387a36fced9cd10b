#include "gl/Object.h"

#include <shadowlab/Context.h>
#include <shadowlab/Error.h>

#include <string>

namespace shadowlab::gl {

void checkFramebuffer(const Framebuffer& fb, const char* what) {
    const GLenum status = glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", status);
        throw Error(std::string(what) + ": framebuffer incomplete (status " + hex + ")");
    }
}

} // namespace shadowlab::gl

namespace shadowlab {

long liveGlObjects() { return gl::liveObjects.load(); }

} // namespace shadowlab
