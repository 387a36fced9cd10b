// The frame: which passes run in which order (see Renderer.h).
#include <shadowlab/Renderer.h>

#include "gl/Object.h"
#include "gl/Program.h"
#include "render/GpuScene.h"
#include "render/ShaderVariant.h"
#include "techniques/ShadowModule.h"

#include <shadowlab/Error.h>

#include "shadowlab_shared.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <optional>

namespace shadowlab {

namespace {

/// The offscreen targets of one frame size.
struct Targets {
    glm::ivec2 size{0};
    gl::Texture color{gl::NoCreate}, position{gl::NoCreate}, normal{gl::NoCreate}, depth{gl::NoCreate}, output{gl::NoCreate};
    gl::Texture visibility{gl::NoCreate};        ///< R32F: compare's visibility output, or the reference's input
    gl::Framebuffer scene{gl::NoCreate}, resolve{gl::NoCreate}, visibilityOut{gl::NoCreate};

    explicit Targets(glm::ivec2 s) : size(s) {
        auto make = [&](GLenum format) {
            gl::Texture t(GL_TEXTURE_2D);
            glTextureStorage2D(t.id(), 1, format, size.x, size.y);
            glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            return t;
        };
        color = make(GL_RGBA16F);
        position = make(GL_RGBA32F);
        normal = make(GL_RGBA16F);
        depth = make(GL_DEPTH_COMPONENT32F);
        output = make(GL_RGBA8);
        visibility = make(GL_R32F);
        scene = gl::Framebuffer();
        glNamedFramebufferTexture(scene.id(), GL_COLOR_ATTACHMENT0 + SL_TARGET_COLOR, color.id(), 0);
        glNamedFramebufferTexture(scene.id(), GL_COLOR_ATTACHMENT0 + SL_TARGET_POSITION, position.id(), 0);
        glNamedFramebufferTexture(scene.id(), GL_COLOR_ATTACHMENT0 + SL_TARGET_NORMAL, normal.id(), 0);
        glNamedFramebufferTexture(scene.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        gl::checkFramebuffer(scene, "scene framebuffer");
        resolve = gl::Framebuffer();
        glNamedFramebufferTexture(resolve.id(), GL_COLOR_ATTACHMENT0, output.id(), 0);
        gl::checkFramebuffer(resolve, "resolve framebuffer");
        visibilityOut = gl::Framebuffer();
        glNamedFramebufferTexture(visibilityOut.id(), GL_COLOR_ATTACHMENT0, visibility.id(), 0);
        glNamedFramebufferTexture(visibilityOut.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        gl::checkFramebuffer(visibilityOut, "visibility framebuffer");
    }
};

/// GL_TIME_ELAPSED around a pass; results read after the frame.
class PassTimer {
public:
    explicit PassTimer(bool enabled) : enabled_(enabled) {}
    void begin(std::string name) {
        if (!enabled_) { names_.push_back(std::move(name)); return; }
        queries_.emplace_back(GL_TIME_ELAPSED);
        names_.push_back(std::move(name));
        glBeginQuery(GL_TIME_ELAPSED, queries_.back().id());
    }
    void end() { if (enabled_) glEndQuery(GL_TIME_ELAPSED); }
    std::vector<PassTiming> results() const {
        std::vector<PassTiming> out;
        for (std::size_t i = 0; i < names_.size(); ++i) {
            double ms = 0.0;
            if (enabled_) {
                GLuint64 ns = 0;
                glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
                ms = static_cast<double>(ns) * 1e-6;
            }
            out.push_back({names_[i], ms});
        }
        return out;
    }

private:
    bool enabled_;
    std::vector<gl::Query> queries_;
    std::vector<std::string> names_;
};

shared::LightUniforms lightUniforms(const Light& light) {
    shared::LightUniforms u{};
    u.radiance = glm::vec4(light.color * light.intensity, 0.0f);
    u.position = glm::vec4(light.position, 1.0f);
    u.direction = glm::vec4(glm::normalize(light.direction), 0.0f);
    const int type = light.type == LightType::Directional ? SL_LIGHT_DIRECTIONAL
                     : light.type == LightType::Spot      ? SL_LIGHT_SPOT
                                                          : SL_LIGHT_POINT;
    u.params = glm::vec4(light.range, std::cos(glm::radians(light.innerConeDeg)),
                         std::cos(glm::radians(light.outerConeDeg)), static_cast<float>(type));
    return u;
}

} // namespace

struct Renderer::Impl {
    Context& context;
    std::optional<GpuScene> gpu;
    std::size_t uploadedMeshes = 0, uploadedTextures = 0;
    std::optional<Targets> targets;
    std::map<std::uint32_t, gl::Program> programs;
    std::vector<std::pair<ShadowTechnique, std::unique_ptr<ShadowModule>>> modules; // per light
    gl::Buffer frameUbo, lightUbo, drawUbo;
    gl::VertexArray emptyVao;

    explicit Impl(Context& c) : context(c) {
        glNamedBufferStorage(frameUbo.id(), sizeof(shared::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        glNamedBufferStorage(lightUbo.id(), sizeof(shared::LightUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        glNamedBufferStorage(drawUbo.id(), sizeof(shared::DrawUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }

    FrameStats frame(const Scene& scene, const RenderOptions& options,
                     const std::vector<std::vector<float>>* screenVisibility);

    // Fills and binds the frame, light and draw uniform blocks; returns the camera's clipFromWorld.
    glm::mat4 bindFrameUniforms(const Scene& scene, glm::ivec2 size) {
        const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        shared::FrameUniforms u{};
        u.clipFromWorld = scene.camera.clipFromView(aspect) * scene.camera.viewFromWorld();
        u.cameraPosition = glm::vec4(scene.camera.position, 1.0f);
        u.ambient = glm::vec4(scene.ambient, 0.0f);
        glNamedBufferSubData(frameUbo.id(), 0, sizeof u, &u);
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_FRAME, frameUbo.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_LIGHT, lightUbo.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_DRAW, drawUbo.id());
        return u.clipFromWorld;
    }

    void setLight(const Light& light) {
        const shared::LightUniforms u = lightUniforms(light);
        glNamedBufferSubData(lightUbo.id(), 0, sizeof u, &u);
    }

    LightPassContext lightContext(const Scene& scene, std::size_t i, const std::vector<DrawItem>& items,
                                  const glm::mat4& clipFromWorld, glm::ivec2 size) {
        return LightPassContext{scene, scene.lights[i], static_cast<int>(i), items, *gpu, clipFromWorld, size,
                                [this, &scene, &items](const ShaderVariant& variant) { drawItems(scene, items, variant); }};
    }

    // Uploads rows top to bottom into GL's bottom-up texture.
    static void uploadVisibility(const Targets& t, const std::vector<float>& values) {
        std::vector<float> flipped(values.size());
        const std::size_t row = static_cast<std::size_t>(t.size.x);
        for (int y = 0; y < t.size.y; ++y)
            std::copy_n(values.begin() + static_cast<long>((t.size.y - 1 - y) * row), row, flipped.begin() + static_cast<long>(y * row));
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(t.visibility.id(), 0, 0, 0, t.size.x, t.size.y, GL_RED, GL_FLOAT, flipped.data());
        glBindTextureUnit(SL_UNIT_SCREEN_VISIBILITY, t.visibility.id());
    }

    const gl::Program& program(const ShaderVariant& variant) {
        const auto key = variant.key();
        auto it = programs.find(key);
        if (it == programs.end()) it = programs.emplace(key, gl::Program(variant.stages(), variant.preamble())).first;
        return it->second;
    }

    ShadowModule& module(std::size_t light, ShadowTechnique technique) {
        if (modules.size() <= light) modules.resize(light + 1);
        auto& [t, m] = modules[light];
        if (!m || t != technique) {
            m = createShadowModule(technique);
            t = technique;
        }
        return *m;
    }

    void setDraw(const Scene& scene, const DrawItem& item) {
        static const Material fallback;
        const Material& m = item.material >= 0 ? scene.materials[static_cast<std::size_t>(item.material)] : fallback;
        shared::DrawUniforms u{};
        u.worldFromObject = item.worldFromObject;
        u.normalFromObject = glm::mat4(glm::inverseTranspose(glm::mat3(item.worldFromObject)));
        u.baseColor = glm::vec4(m.baseColor, item.receivesShadows ? 1.0f : 0.0f);
        u.ambient = glm::vec4(m.ambient, 0.0f);
        u.diffuse = glm::vec4(m.diffuse, 0.0f);
        u.specular = glm::vec4(m.specular, m.shininess);
        glNamedBufferSubData(drawUbo.id(), 0, sizeof u, &u);
        if (m.baseColorTexture >= 0) glBindTextureUnit(SL_UNIT_BASE_COLOR, gpu->texture(m.baseColorTexture).id());
    }

    bool textured(const Scene& scene, const DrawItem& item) const {
        return item.material >= 0 && scene.materials[static_cast<std::size_t>(item.material)].baseColorTexture >= 0;
    }

    // Draws every item with the program for `variant`, choosing the textured
    // or untextured form per material.
    void drawItems(const Scene& scene, const std::vector<DrawItem>& items, ShaderVariant variant) {
        const gl::Program* current = nullptr;
        for (const DrawItem& item : items) {
            variant.baseColorTexture = textured(scene, item);
            const gl::Program& wanted = program(variant);
            if (&wanted != current) {  // switch programs only between textured and untextured items
                wanted.use();
                current = &wanted;
            }
            setDraw(scene, item);
            gpu->draw(item.mesh);
        }
    }
};

Renderer::Renderer(Context& context) : impl_(std::make_unique<Impl>(context)) {}
Renderer::~Renderer() = default;

void Renderer::upload(const Scene& scene) {
    impl_->gpu.emplace(scene);
    impl_->uploadedMeshes = scene.meshes.size();
    impl_->uploadedTextures = scene.textures.size();
}

FrameStats Renderer::render(const Scene& scene, const RenderOptions& options) {
    return impl_->frame(scene, options, nullptr);
}

FrameStats Renderer::renderWithVisibility(const Scene& scene, const RenderOptions& options,
                                          const std::vector<std::vector<float>>& visibility) {
    const std::size_t pixels = static_cast<std::size_t>(options.width) * static_cast<std::size_t>(std::max(options.height, 0));
    if (visibility.size() != scene.lights.size())
        throw Error("Renderer::renderWithVisibility: " + std::to_string(visibility.size()) + " visibility images for " +
                    std::to_string(scene.lights.size()) + " lights");
    for (const auto& v : visibility)
        if (v.size() != pixels) throw Error("Renderer::renderWithVisibility: a visibility image does not match the render size");
    return impl_->frame(scene, options, &visibility);
}

FrameStats Renderer::Impl::frame(const Scene& scene, const RenderOptions& options,
                                 const std::vector<std::vector<float>>* screenVisibility) {
    Impl& d = *this;
    const auto cpuStart = std::chrono::steady_clock::now();
    if (!d.gpu) throw Error("Renderer::render: no scene uploaded (call upload first)");
    if (scene.meshes.size() != d.uploadedMeshes || scene.textures.size() != d.uploadedTextures)
        throw Error("Renderer::render: the scene differs from the uploaded one (call upload again)");
    const GlInfo& info = d.context.info();
    const int limit = std::min({info.maxTextureSize, info.maxViewportWidth, info.maxViewportHeight});
    if (options.width < 1 || options.height < 1 || options.width > limit || options.height > limit)
        throw Error("render size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                    ": expected 1.." + std::to_string(limit) + " pixels per side (this GPU's limit)");
    const glm::ivec2 size(options.width, options.height);
    if (!d.targets || d.targets->size != size) d.targets.emplace(size);
    Targets& t = *d.targets;

    const auto items = scene.drawItems();
    const glm::mat4 clipFromWorld = d.bindFrameUniforms(scene, size);
    PassTimer timer(options.measureGpuTime);
    auto contextFor = [&](std::size_t i) { return d.lightContext(scene, i, items, clipFromWorld, size); };

    // 1. Shadow passes (each technique sets its own framebuffer and state).
    for (std::size_t i = 0; i < scene.lights.size() && !screenVisibility; ++i) {
        const Light& light = scene.lights[i];
        ShadowModule& module = d.module(i, light.shadow.technique);
        if (!module.hasShadowPass()) continue;
        timer.begin("shadow[" + std::to_string(i) + "]");
        module.renderShadowPass(contextFor(i));
        timer.end();
    }

    // 2. Base pass: depth, ambient, position, normal.
    glBindFramebuffer(GL_FRAMEBUFFER, t.scene.id());
    glViewport(0, 0, size.x, size.y);
    const GLenum all[] = {GL_COLOR_ATTACHMENT0 + SL_TARGET_COLOR, GL_COLOR_ATTACHMENT0 + SL_TARGET_POSITION,
                          GL_COLOR_ATTACHMENT0 + SL_TARGET_NORMAL};
    glNamedFramebufferDrawBuffers(t.scene.id(), 3, all);
    const glm::vec4 background(scene.background, 1.0f), zero(0.0f);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(t.scene.id(), GL_COLOR, SL_TARGET_COLOR, &background.x);
    glClearNamedFramebufferfv(t.scene.id(), GL_COLOR, SL_TARGET_POSITION, &zero.x);
    glClearNamedFramebufferfv(t.scene.id(), GL_COLOR, SL_TARGET_NORMAL, &zero.x);
    glClearNamedFramebufferfv(t.scene.id(), GL_DEPTH, 0, &farDepth);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    timer.begin("base");
    d.drawItems(scene, items, ShaderVariant{ShaderPass::Base});
    timer.end();

    // 3. One additive pass per light on the base pass's depth.
    const GLenum colorOnly[] = {GL_COLOR_ATTACHMENT0 + SL_TARGET_COLOR, GL_NONE, GL_NONE};
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        d.setLight(light);
        glBindFramebuffer(GL_FRAMEBUFFER, t.scene.id());
        glNamedFramebufferDrawBuffers(t.scene.id(), 3, colorOnly);
        glViewport(0, 0, size.x, size.y);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_EQUAL);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        ShaderVariant variant{ShaderPass::Light, light.type, light.shadow.technique};
        timer.begin("light[" + std::to_string(i) + "]");
        if (screenVisibility) {
            uploadVisibility(t, (*screenVisibility)[i]);
            variant.screenVisibility = true;
            d.drawItems(scene, items, variant);
        } else {
            d.module(i, light.shadow.technique).renderLightPass(contextFor(i), variant);
        }
        timer.end();
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);

    // 4. Resolve to sRGB.
    glBindFramebuffer(GL_FRAMEBUFFER, t.resolve.id());
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    timer.begin("resolve");
    d.program(ShaderVariant{ShaderPass::Resolve}).use();
    glBindTextureUnit(SL_UNIT_RESOLVE_INPUT, t.color.id());
    glBindVertexArray(d.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    timer.end();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    FrameStats stats;
    stats.passes = timer.results();
    glFinish();
    stats.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count();
    return stats;
}

namespace {
// Reads a texture and flips it so that rows go top to bottom.
template <class T>
std::vector<T> readTexture(const gl::Texture& texture, glm::ivec2 size, GLenum format, GLenum type, int components) {
    std::vector<T> data(static_cast<std::size_t>(size.x) * size.y * components);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(data.size() * sizeof(T)), data.data());
    const std::size_t row = static_cast<std::size_t>(size.x) * components;
    for (int y = 0; y < size.y / 2; ++y)
        std::swap_ranges(data.begin() + static_cast<long>(y * row), data.begin() + static_cast<long>((y + 1) * row),
                         data.begin() + static_cast<long>((size.y - 1 - y) * row));
    return data;
}
} // namespace

ImageRGBA8 Renderer::readColor() const {
    if (!impl_->targets) throw Error("Renderer::readColor: nothing rendered yet");
    const Targets& t = *impl_->targets;
    return {t.size.x, t.size.y, readTexture<std::uint8_t>(t.output, t.size, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
}

std::vector<float> Renderer::readVisibility(const Scene& scene, std::size_t lightIndex) {
    Impl& d = *impl_;
    if (!d.targets) throw Error("Renderer::readVisibility: nothing rendered yet");
    if (lightIndex >= scene.lights.size())
        throw Error("Renderer::readVisibility: light " + std::to_string(lightIndex) + " of " + std::to_string(scene.lights.size()));
    Targets& t = *d.targets;
    const Light& light = scene.lights[lightIndex];
    const auto items = scene.drawItems();
    const glm::mat4 clipFromWorld = d.bindFrameUniforms(scene, t.size);
    d.setLight(light);
    glBindFramebuffer(GL_FRAMEBUFFER, t.visibilityOut.id());
    glViewport(0, 0, t.size.x, t.size.y);
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(t.visibilityOut.id(), GL_COLOR, 0, zero);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_EQUAL);  // the last frame's depth: the same visible surfaces
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    ShaderVariant variant{ShaderPass::Light, light.type, light.shadow.technique};
    variant.outputVisibility = true;
    d.module(lightIndex, light.shadow.technique).renderLightPass(d.lightContext(scene, lightIndex, items, clipFromWorld, t.size), variant);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return readTexture<float>(t.visibility, t.size, GL_RED, GL_FLOAT, 1);
}

SurfaceBuffer Renderer::readSurfaces() const {
    if (!impl_->targets) throw Error("Renderer::readSurfaces: nothing rendered yet");
    const Targets& t = *impl_->targets;
    SurfaceBuffer out;
    out.width = t.size.x;
    out.height = t.size.y;
    const auto pos = readTexture<float>(t.position, t.size, GL_RGBA, GL_FLOAT, 4);
    const auto nrm = readTexture<float>(t.normal, t.size, GL_RGBA, GL_FLOAT, 4);
    out.position.resize(pos.size() / 4);
    out.normal.resize(nrm.size() / 4);
    for (std::size_t i = 0; i < out.position.size(); ++i) {
        out.position[i] = glm::vec4(pos[4 * i], pos[4 * i + 1], pos[4 * i + 2], pos[4 * i + 3]);
        out.normal[i] = glm::vec4(nrm[4 * i], nrm[4 * i + 1], nrm[4 * i + 2], nrm[4 * i + 3]);
    }
    return out;
}

} // namespace shadowlab
