// The caller's own context, current on the calling thread
// (Context::adoptCurrent): shadowlab draws into it and owns nothing of it;
// the renderer puts back the GL state it changes (SavedState.h).
#include "gl/Debug.h"

#include <shadowlab/Context.h>
#include <shadowlab/Error.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

namespace shadowlab {

namespace {

// The current context's handle where EGL made it, else GL's answer that
// one is current (GLFW's and Qt's GLX contexts): nullptr when none is.
const void* currentContext() {
    if (epoxy_has_egl()) {
        const EGLContext egl = eglGetCurrentContext();
        if (egl != EGL_NO_CONTEXT) return egl;
    }
    return glGetString(GL_VERSION);
}

struct AdoptedImpl final : Context::Impl {
    const void* handle = nullptr;  ///< the EGL context adopted, or GL's version string (GLX)
    bool ownCallback = false;      ///< shadowlab's debug callback replaced the caller's
    GLDEBUGPROC callerCallback = nullptr;
    const void* callerParam = nullptr;
    GLboolean callerOutput = GL_FALSE, callerSynchronous = GL_FALSE;

    bool current() const { return currentContext() == handle && handle != nullptr; }
    void makeCurrent() override {
        if (!current()) throw Error("Context::makeCurrent: the adopted context is not current on this thread (make it current the way it was made)");
    }
    void releaseCurrent() override {}
    ~AdoptedImpl() override {
        if (!current()) return;  // the caller destroyed or switched its context first: nothing of it can be touched
        releaseGlObjects();
        if (!ownCallback) return;
        glDebugMessageCallback(callerCallback, callerParam);
        callerOutput ? glEnable(GL_DEBUG_OUTPUT) : glDisable(GL_DEBUG_OUTPUT);
        callerSynchronous ? glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS) : glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    }
};

} // namespace

Context Context::adoptCurrent(const ContextOptions& options) {
    auto impl = std::make_unique<AdoptedImpl>();
    impl->handle = currentContext();
    if (!impl->handle) throw Error("Context::adoptCurrent: no OpenGL context is current on this thread (make the application's context current first)");
    impl->adopted = true;
    impl->debug.verbose = options.verbose;
    gl::requireGl45("adopted");
    impl->info = gl::queryGlInfo();
    impl->info.platform = "adopted";
    if (options.debug) {
        void* callback = nullptr;
        void* param = nullptr;
        glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &callback);
        glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &param);
        impl->callerCallback = reinterpret_cast<GLDEBUGPROC>(callback);
        impl->callerParam = param;
        impl->callerOutput = glIsEnabled(GL_DEBUG_OUTPUT);
        impl->callerSynchronous = glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        impl->ownCallback = true;
        gl::installDebugOutput(impl->debug);
    }
    return Context(std::move(impl));
}

} // namespace shadowlab
