#include "gl/Debug.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <epoxy/gl.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace shadowlab::gl {

namespace {
thread_local bool quiet = false;

void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                               const GLchar* message, const void* user) {
    auto& state = *static_cast<DebugState*>(const_cast<void*>(user));
    const bool error = type == GL_DEBUG_TYPE_ERROR;
    if (error) {
        state.errors.fetch_add(1);
        std::lock_guard lock(state.mutex);
        state.lastError = message;
    }
    if (quiet && !state.verbose) return;
    // Out of memory is said in one line by throwIfOutOfMemory or the run's error count.
    if (error && std::string_view(message).find("GL_OUT_OF_MEMORY") != std::string_view::npos && !state.verbose) return;
    const bool important = severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM;
    if (error || (important && type != GL_DEBUG_TYPE_PERFORMANCE) || state.verbose)
        std::fprintf(stderr, "shadowlab: GL %s: %s\n", error ? "error" : "debug", message);
}

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "";
}
int glInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}
} // namespace

void installDebugOutput(DebugState& state) {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, &state);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

DeviceMemory queryDeviceMemory(const std::function<bool(const char*)>& hasExtension,
                               const std::function<void(unsigned pname, int* values)>& getIntegerv) {
    constexpr unsigned kNvxCurrentAvailableVidmem = 0x9049;  // GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
    constexpr unsigned kAtiTextureFreeMemory = 0x87FC;       // GL_TEXTURE_FREE_MEMORY_ATI: 4 values, [0] total free
    int values[4] = {0, 0, 0, 0};
    if (hasExtension("GL_NVX_gpu_memory_info")) {
        getIntegerv(kNvxCurrentAvailableVidmem, values);
        if (values[0] > 0) return {1024LL * values[0], "GL_NVX_gpu_memory_info"};
    }
    if (hasExtension("GL_ATI_meminfo")) {
        getIntegerv(kAtiTextureFreeMemory, values);
        if (values[0] > 0) return {1024LL * values[0], "GL_ATI_meminfo"};
    }
    return {};
}

QuietDebugOutput::QuietDebugOutput() : wasQuiet_(quiet) { quiet = true; }
QuietDebugOutput::~QuietDebugOutput() { quiet = wasQuiet_; }

void throwIfOutOfMemory(const char* where) {
    bool outOfMemory = false;
    for (int i = 0; i < 64; ++i) {  // GL keeps one flag per error kind; a lost context may never clear them
        const GLenum error = glGetError();
        if (error == GL_NO_ERROR) break;
        outOfMemory = outOfMemory || error == GL_OUT_OF_MEMORY;
    }
    if (outOfMemory)
        throw Error(std::string("the GPU ran out of memory ") + where +
                    " (GL_OUT_OF_MEMORY): lower --width/--height or lights[i].shadow.map.size");
}

GlInfo queryGlInfo() {
    GlInfo info;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    info.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    info.maxTextureSize = glInt(GL_MAX_TEXTURE_SIZE);
    info.maxCubeMapSize = glInt(GL_MAX_CUBE_MAP_TEXTURE_SIZE);
    info.maxArrayLayers = glInt(GL_MAX_ARRAY_TEXTURE_LAYERS);
    info.maxRenderbufferSize = glInt(GL_MAX_RENDERBUFFER_SIZE);
    GLint dims[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
    info.maxViewportWidth = dims[0];
    info.maxViewportHeight = dims[1];
    // SHADOWLAB_DEVICE_MEMORY_KIB stands in for a driver with
    // GL_NVX_gpu_memory_info reporting that much free memory (llvmpipe
    // reports none): the tests check the device-memory guard through it.
    const char* injected = std::getenv("SHADOWLAB_DEVICE_MEMORY_KIB");
    int injectedKiB = 0;
    if (injected && *injected) {
        const std::string value = injected;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), injectedKiB);
        if (ec != std::errc() || end != value.data() + value.size() || injectedKiB <= 0)
            throw Error(text::escapeControl(text::clipMiddle("SHADOWLAB_DEVICE_MEMORY_KIB=" + value)) +
                        ": expected a whole number of KiB in 1..2147483647");
    }
    const DeviceMemory memory =
        injectedKiB > 0 ? queryDeviceMemory([](const char* name) { return std::string(name) == "GL_NVX_gpu_memory_info"; },
                                            [injectedKiB](unsigned, int* values) { values[0] = injectedKiB; })
                        : queryDeviceMemory([](const char* name) { return epoxy_has_gl_extension(name); },
                                            [](unsigned pname, int* values) { glGetIntegerv(pname, values); });
    info.deviceMemoryBytes = memory.bytes;
    info.deviceMemorySource = injectedKiB > 0 ? "SHADOWLAB_DEVICE_MEMORY_KIB" : memory.source;
    return info;
}

void requireGl45(const char* platform) {
    const int version = epoxy_gl_version();
    GLint mask = 0;
    if (version >= 32) glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    if (version < 45 || !(mask & GL_CONTEXT_CORE_PROFILE_BIT))
        throw Error(std::string(platform) + ": OpenGL 4.5 core is required, found '" + glString(GL_VERSION) + "'" +
                    (mask & GL_CONTEXT_CORE_PROFILE_BIT ? "" : " (not a core profile)"));
}

} // namespace shadowlab::gl
