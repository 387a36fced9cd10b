// The plug-in point, exercised by techniques that exist only in this test:
// through TechniqueHost alone they draw casters with their own programs and
// transforms, share one texture array between two lights, use the stencil
// after the base pass, time their own passes, and leave the base pass's
// output as it was. Checked against the ray-traced reference.
#include "GLTestContext.h"
#include "ImageArtifacts.h"

#include "gl/ShaderSource.h"
#include "techniques/Registry.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include "shadowlab_shared.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <map>

using namespace shadowlab;
using shadowlab::test::GLTest;

namespace {

// --- "test-stencil-map": a hard shadow map per light in one shared array ---

struct StencilMapOptions {
    static constexpr const char* kTechnique = "test-stencil-map";
    int size = 1024;               ///< texels per side of each layer
    float bias = 0.004f;           ///< depth (0..1 of the light's range)
    bool stencilCasters = true;    ///< casters do not receive the light (drawn through the stencil)
};

const OptionTable& stencilMapTable() {
    static const OptionTable t = OptionTableFor<StencilMapOptions>("test-stencil-map")
                                     .integer(&StencilMapOptions::size, "size", 16, 4096, "texels", "side of each layer")
                                     .number(&StencilMapOptions::bias, "bias", 0.0, 0.1, "depth", "constant depth bias")
                                     .boolean(&StencilMapOptions::stencilCasters, "stencilCasters", "casters do not receive the light")
                                     .build();
    return t;
}

constexpr int kMaxLayers = 4;

// The technique's own block (SL_BINDING_TECHNIQUE): one matrix per layer.
struct TestBlock {
    glm::mat4 lightClipFromWorld[kMaxLayers];
    glm::vec4 params;  // x bias
};

const char* kDepthVert = R"(#include "shadowlab_shared.h"
layout(location = 0) in vec3 inPosition;
layout(std140, binding = SL_BINDING_TECHNIQUE) uniform TestBlock { mat4 lightClipFromWorld[4]; vec4 params; } test;
layout(location = 0) uniform int layer;
void main() { gl_Position = test.lightClipFromWorld[layer] * draw.worldFromObject * vec4(inPosition, 1.0); }
)";
const char* kEmptyFrag = "void main() {}\n";
const char* kHook = R"(// test-stencil-map's hook: this light's layer (params.y) of the shared array.
layout(std140, binding = SL_BINDING_TECHNIQUE) uniform TestBlock { mat4 lightClipFromWorld[4]; vec4 params; } test;
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2DArrayShadow testMaps;
vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    int layer = int(test.params.y);
    vec4 clip = test.lightClipFromWorld[layer] * vec4(worldPosition, 1.0);
    vec3 p = clip.xyz / clip.w * 0.5 + 0.5;  // the bias matrix
    return vec3(texture(testMaps, vec4(p.xy, float(layer), p.z - test.params.x)));
}
)";

struct Counters {
    int arraysCreated = 0;
    int shadowPasses = 0;
};
Counters counters;

class StencilMap final : public Technique {
public:
    void prepare(TechniqueHost&, const FrameInfo& frame, std::span<const int> lights) override {
        const int size = frame.scene.lights[static_cast<std::size_t>(lights[0])].shadow.get<StencilMapOptions>().size;
        if (static_cast<int>(lights.size()) > kMaxLayers) throw Error("test-stencil-map: at most 4 lights");
        layerOf_.clear();
        for (std::size_t i = 0; i < lights.size(); ++i) layerOf_[lights[i]] = static_cast<int>(i);
        if (!array_ || size != size_ || static_cast<int>(lights.size()) != layers_) {
            size_ = size;
            layers_ = static_cast<int>(lights.size());
            array_ = gl::Texture(GL_TEXTURE_2D_ARRAY);  // one texture for every light using this technique
            glTextureStorage3D(array_.id(), 1, GL_DEPTH_COMPONENT32F, size_, size_, layers_);
            glTextureParameteri(array_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
            glTextureParameteri(array_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
            glTextureParameteri(array_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(array_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTextureParameteri(array_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(array_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            ++counters.arraysCreated;
        }
        if (!ubo_) {
            ubo_ = gl::Buffer();
            glNamedBufferStorage(ubo_.id(), sizeof(TestBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
        }
    }
    bool hasShadowPass(const Light&) const override { return true; }
    void renderShadowPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view) override {
        ++counters.shadowPasses;
        const int layer = layerOf_.at(view.index);
        // An orthographic light camera around every item (the lecture's box).
        Bounds all;
        for (const Bounds& b : frame.itemBounds) all.add(b);
        const float radius = 0.5f * glm::length(all.size());
        const glm::vec3 dir = glm::normalize(view.light.direction);
        const glm::vec3 up = std::abs(dir.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        block_.lightClipFromWorld[layer] = glm::ortho(-radius, radius, -radius, radius, 0.0f, 2.0f * radius) *
                                           glm::lookAt(all.centre() - dir * radius, all.centre(), up);
        block_.params.x = view.light.shadow.get<StencilMapOptions>().bias;
        glNamedBufferSubData(ubo_.id(), 0, sizeof block_, &block_);
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_TECHNIQUE, ubo_.id());

        if (!fbo_) fbo_ = gl::Framebuffer();
        glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, array_.id(), 0, layer);
        glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
        gl::checkFramebuffer(fbo_, "test-stencil-map");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
        glViewport(0, 0, size_, size_);
        gl::RenderState state;
        state.noColor();
        host.apply(state);
        const float one = 1.0f;
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
        const gl::Program& depth = host.program({{{GL_VERTEX_SHADER, "test-depth.vert", kDepthVert},
                                                  {GL_FRAGMENT_SHADER, "test-depth.frag", kEmptyFrag}}, ""});
        glProgramUniform1i(depth.id(), 0, layer);
        {
            const auto scope = host.timeScope("casters");
            host.drawItems(ItemFilter::Casters, depth);
        }
        // A careless technique: leave garbage bound at the renderer's own
        // block bindings. The renderer must rebind its blocks for its passes.
        if (!junk_) {
            junk_ = gl::Buffer();
            std::vector<float> garbage(256, 1e6f);
            glNamedBufferStorage(junk_.id(), static_cast<GLsizeiptr>(garbage.size() * sizeof(float)), garbage.data(), 0);
        }
        for (GLuint binding : {SL_BINDING_FRAME, SL_BINDING_LIGHT, SL_BINDING_DRAW}) glBindBufferBase(GL_UNIFORM_BUFFER, binding, junk_.id());
    }
    bool sharesBasePass(const Light& light) const override { return !light.shadow.get<StencilMapOptions>().stencilCasters; }
    void bindLightPass(TechniqueHost&, const FrameInfo&, const LightView& view) override {
        block_.params = glm::vec4(view.light.shadow.get<StencilMapOptions>().bias, static_cast<float>(layerOf_.at(view.index)), 0, 0);
        glNamedBufferSubData(ubo_.id(), 0, sizeof block_, &block_);
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_TECHNIQUE, ubo_.id());
        glBindTextureUnit(SL_UNIT_SHADOW_FIRST, array_.id());
    }
    void renderLightPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view) override {
        bindLightPass(host, frame, view);
        if (!view.light.shadow.get<StencilMapOptions>().stencilCasters) {
            host.drawLit(host.litState());
            return;
        }
        // Mark the pixels where a caster is the visible surface, then light
        // everything else through the stencil.
        gl::RenderState mark;
        mark.depthFunc = GL_EQUAL;
        mark.depthWrite = false;
        mark.noColor();
        mark.stencil({GL_ALWAYS, 1, 0xFF, 0xFF, GL_KEEP, GL_KEEP, GL_REPLACE});
        host.apply(mark);  // the base pass cleared the stencil to 0
        const gl::Program& depth = host.program({{{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "test-depth.frag", kEmptyFrag}}, ""});
        host.drawItems(ItemFilter::Casters, depth);
        gl::RenderState lit = host.litState();
        lit.stencil({GL_NOTEQUAL, 1, 0xFF, 0x00});
        host.drawLit(lit);
        // Leave the stencil as the next light expects it: cleared.
        gl::RenderState clear;
        clear.depthWrite = false;
        clear.noColor();
        clear.stencil({GL_ALWAYS, 0, 0xFF, 0xFF, GL_ZERO, GL_ZERO, GL_ZERO});
        clear.depthTest = false;
        host.apply(clear);
        host.drawItems(ItemFilter::Casters, depth);
    }
    void debugImages(TechniqueHost&, const FrameInfo&, const LightView& view, const DebugImageKinds&, std::vector<DebugImage>& out) override {
        const int layer = layerOf_.at(view.index);
        std::vector<float> depth(static_cast<std::size_t>(size_) * size_);
        glGetTextureSubImage(array_.id(), 0, 0, 0, layer, size_, size_, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                             static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
        ImageRGBA8 image{size_, size_, std::vector<std::uint8_t>(depth.size() * 4, 255)};
        for (std::size_t i = 0; i < depth.size(); ++i)
            image.pixels[4 * i] = image.pixels[4 * i + 1] = image.pixels[4 * i + 2] = static_cast<std::uint8_t>(depth[i] * 255.0f);
        out.push_back({"depth", std::move(image), {}});
    }

private:
    gl::Texture array_{gl::NoCreate};
    gl::Buffer ubo_{gl::NoCreate}, junk_{gl::NoCreate};
    gl::Framebuffer fbo_{gl::NoCreate};
    std::map<int, int> layerOf_;
    TestBlock block_{};
    int size_ = 0, layers_ = 0;
};

// --- "test-heavy": a deliberately expensive shadow pass ---------------------

struct HeavyOptions {
    static constexpr const char* kTechnique = "test-heavy";
    int draws = 40;  ///< full-screen triangles drawn in the shadow pass
};

const char* kHeavyFrag = R"(layout(location = 0) out vec4 color;
void main() {
    float x = gl_FragCoord.x * 0.001;
    for (int i = 0; i < 200; ++i) x = sin(x * 1.0001 + 0.3);
    color = vec4(x);
}
)";

class Heavy final : public Technique {
public:
    bool hasShadowPass(const Light&) const override { return true; }
    void renderShadowPass(TechniqueHost& host, const FrameInfo&, const LightView& view) override {
        if (!target_) {
            target_ = gl::Texture(GL_TEXTURE_2D);
            glTextureStorage2D(target_.id(), 1, GL_RGBA8, 512, 512);
            fbo_ = gl::Framebuffer();
            glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target_.id(), 0);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
        glViewport(0, 0, 512, 512);
        gl::RenderState state;
        state.depthTest = false;
        host.apply(state);
        host.program({{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "test-heavy.frag", kHeavyFrag}}, ""}).use();
        for (int i = 0; i < view.light.shadow.get<HeavyOptions>().draws; ++i) host.drawFullscreenTriangle();
    }

private:
    gl::Texture target_{gl::NoCreate};
    gl::Framebuffer fbo_{gl::NoCreate};
};

const OptionTable& heavyTable() {
    static const OptionTable t = OptionTableFor<HeavyOptions>("test-heavy")
                                     .integer(&HeavyOptions::draws, "draws", 1, 1000, "", "full-screen triangles in the shadow pass")
                                     .build();
    return t;
}

// --- "test-adjacency": draws with adjacency, a tinted hook, frame facts ------

struct AdjacencyOptions {
    static constexpr const char* kTechnique = "test-adjacency";
};

const char* kPlainVert = R"(#include "shadowlab_shared.h"
layout(location = 0) in vec3 inPosition;
void main() { gl_Position = frame.clipFromWorld * draw.worldFromObject * vec4(inPosition, 1.0); }
)";
// Passes each triangle of a GL_TRIANGLES_ADJACENCY primitive through
// (vertices 0, 2, 4), and checks that each neighbour (1, 3, 5) is a real
// triangle's vertex: the adjacency builder marks an open edge with the
// triangle's own opposite vertex, and such a triangle is drawn with 0.5.
const char* kPassGeom = R"(layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 3) out;
out float vOk;
void main() {
    float ok = 1.0;
    for (int e = 0; e < 3; ++e) {
        vec4 own = gl_in[(2 * e + 4) % 6].gl_Position, across = gl_in[2 * e + 1].gl_Position;
        if (own == across) ok = 0.5;
    }
    for (int i = 0; i < 6; i += 2) { gl_Position = gl_in[i].gl_Position; vOk = ok; EmitVertex(); }
    EndPrimitive();
}
)";
const char* kOkFrag = "in float vOk;\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(vOk); }\n";
const char* kOneFrag = "layout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n";
const char* kTintHook = "vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) { return vec3(1.0, 0.5, 0.25); }\n";

struct FrameFacts {
    std::uint64_t frameIndex = 0;
    double timeSeconds = -1.0;
};
FrameFacts facts;

class AdjacencyProbe final : public Technique {
public:
    bool hasShadowPass(const Light&) const override { return true; }
    void renderShadowPass(TechniqueHost& host, const FrameInfo& frame, const LightView&) override {
        facts = {frame.frameIndex, frame.timeSeconds};
        for (int i = 0; i < 2; ++i) {
            if (!targets_[i]) {
                targets_[i] = gl::Texture(GL_TEXTURE_2D);
                glTextureStorage2D(targets_[i].id(), 1, GL_RGBA8, kSize, kSize);
                fbos_[i] = gl::Framebuffer();
                glNamedFramebufferTexture(fbos_[i].id(), GL_COLOR_ATTACHMENT0, targets_[i].id(), 0);
            }
            glBindFramebuffer(GL_FRAMEBUFFER, fbos_[i].id());
            glViewport(0, 0, kSize, kSize);
            gl::RenderState state;
            state.depthTest = false;
            host.apply(state);
            const float zero[4] = {0, 0, 0, 0};
            glClearNamedFramebufferfv(fbos_[i].id(), GL_COLOR, 0, zero);
            if (i == 0) {
                host.drawItems(ItemFilter::Casters, host.program({{{GL_VERTEX_SHADER, "test-plain.vert", kPlainVert},
                                                                   {GL_FRAGMENT_SHADER, "test-one.frag", kOneFrag}}, ""}));
            } else {
                host.drawItems(ItemFilter::Casters,
                               host.program({{{GL_VERTEX_SHADER, "test-plain.vert", kPlainVert}, {GL_GEOMETRY_SHADER, "test-pass.geom", kPassGeom},
                                              {GL_FRAGMENT_SHADER, "test-ok.frag", kOkFrag}}, ""}),
                               {}, Topology::TrianglesAdjacency);
            }
        }
    }
    void debugImages(TechniqueHost&, const FrameInfo&, const LightView&, const DebugImageKinds&, std::vector<DebugImage>& out) override {
        for (int i = 0; i < 2; ++i) {
            ImageRGBA8 image{kSize, kSize, std::vector<std::uint8_t>(static_cast<std::size_t>(kSize) * kSize * 4)};
            glGetTextureImage(targets_[i].id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.pixels.size()), image.pixels.data());
            out.push_back({i == 0 ? "triangles" : "adjacency", std::move(image), {}});
        }
    }

private:
    static constexpr int kSize = 128;
    gl::Texture targets_[2]{gl::Texture(gl::NoCreate), gl::Texture(gl::NoCreate)};
    gl::Framebuffer fbos_[2]{gl::Framebuffer(gl::NoCreate), gl::Framebuffer(gl::NoCreate)};
};

// Registers the test techniques once per test binary.
void registerTestTechniques() {
    static const bool done = [] {
        gl::addShaderFile("shadow_test_stencil_map.glsl", kHook);
        registerTechnique({"test-stencil-map", "test: a shadow-map array shared by lights, casters stencilled out", &stencilMapTable()},
                          "shadow_test_stencil_map.glsl", [] { return std::make_unique<StencilMap>(); });
        registerTechnique({"test-heavy", "test: a deliberately slow shadow pass", &heavyTable(),
                           [](const Light& l) { return l.type == LightType::Point ? std::string("test-heavy: no point lights") : std::string(); }},
                          "shadow_none.glsl", [] { return std::make_unique<Heavy>(); });
        static const OptionTable adjacencyTable = OptionTableFor<AdjacencyOptions>("test-adjacency").build();
        gl::addShaderFile("shadow_test_tint.glsl", kTintHook);
        registerTechnique({"test-adjacency", "test: adjacency draws, a tinted hook, frame facts", &adjacencyTable},
                          "shadow_test_tint.glsl", [] { return std::make_unique<AdjacencyProbe>(); });
        return true;
    }();
    (void)done;
}

// Two suns from different sides over a ground that casts nothing; a box and
// a sphere cast and do not receive (they are stencilled out of the light).
Scene twoSuns(const std::string& technique, float intensity = 0.45f) {
    return parseScene(R"({
      "camera": {"position": [0, 9, 9], "target": [0, 0, 0], "fovY": 50},
      "ambient": [0.2, 0.2, 0.2],
      "lights": [
        {"name": "west sun", "type": "directional", "direction": [0.6, -1, 0.1], "intensity": )" + std::to_string(intensity) + R"(,
         "shadow": {"technique": ")" + technique + R"(", "test-stencil-map": {"size": 1024}}},
        {"name": "east sun", "type": "directional", "direction": [-0.5, -1, -0.3], "intensity": )" + std::to_string(intensity) + R"(,
         "shadow": {"technique": ")" + technique + R"("}}
      ],
      "nodes": [
        {"name": "ground", "shape": {"type": "plane", "size": [30, 30]}, "castsShadows": false},
        {"name": "box", "shape": {"type": "box", "size": [1, 2, 1]}, "translation": [-1, 1.5, 0], "receivesShadows": false},
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.8}, "translation": [1.5, 1.2, 0.5], "receivesShadows": false}
      ]
    })", "two-suns", ".");
}

int channelDiff(const ImageRGBA8& a, const ImageRGBA8& b, std::size_t pixel) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.pixels[pixel * 4 + c]) - int(b.pixels[pixel * 4 + c])));
    return worst;
}

}  // namespace

class TechniqueGLTest : public GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        registerTestTechniques();
    }
};

TEST_F(TechniqueGLTest, RegisteredTechniquesAreListedAndTheirOptionsParse) {
    const TechniqueInfo* info = findTechnique("test-stencil-map");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->options->fields.size(), 3u);
    const Scene scene = twoSuns("test-stencil-map");
    EXPECT_EQ(scene.lights[0].shadow.get<StencilMapOptions>().size, 1024);  // from the block
    EXPECT_EQ(scene.lights[1].shadow.get<StencilMapOptions>().size, 1024);  // no block: the default
    const Scene changed = parseScene(R"({"lights": [{"type": "directional", "shadow": {"technique": "none",
                                       "test-stencil-map": {"size": 64, "bias": 0.01, "stencilCasters": false}}}]})", "s", ".",
                                     {"lights[0].shadow.test-stencil-map.size=128"});
    const StencilMapOptions& o = changed.lights[0].shadow.get<StencilMapOptions>();
    EXPECT_EQ(o.size, 128);           // --set wins over the file's 64
    EXPECT_FLOAT_EQ(o.bias, 0.01f);
    EXPECT_FALSE(o.stencilCasters);
    EXPECT_EQ(changed.lights[0].shadow.technique, "none");  // a block for another technique is kept, not used
}

TEST_F(TechniqueGLTest, TwoLightsShareOneArrayAndMatchTheReference) {
    const Scene scene = twoSuns("test-stencil-map");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    const Counters before = counters;
    CompareOptions options;
    options.width = 320;
    options.height = 240;
    const Comparison c = compareWithReference(renderer, scene, options);
    EXPECT_EQ(counters.arraysCreated - before.arraysCreated, 1) << "one texture array for both lights";
    EXPECT_EQ(counters.shadowPasses - before.shadowPasses, 2) << "one shadow pass per light (the reference frame has none)";
    for (const LightComparison& l : c.lights) {
        SCOPED_TRACE(l.name);
        // Each shadow covers about 1 % of this 320x240 view (951 and more
        // pixels measured); half of that still proves there is one to get wrong.
        EXPECT_GT(l.referenceShadowedPixels, 500u) << "each light throws a real shadow on the ground";
        // A 1024^2 map over a 31 m box is 3 cm a texel, under a pixel here:
        // away from the 1-pixel edge band nothing may be wrong but a few
        // texel-staircase pixels; 0.2 % of receivers allows ~150 of them.
        EXPECT_LT(l.falseLitAwayFromEdges, 0.002);
        EXPECT_LT(l.falseShadowAwayFromEdges, 0.002);
    }
    const auto& named = c.techniqueFrame.passes;
    const bool nested = std::any_of(named.begin(), named.end(), [](const PassTiming& p) { return p.name == "shadow[1].casters"; });
    EXPECT_TRUE(nested) << "a technique's own scope is timed inside its pass";
}

TEST_F(TechniqueGLTest, BasePassOutputIsUnchangedAndTheStencilKeepsCastersOutOfTheLight) {
    // The technique leaves garbage bound at the renderer's block bindings
    // after its shadow pass; the base pass must not see it.
    const Scene scene = twoSuns("test-stencil-map");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    CompareOptions options;
    options.width = 320;
    options.height = 240;
    const Comparison c = compareWithReference(renderer, scene, options);
    RenderOptions render{320, 240};
    const Scene ambientOnly = twoSuns("none", 0.0f);
    renderer.render(ambientOnly, render);
    const ImageRGBA8 ambient = renderer.readColor();
    const Scene unshadowed = twoSuns("none");
    renderer.render(unshadowed, render);
    const ImageRGBA8 lit = renderer.readColor();

    // 8-bit sRGB output: the same linear sum rounds to the same byte, but the
    // order of additions can differ (base pass vs. separate light pass), so
    // allow one step.
    constexpr int kTolerance = 1;
    std::size_t casters = 0, litGround = 0, darkGround = 0;
    for (std::size_t i = 0; i < c.surfaces.position.size(); ++i) {
        if (c.surfaces.position[i].w < 0.5f) continue;
        const bool receiver = c.surfaces.normal[i].w > 0.5f;
        if (!receiver) {  // box or ball: stencilled out of both lights, ambient only
            ++casters;
            EXPECT_LE(channelDiff(c.technique, ambient, i), kTolerance) << "caster pixel " << i;
            continue;
        }
        const auto vis0 = c.lights[0].referenceVisibility.pixels[i], vis1 = c.lights[1].referenceVisibility.pixels[i];
        const auto x = static_cast<int>(i % 320), y = static_cast<int>(i / 320);
        bool nearEdge = false;  // skip pixels next to a true shadow edge of either light
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                const int nx = std::clamp(x + dx, 0, 319), ny = std::clamp(y + dy, 0, 239);
                const std::size_t j = static_cast<std::size_t>(ny) * 320 + nx;
                nearEdge = nearEdge || c.lights[0].referenceVisibility.pixels[j] != vis0 || c.lights[1].referenceVisibility.pixels[j] != vis1;
            }
        if (nearEdge) continue;
        if (vis0 == 65535 && vis1 == 65535) {
            ++litGround;
            EXPECT_LE(channelDiff(c.technique, lit, i), kTolerance) << "lit ground pixel " << i;
        } else if (vis0 == 0 && vis1 == 0) {
            ++darkGround;
            EXPECT_LE(channelDiff(c.technique, ambient, i), kTolerance) << "doubly shadowed ground pixel " << i;
        }
    }
    EXPECT_GT(casters, 2000u);
    EXPECT_GT(litGround, 20000u);
    EXPECT_GT(darkGround, 50u) << "the two shadows overlap somewhere";
    test::saveImagesIfFailed("technique-vs-unshadowed", c.technique, lit);
    test::saveImagesIfFailed("technique-vs-ambient", c.technique, ambient);
}

TEST_F(TechniqueGLTest, DebugImagesComeThroughTheHook) {
    const Scene scene = twoSuns("test-stencil-map");
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {64, 48});
    const std::vector<DebugImage> images = renderer.debugImages(scene);
    ASSERT_EQ(images.size(), 2u);
    EXPECT_EQ(images[0].name, "light0-depth");
    EXPECT_EQ(images[1].name, "light1-depth");
    for (const DebugImage& d : images) {
        EXPECT_EQ(d.image.width, 1024);
        std::size_t nearer = 0;  // texels where a caster is nearer than the far plane
        for (std::size_t i = 0; i < d.image.pixels.size(); i += 4) nearer += d.image.pixels[i] < 255;
        EXPECT_GT(nearer, 1000u) << d.name;
    }
}

TEST_F(TechniqueGLTest, AHeavyPassIsChargedToItselfOnThisRenderer) {
    // On llvmpipe a GL_TIME_ELAPSED query would charge the queued work of
    // one pass to the next; the Auto clock must put it where it belongs.
    Scene scene = twoSuns("test-heavy");
    scene.lights.pop_back();
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options{320, 240, TimingClock::Auto};
    renderer.render(scene, options);  // compiles the programs
    const FrameStats stats = renderer.render(scene, options);
    std::map<std::string, double> ms;
    for (const PassTiming& p : stats.passes) ms[p.name] = p.ms;
    ASSERT_EQ(ms.size(), 2u);
    ASSERT_TRUE(ms.count("shadow[0]") && ms.count("base"));
    if (stats.clock != "cpu-finish") GTEST_SKIP() << "a GPU renderer (" << stats.clock << "): this check is for deferred rasterisers";
    // 40 full-screen triangles of 512^2 with a 200-step loop each: hundreds
    // of milliseconds on 2 cores, against ~1 ms for the base pass. A factor
    // of 5 leaves room for a noisy shared machine.
    EXPECT_GT(ms["shadow[0]"], 5.0 * ms["base"]) << "shadow " << ms["shadow[0]"] << " ms, base " << ms["base"] << " ms";
    EXPECT_GT(ms["shadow[0]"], 20.0);
}

TEST_F(TechniqueGLTest, AnUnsupportedLightIsAnErrorNamingTheJsonPath) {
    try {
        parseScene(R"({"lights": [{"type": "point", "position": [0, 1, 0], "shadow": {"technique": "test-heavy"}}]})", "p.json", ".");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "p.json: lights[0].shadow.technique: test-heavy: no point lights");
    }
}

TEST_F(TechniqueGLTest, AdjacencyDrawsCoverTheSameTrianglesWithRealNeighbours) {
    // Closed casters (box, sphere): every edge has a neighbour off its line.
    Scene scene = twoSuns("test-adjacency");
    scene.lights.pop_back();
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    renderer.render(scene, {64, 48});
    const std::vector<DebugImage> images = renderer.debugImages(scene);
    ASSERT_EQ(images.size(), 2u);
    const ImageRGBA8& plain = images[0].image;
    const ImageRGBA8& adjacency = images[1].image;
    std::size_t covered = 0, mismatched = 0, degenerate = 0;
    for (std::size_t i = 0; i < plain.pixels.size(); i += 4) {
        covered += plain.pixels[i] == 255;
        mismatched += (plain.pixels[i] > 0) != (adjacency.pixels[i] > 0);
        degenerate += adjacency.pixels[i] > 0 && adjacency.pixels[i] < 255;
    }
    // The box and the ball cover about 3 % of the 128x128 view (470 pixels measured).
    EXPECT_GT(covered, 200u);
    EXPECT_EQ(mismatched, 0u) << "the adjacency draw covers exactly the triangles";
    EXPECT_EQ(degenerate, 0u) << "closed meshes have a real neighbour across every edge";
    test::saveImagesIfFailed("adjacency-vs-triangles", adjacency, plain);
}

TEST_F(TechniqueGLTest, ColouredVisibilityAndFrameFactsReachTheTechnique) {
    Scene scene = twoSuns("test-adjacency");
    scene.lights.pop_back();
    Renderer renderer(test::glContext());
    renderer.upload(scene);
    RenderOptions options{64, 48};
    options.timeSeconds = 2.5;
    renderer.render(scene, options);
    renderer.render(scene, options);
    EXPECT_EQ(facts.frameIndex, 1u) << "the second frame of this renderer";
    EXPECT_EQ(facts.timeSeconds, 2.5);
    const std::vector<glm::vec3> rgb = renderer.readVisibilityRgb(scene, 0);
    const std::vector<float> mean = renderer.readVisibility(scene, 0);
    std::size_t tinted = 0;
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        if (rgb[i] == glm::vec3(0.0f)) continue;  // background
        if (rgb[i] == glm::vec3(1.0f)) continue;  // casters: receivesShadows false, lit whatever the hook says
        ++tinted;
        EXPECT_EQ(rgb[i], glm::vec3(1.0f, 0.5f, 0.25f)) << i;
        EXPECT_FLOAT_EQ(mean[i], (1.0f + 0.5f + 0.25f) / 3.0f) << i;
    }
    EXPECT_GT(tinted, 1000u) << "the ground receives the tinted visibility";
}
