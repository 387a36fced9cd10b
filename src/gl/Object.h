#pragma once
// Move-only RAII handles for OpenGL 4.5 objects, created with direct state
// access (glCreate*). One alias per object kind; the destructor deletes the
// object and does nothing for id 0 (a moved-from or NoCreate handle).
#include <epoxy/gl.h>

#include <atomic>
#include <cstddef>
#include <utility>

namespace shadowlab::gl {

/// GL objects owned by handles right now (shadowlab::liveGlObjects()).
inline std::atomic<long> liveObjects{0};

/// Tag for an empty handle that owns no GL object (Magnum's NoCreate).
struct NoCreateT { explicit constexpr NoCreateT() = default; };
inline constexpr NoCreateT NoCreate{};

template <class Traits>
class Object {
public:
    explicit Object(NoCreateT) noexcept {}
    /// Creates the object. Args go to Traits::create (e.g. a texture target).
    template <class... Args>
    explicit Object(Args... args) : id_(Traits::create(args...)) {
        if (id_ != 0) ++liveObjects;
    }
    ~Object() { release(); }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;
    Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            release();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GLuint id() const noexcept { return id_; }
    explicit operator bool() const noexcept { return id_ != 0; }

private:
    void release() {
        if (id_ == 0) return;
        Traits::destroy(id_);
        --liveObjects;
        id_ = 0;
    }
    GLuint id_ = 0;
};

namespace detail {
struct BufferTraits {
    static GLuint create() { GLuint id = 0; glCreateBuffers(1, &id); return id; }
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayTraits {
    static GLuint create() { GLuint id = 0; glCreateVertexArrays(1, &id); return id; }
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct TextureTraits {
    static GLuint create(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return id; }
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
// A view of another texture's levels and layers (glTextureView): named by
// glGenTextures, as a view needs a name never bound to a target.
struct TextureViewTraits {
    static GLuint create(GLenum target, GLuint original, GLenum format, GLuint minLevel, GLuint levels, GLuint minLayer, GLuint layers) {
        GLuint id = 0;
        glGenTextures(1, &id);
        glTextureView(id, target, original, format, minLevel, levels, minLayer, layers);
        return id;
    }
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct SamplerTraits {
    static GLuint create() { GLuint id = 0; glCreateSamplers(1, &id); return id; }
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct FramebufferTraits {
    static GLuint create() { GLuint id = 0; glCreateFramebuffers(1, &id); return id; }
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct QueryTraits {
    static GLuint create(GLenum target) { GLuint id = 0; glCreateQueries(target, 1, &id); return id; }
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct ShaderTraits {
    static GLuint create(GLenum stage) { return glCreateShader(stage); }
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct ProgramTraits {
    static GLuint create() { return glCreateProgram(); }
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
} // namespace detail

using Buffer = Object<detail::BufferTraits>;
using VertexArray = Object<detail::VertexArrayTraits>;
using Texture = Object<detail::TextureTraits>;         ///< Texture(GL_TEXTURE_2D) etc.
using TextureView = Object<detail::TextureViewTraits>; ///< TextureView(GL_TEXTURE_2D, array, format, 0, 1, layer, 1) etc.
using Sampler = Object<detail::SamplerTraits>;
using Framebuffer = Object<detail::FramebufferTraits>;
using Query = Object<detail::QueryTraits>;             ///< Query(GL_TIME_ELAPSED) etc.
using Shader = Object<detail::ShaderTraits>;           ///< Shader(GL_VERTEX_SHADER) etc.
using ProgramHandle = Object<detail::ProgramTraits>;

/// Makes `buffer` hold at least `bytes` (immutable storage, updatable with
/// glNamedBufferSubData): a new buffer of max(bytes, 2 x capacity) when
/// `capacity` (its bytes, updated) is short, so a growing list reallocates
/// rarely. Its contents are not kept.
void reserveBuffer(Buffer& buffer, std::size_t& capacity, std::size_t bytes);

/// Throws shadowlab::Error naming `what` unless the framebuffer is complete.
void checkFramebuffer(const Framebuffer& fb, const char* what);

} // namespace shadowlab::gl
