// Nothing a pass leaves set reaches the next pass: every pass applies a
// whole gl::RenderState. A test technique leaves GL state dirty at the end
// of its shadow pass, one piece at a time (raw GL calls, as a careless
// technique would), and the frame after it, a cube-map light's pass, the
// base pass and a separate light pass, must be the clean frame, pixel for
// pixel. That each piece of dirt would change pixels if it were in effect
// is shown first by one draw with and without it, so the leak test cannot
// pass for want of dirt that matters. (Checked by mutation: gl::apply
// without its polygon-offset or sRGB line fails the leak test. Depth clamp
// left on changes no pixel of this frame: only the single draw shows it;
// seamless cube filtering left off shows in neither, so for it this test
// only proves that apply() resets it, not that it would matter here.)
#include "GLTestContext.h"
#include "ImageArtifacts.h"

#include "gl/PassClock.h"
#include "gl/Program.h"
#include "gl/RenderState.h"
#include "techniques/Registry.h"

#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <functional>
#include <string>
#include <vector>

using namespace shadowlab;
using shadowlab::test::GLTest;

namespace {

// One piece of dirt: a GL state no pass of the frame wants.
struct Dirt {
    const char* name;
    std::function<void()> leave;
};

// Every part of RenderState, set the wrong way.
const std::vector<Dirt>& dirt() {
    static const std::vector<Dirt> all = {
        {"colour mask", [] { glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE); }},
        {"blending", [] { glEnable(GL_BLEND); glBlendFunc(GL_ZERO, GL_ONE); }},
        {"blending of one target", [] { glEnablei(GL_BLEND, 0); glBlendFunci(0, GL_ZERO, GL_ONE); glBlendEquationi(0, GL_MIN); }},
        {"culling", [] { glEnable(GL_CULL_FACE); glCullFace(GL_FRONT_AND_BACK); }},
        {"depth function", [] { glEnable(GL_DEPTH_TEST); glDepthFunc(GL_NEVER); }},
        {"depth writes", [] { glDepthMask(GL_FALSE); }},
        {"stencil", [] { glEnable(GL_STENCIL_TEST); glStencilFunc(GL_NEVER, 0, 0xFF); glStencilMask(0x00); }},
        {"polygon offset", [] { glEnable(GL_POLYGON_OFFSET_FILL); glPolygonOffset(0.0f, -1.0e6f); }},
        {"depth clamp", [] { glEnable(GL_DEPTH_CLAMP); }},
        {"0..1 clip depth", [] { glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); }},
        {"sRGB writes", [] { glEnable(GL_FRAMEBUFFER_SRGB); }},
        {"clip distance", [] { glEnable(GL_CLIP_DISTANCE0); }},
        {"seamless cube maps off", [] { glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS); }},
        {"scissor", [] { glEnable(GL_SCISSOR_TEST); glScissor(0, 0, 1, 1); }},
    };
    return all;
}

// --- the careless technique: an empty shadow pass that leaves dirt ---

struct LeakyOptions {
    static constexpr const char* kTechnique = "test-leaky";
    int dirt = -1;  ///< index into dirt(), -1 none, past the end: all of it
};

const OptionTable& leakyTable() {
    static const OptionTable t = OptionTableFor<LeakyOptions>("test-leaky")
                                     .integer(&LeakyOptions::dirt, "dirt", -1, 100, "index", "which GL state the shadow pass leaves set")
                                     .build();
    return t;
}

class Leaky final : public Technique {
public:
    bool hasShadowPass(const Light&) const override { return true; }
    void renderShadowPass(TechniqueHost&, const FrameInfo&, const LightView& view) override {
        const int which = view.light.shadow.get<LeakyOptions>().dirt;
        const auto& all = dirt();
        for (int i = 0; i < static_cast<int>(all.size()); ++i)
            if (which == i || which >= static_cast<int>(all.size())) all[static_cast<std::size_t>(i)].leave();
    }
};

void registerLeaky() {
    static const bool done = [] {
        registerTechnique({"test-leaky", "test: a shadow pass that leaves GL state set", &leakyTable()},
                          "shadow_none.glsl", [] { return std::make_unique<Leaky>(); });
        return true;
    }();
    (void)done;
}

// A sun with the careless technique (its pass runs first, its light is
// drawn in the base pass), a point light's cube map (a shadow pass after
// it, sampled across face seams) and a spot light of its own light pass.
Scene leakyScene(int which) {
    return parseScene(R"({
      "camera": {"position": [0, 6, 8], "target": [0, 0.5, 0], "fovY": 50},
      "ambient": [0.15, 0.15, 0.15],
      "lights": [
        {"type": "directional", "direction": [0.3, -1, 0.2], "intensity": 0.5, "shadow": {"technique": "test-leaky", "test-leaky": {"dirt": )" +
                      std::to_string(which) + R"(}}},
        {"type": "point", "position": [0, 2.5, 0], "intensity": 0.6, "shadow": {"technique": "map", "map": {"size": 128, "filter": "hardware"}}},
        {"type": "spot", "position": [3, 4, 3], "direction": [-0.6, -1, -0.6], "outerCone": 35, "intensity": 0.6,
         "shadow": {"technique": "map", "map": {"size": 256}}}
      ],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [12, 12]}},
        {"name": "box", "shape": {"type": "box", "size": [1, 1, 1]}, "translation": [-1, 0.5, 0.5]},
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.6}, "translation": [1.2, 0.8, -0.4]},
        {"name": "post on a seam", "shape": {"type": "box", "size": [0.3, 1.5, 0.3]}, "translation": [2.5, 0.75, 0.3]}
      ]
    })", "leaky", ".");
}

ImageRGBA8 renderLeaky(Renderer& renderer, int which) {
    const Scene scene = leakyScene(which);
    renderer.upload(scene);
    renderer.render(scene, RenderOptions{160, 120});
    return renderer.readColor();
}

// One triangle covering a 32x32 sRGB target, with its depth and stencil,
// at NDC depth z, drawn after a clean state and `extra` (dirt or nothing):
// its colour and depth values. With `clip` it writes gl_ClipDistance[0] =
// -1 (clipped only with the clip distance on).
std::vector<float> drawOnce(const std::function<void()>& extra, float z, bool clip) {
    constexpr int kSize = 32;
    gl::Texture colour(GL_TEXTURE_2D), depth(GL_TEXTURE_2D);
    glTextureStorage2D(colour.id(), 1, GL_SRGB8_ALPHA8, kSize, kSize);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH24_STENCIL8, kSize, kSize);
    gl::Framebuffer fbo;
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, colour.id(), 0);
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth.id(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, kSize, kSize);
    gl::apply(gl::RenderState{});
    const float clearColour[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clearColour);
    glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    const gl::Program program({{GL_VERTEX_SHADER, "dirt.vert", R"(
        uniform float z;
        void main() {
            vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
            gl_Position = vec4(p, z, 1.0);
#if CLIP
            gl_ClipDistance[0] = -1.0;
#endif
        })"},
                               {GL_FRAGMENT_SHADER, "dirt.frag", "layout(location = 0) out vec4 c; void main() { c = vec4(0.8, 0.4, 0.2, 1.0); }"}},
                              clip ? "#define CLIP 1\n" : "#define CLIP 0\n");
    program.use();
    glUniform1f(program.uniform("z"), z);
    extra();
    gl::VertexArray vao;
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    std::vector<float> out(static_cast<std::size_t>(kSize * kSize) * 5);
    glGetTextureImage(colour.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(kSize * kSize * 4 * sizeof(float)), out.data());
    glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(kSize * kSize * sizeof(float)),
                      out.data() + static_cast<std::ptrdiff_t>(kSize * kSize * 4));
    gl::apply(gl::RenderState{});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

}  // namespace

class RenderStateGLTest : public GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        registerLeaky();
    }
};

TEST_F(RenderStateGLTest, EveryPieceOfDirtChangesADrawWhileInEffect) {
    const auto nothing = [] {};
    for (const Dirt& d : dirt()) {
        if (std::string(d.name) == "seamless cube maps off") continue;  // no cube map in this draw
        // Mesa's llvmpipe clips by what the vertex stage writes to
        // gl_ClipDistance whether GL_CLIP_DISTANCE0 is on or off (seen here:
        // a triangle writing -1 is never drawn), so only a GPU shows this
        // piece in effect.
        if (std::string(d.name) == "clip distance" && gl::isSoftwareRasterizer(test::glContext().info().renderer)) continue;
        // Depth clamp shows on a triangle before the near plane, 0..1 clip
        // depth on one in GL's near half (clipped then); the rest on one inside.
        const float z = std::string(d.name) == "depth clamp" ? -1.5f : std::string(d.name) == "0..1 clip depth" ? -0.5f : 0.25f;
        const bool clip = std::string(d.name) == "clip distance";
        const std::vector<float> clean = drawOnce(nothing, z, clip);
        const std::vector<float> dirty = drawOnce(d.leave, z, clip);
        EXPECT_NE(clean, dirty) << d.name << " changes nothing: the leak test would not see it leak";
    }
}

TEST_F(RenderStateGLTest, StateLeftSetByAPassDoesNotChangeTheNextPassesPixels) {
    Renderer renderer(test::glContext());
    const ImageRGBA8 clean = renderLeaky(renderer, -1);
    const int count = static_cast<int>(dirt().size());
    for (int i = 0; i <= count; ++i) {
        const ImageRGBA8 frame = renderLeaky(renderer, i);
        // Exact: the same draws with the same state give the same bytes.
        const std::string what = i < count ? dirt()[static_cast<std::size_t>(i)].name : "all of it";
        EXPECT_TRUE(frame.pixels == clean.pixels) << "left set: " << what;
        test::saveImagesIfFailed("state-leak-" + std::to_string(i), frame, clean);
    }
    // The clean frame is not blank: the lights and shadows are there to be
    // changed (neighbouring pixels differ along the ground's shading and
    // every shadow edge: thousands of the 19,200; 1000 rules out a flat frame).
    std::size_t distinct = 0;
    for (std::size_t p = 4; p < clean.pixels.size(); p += 4) distinct += clean.pixels[p] != clean.pixels[p - 4];
    EXPECT_GT(distinct, 1000u);
}
