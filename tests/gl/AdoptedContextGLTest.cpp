// A caller's own context (Context::adoptCurrent): every Renderer call puts
// back the GL state it changes. The caller sets every piece of the state
// Context.h lists to a value shadowlab would not leave (its own objects
// bound on every unit and binding, odd viewport, masks, functions), and
// after each Renderer call, for every technique, that state is read again
// field by field (this test's own reads, not the library's SavedState) and
// must be as the caller left it.
#include "GLTestContext.h"

#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <epoxy/gl.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::GLTest;
namespace fs = std::filesystem;

namespace {

using State = std::map<std::string, std::vector<double>>;

std::vector<double> ints(GLenum name, int count = 1) {
    std::vector<GLint> v(static_cast<std::size_t>(count), 0);
    glGetIntegerv(name, v.data());
    return {v.begin(), v.end()};
}
double indexed(GLenum name, GLuint i) {
    GLint64 v = 0;
    glGetInteger64i_v(name, i, &v);
    return static_cast<double>(v);
}
std::vector<double> floats(GLenum name, int count = 1) {
    std::vector<GLfloat> v(static_cast<std::size_t>(count), 0.0f);
    glGetFloatv(name, v.data());
    return {v.begin(), v.end()};
}

// The state Context::adoptCurrent promises to keep, read field by field.
State readState() {
    State s;
    for (const auto& [name, e] : std::vector<std::pair<const char*, GLenum>>{
             {"draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING}, {"read framebuffer", GL_READ_FRAMEBUFFER_BINDING},
             {"program", GL_CURRENT_PROGRAM}, {"vertex array", GL_VERTEX_ARRAY_BINDING}, {"array buffer", GL_ARRAY_BUFFER_BINDING},
             {"uniform buffer", GL_UNIFORM_BUFFER_BINDING}, {"storage buffer", GL_SHADER_STORAGE_BUFFER_BINDING},
             {"pack buffer", GL_PIXEL_PACK_BUFFER_BINDING}, {"unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING},
             {"active texture", GL_ACTIVE_TEXTURE}, {"depth func", GL_DEPTH_FUNC}, {"cull face", GL_CULL_FACE_MODE},
             {"front face", GL_FRONT_FACE}, {"clip origin", GL_CLIP_ORIGIN}, {"clip depth", GL_CLIP_DEPTH_MODE},
             {"stencil func", GL_STENCIL_FUNC}, {"stencil ref", GL_STENCIL_REF}, {"stencil value mask", GL_STENCIL_VALUE_MASK},
             {"stencil write mask", GL_STENCIL_WRITEMASK}, {"stencil fail", GL_STENCIL_FAIL}, {"stencil depth fail", GL_STENCIL_PASS_DEPTH_FAIL},
             {"stencil pass", GL_STENCIL_PASS_DEPTH_PASS}, {"back stencil func", GL_STENCIL_BACK_FUNC},
             {"back stencil write mask", GL_STENCIL_BACK_WRITEMASK}, {"back stencil pass", GL_STENCIL_BACK_PASS_DEPTH_PASS},
             {"pack alignment", GL_PACK_ALIGNMENT}, {"unpack alignment", GL_UNPACK_ALIGNMENT}, {"pack row length", GL_PACK_ROW_LENGTH}})
        s[name] = ints(e);
    s["viewport"] = ints(GL_VIEWPORT, 4);
    s["polygon mode"] = ints(GL_POLYGON_MODE, 2);
    s["scissor box"] = ints(GL_SCISSOR_BOX, 4);
    s["polygon offset"] = {floats(GL_POLYGON_OFFSET_FACTOR)[0], floats(GL_POLYGON_OFFSET_UNITS)[0]};
    GLboolean depthMask = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    s["depth mask"] = {static_cast<double>(depthMask)};
    for (const auto& [name, e] : std::vector<std::pair<const char*, GLenum>>{
             {"scissor test", GL_SCISSOR_TEST}, {"depth test", GL_DEPTH_TEST}, {"stencil test", GL_STENCIL_TEST}, {"cull", GL_CULL_FACE},
             {"polygon offset fill", GL_POLYGON_OFFSET_FILL}, {"depth clamp", GL_DEPTH_CLAMP}, {"seamless cube maps", GL_TEXTURE_CUBE_MAP_SEAMLESS},
             {"framebuffer sRGB", GL_FRAMEBUFFER_SRGB}})
        s[name] = {static_cast<double>(glIsEnabled(e))};
    for (GLuint i = 0; i < 8; ++i) s["clip distance " + std::to_string(i)] = {static_cast<double>(glIsEnabled(GL_CLIP_DISTANCE0 + i))};
    for (GLuint i = 0; i < 4; ++i) {
        GLboolean mask[4] = {};
        glGetBooleani_v(GL_COLOR_WRITEMASK, i, mask);
        GLint src = 0, dst = 0, equation = 0;
        glGetIntegeri_v(GL_BLEND_SRC_RGB, i, &src);
        glGetIntegeri_v(GL_BLEND_DST_RGB, i, &dst);
        glGetIntegeri_v(GL_BLEND_EQUATION_RGB, i, &equation);
        s["blend " + std::to_string(i)] = {static_cast<double>(glIsEnabledi(GL_BLEND, i)), double(src), double(dst), double(equation)};
        s["colour mask " + std::to_string(i)] = {double(mask[0]), double(mask[1]), double(mask[2]), double(mask[3])};
    }
    for (GLuint i = 0; i < 8; ++i) {
        s["uniform buffer " + std::to_string(i)] = {indexed(GL_UNIFORM_BUFFER_BINDING, i), indexed(GL_UNIFORM_BUFFER_START, i), indexed(GL_UNIFORM_BUFFER_SIZE, i)};
        s["storage buffer " + std::to_string(i)] = {indexed(GL_SHADER_STORAGE_BUFFER_BINDING, i), indexed(GL_SHADER_STORAGE_BUFFER_START, i),
                                                    indexed(GL_SHADER_STORAGE_BUFFER_SIZE, i)};
    }
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (GLuint unit = 0; unit < 24; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        s["unit " + std::to_string(unit)] = {ints(GL_TEXTURE_BINDING_2D)[0], ints(GL_TEXTURE_BINDING_2D_ARRAY)[0], ints(GL_TEXTURE_BINDING_CUBE_MAP)[0],
                                             ints(GL_TEXTURE_BINDING_CUBE_MAP_ARRAY)[0], ints(GL_SAMPLER_BINDING)[0]};
    }
    glActiveTexture(static_cast<GLenum>(active));
    return s;
}

// The caller's objects, bound everywhere, and every listed state set to a
// value no shadowlab pass leaves.
struct CallerObjects {
    GLuint framebuffer = 0, colour = 0, vao = 0, program = 0;
    std::vector<GLuint> buffers, textures, samplers;

    CallerObjects() {
        glCreateTextures(GL_TEXTURE_2D, 1, &colour);
        glTextureStorage2D(colour, 1, GL_RGBA8, 64, 64);
        glCreateFramebuffers(1, &framebuffer);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, colour, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glCreateVertexArrays(1, &vao);
        glBindVertexArray(vao);
        program = glCreateProgram();
        const char* vs = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
        const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
        glShaderSource(shader, 1, &vs, nullptr);
        glCompileShader(shader);
        glAttachShader(program, shader);
        glLinkProgram(program);
        glDeleteShader(shader);
        glUseProgram(program);
        buffers.resize(20);
        glCreateBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
        for (GLuint b : buffers) glNamedBufferData(b, 4096, nullptr, GL_STATIC_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers[1]);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers[2]);
        for (GLuint i = 0; i < 8; ++i) {
            glBindBufferRange(GL_UNIFORM_BUFFER, i, buffers[3 + i], 256, 512);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, buffers[11 + i]);
        }
        glBindBuffer(GL_UNIFORM_BUFFER, buffers[19]);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[19]);
        textures.resize(48);
        samplers.resize(24);
        glCreateSamplers(static_cast<GLsizei>(samplers.size()), samplers.data());
        for (GLuint unit = 0; unit < 24; ++unit) {
            glCreateTextures(GL_TEXTURE_2D, 1, &textures[2 * unit]);
            glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &textures[2 * unit + 1]);
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(GL_TEXTURE_2D, textures[2 * unit]);
            glBindTexture(GL_TEXTURE_CUBE_MAP, textures[2 * unit + 1]);
            glBindSampler(unit, samplers[unit]);
        }
        glActiveTexture(GL_TEXTURE5);
        glViewport(3, 4, 50, 60);
        glScissor(1, 2, 30, 40);
        glEnable(GL_SCISSOR_TEST);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GEQUAL);
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilFuncSeparate(GL_FRONT, GL_NOTEQUAL, 3, 0x0F);
        glStencilFuncSeparate(GL_BACK, GL_LESS, 1, 0xF0);
        glStencilOpSeparate(GL_FRONT, GL_INCR, GL_DECR, GL_INVERT);
        glStencilOpSeparate(GL_BACK, GL_ZERO, GL_REPLACE, GL_INCR_WRAP);
        glStencilMaskSeparate(GL_FRONT, 0x3C);
        glStencilMaskSeparate(GL_BACK, 0xC3);
        glEnablei(GL_BLEND, 0);
        glEnablei(GL_BLEND, 2);
        glBlendFunci(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glBlendFunci(2, GL_DST_COLOR, GL_ZERO);
        glBlendEquationi(2, GL_MAX);
        glColorMaski(1, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glFrontFace(GL_CW);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(2.5f, 7.0f);
        glEnable(GL_CLIP_DISTANCE1);
        glEnable(GL_CLIP_DISTANCE5);
        glEnable(GL_DEPTH_CLAMP);
        glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        glEnable(GL_FRAMEBUFFER_SRGB);
        glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
        glPixelStorei(GL_PACK_ROW_LENGTH, 7);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    }
    ~CallerObjects() {
        // GL's defaults back for the other tests on this context.
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glBindVertexArray(0);
        glUseProgram(0);
        for (GLuint unit = 0; unit < 24; ++unit) glBindSampler(unit, 0);
        glActiveTexture(GL_TEXTURE0);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_STENCIL_TEST);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisablei(GL_BLEND, 0);
        glDisablei(GL_BLEND, 2);
        glBlendFunci(0, GL_ONE, GL_ZERO);
        glBlendFunci(2, GL_ONE, GL_ZERO);
        glBlendEquationi(2, GL_FUNC_ADD);
        glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(0.0f, 0.0f);
        glDisable(GL_CLIP_DISTANCE1);
        glDisable(GL_CLIP_DISTANCE5);
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glDeleteProgram(program);
        glDeleteVertexArrays(1, &vao);
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteTextures(1, &colour);
        glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
        glDeleteSamplers(static_cast<GLsizei>(samplers.size()), samplers.data());
        glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    }
};

fs::path sceneFile(const std::string& name) { return fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / name; }

std::string differences(const State& before, const State& after) {
    std::string out;
    for (const auto& [name, values] : before)
        if (after.at(name) != values) out += (out.empty() ? "" : ", ") + name;
    return out;
}

} // namespace

class AdoptedContextGLTest : public GLTest {};

TEST_F(AdoptedContextGLTest, EveryCallPutsTheCallersStateBack) {
    Context adopted = Context::adoptCurrent(ContextOptions{false, false});  // the test context's own debug output stays
    EXPECT_EQ(adopted.info().platform, "adopted");
    CallerObjects caller;
    const State before = readState();
    // Every technique, and the map's kinds: a 2D map, a cube, cascades, the
    // atlas, SDSM's compute passes, moments, PCSS.
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
        {"two-boxes-sun.json", {}},
        {"two-boxes-sun.json", {"lights[0].shadow.map.cascades=3", "lights[0].shadow.map.fit=\"sdsm\""}},
        {"two-boxes-sun.json", {"lights[0].shadow.map.representation=\"evsm4\"", "lights[0].shadow.map.blur=2"}},
        {"two-boxes-sun.json", {"lights[0].shadow.technique=volume"}},
        {"two-boxes-sun.json", {"lights[0].shadow.technique=planar"}},
        {"discs.json", {"lights[0].shadow.technique=disc"}},
        {"spot-objects.json", {"lights[0].shadow.map.atlas=true"}},
        {"four-spheres-point.json", {"lights[0].shadow.map.filter=\"pcss\"", "lights[0].size=0.2"}},
        {"many-lights.json", {}},
    };
    for (const auto& [file, sets] : cases) {
        SCOPED_TRACE(file + (sets.empty() ? "" : " " + sets.front()));
        const Scene scene = loadSceneFile(sceneFile(file), sets);
        Renderer renderer(adopted);
        EXPECT_EQ(differences(before, readState()), "") << "after the Renderer was made";
        renderer.upload(scene);
        EXPECT_EQ(differences(before, readState()), "") << "after upload";
        RenderOptions options;
        options.width = 96;
        options.height = 64;
        renderer.render(scene, options);
        EXPECT_EQ(differences(before, readState()), "") << "after render";
        renderer.readColor();
        EXPECT_EQ(differences(before, readState()), "") << "after readColor";
        renderer.readVisibility(scene, 0);
        EXPECT_EQ(differences(before, readState()), "") << "after readVisibility";
        renderer.debugImages(scene);
        EXPECT_EQ(differences(before, readState()), "") << "after debugImages";
    }
    EXPECT_EQ(differences(before, readState()), "") << "after the Renderers were destroyed";
}

TEST_F(AdoptedContextGLTest, AdoptingWithoutACurrentContextIsAnError) {
    test::glContext().releaseCurrent();
    try {
        Context::adoptCurrent();
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no OpenGL context is current"), std::string::npos) << e.what();
    }
    test::glContext().makeCurrent();
}
