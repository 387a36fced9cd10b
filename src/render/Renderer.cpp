// The frame: which passes run in which order (see Renderer.h), and the
// services the techniques get (TechniqueHost).
#include <shadowlab/Renderer.h>

#include "core/Plane.h"
#include "gl/Debug.h"
#include "render/DrawList.h"
#include "render/FrameTargets.h"
#include "render/GpuScene.h"
#include "render/ShaderVariant.h"
#include "techniques/Registry.h"

#include <shadowlab/Error.h>
#include <shadowlab/Techniques.h>

#include "shadowlab_shared.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>

namespace shadowlab {

namespace {

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
    if (light.type == LightType::Spot && light.projectorTexture >= 0) {
        // The spot's camera: along its axis, the image filling the square around the outer cone.
        const glm::vec3 axis = glm::normalize(light.direction);
        u.projectorFromWorld = glm::perspective(2.0f * glm::radians(light.outerConeDeg), 1.0f, 0.01f, 100.0f) *
                               glm::lookAt(light.position, light.position + axis, lightCameraUp(axis));
    }
    return u;
}

gl::ClockKind clockKind(TimingClock clock, const GlInfo& info) {
    switch (clock) {
    case TimingClock::Off: return gl::ClockKind::Off;
    case TimingClock::Auto: return gl::clockFor(info.renderer);
    case TimingClock::CpuFinish: return gl::ClockKind::CpuFinish;
    case TimingClock::GpuTimestamp: return gl::ClockKind::GpuTimestamp;
    }
    return gl::ClockKind::Off;
}

/// What drawLit draws: the light's shading, its visibility term (compare),
/// or the shading with the reference's visibility.
enum class LitMode { Shade, OutputVisibility, ScreenVisibility };

} // namespace

struct Renderer::Impl final : TechniqueHost {
    Context& context;
    gl::ProgramCache& programs;
    std::optional<GpuScene> gpu;
    std::size_t uploadedMeshes = 0, uploadedTextures = 0;
    std::optional<FrameTargets> targets;
    std::map<std::string, std::unique_ptr<Technique>, std::less<>> instances;
    DrawList drawList;
    gl::Buffer frameUbo, lightUbo;
    gl::VertexArray emptyVao;
    std::uint64_t frames = 0;
    bool lastFrameHadSurfaces = false;

    // The frame being drawn (valid inside frame(), readVisibility(), debugImages()).
    const Scene* scene = nullptr;
    std::vector<DrawItem> items;
    std::vector<Bounds> itemBounds;
    std::vector<std::optional<glm::vec4>> itemPlanes;
    std::vector<std::vector<glm::vec4>> itemConvex;
    std::optional<FrameInfo> info;
    std::optional<gl::PassClock> clock;
    LitMode litMode = LitMode::Shade;
    const Light* currentLight = nullptr;
    std::string currentPass;  // for count()
    std::vector<std::pair<std::string, double>> counters;
    std::vector<std::string> notes;

    // Techniques bind samplers to their units; none may leak into another's pass.
    static void resetTechniqueSamplers() {
        for (GLuint unit = SL_UNIT_SHADOW_FIRST; unit < SL_UNIT_SHADOW_FIRST + 8; ++unit) glBindSampler(unit, 0);
    }

    explicit Impl(Context& c) : context(c), programs(*c.impl().programs) {
        glNamedBufferStorage(frameUbo.id(), sizeof(shared::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        glNamedBufferStorage(lightUbo.id(), sizeof(shared::LightUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }

    // --- TechniqueHost ---------------------------------------------------------
    const gl::Program& program(const gl::ProgramKey& key) override { return programs.get(key); }
    void apply(const gl::RenderState& state) override { gl::apply(state); }

    void drawItems(ItemFilter filter, const gl::Program& prog, const std::function<bool(std::size_t)>& perItem,
                   Topology topology) override {
        bindOwnBlocks();
        prog.use();
        for (std::size_t i = 0; i < items.size(); ++i) {
            const DrawItem& item = items[i];
            if ((filter == ItemFilter::Casters && !item.castsShadows) || (filter == ItemFilter::Receivers && !item.receivesShadows))
                continue;
            if (perItem && !perItem(i)) continue;
            drawList.bind(i);
            // An alpha-tested caster's holes come from its texture (alpha_test.h).
            if (item.material >= 0) {
                const Material& m = scene->materials[static_cast<std::size_t>(item.material)];
                if (m.alphaTested() && m.baseColorTexture >= 0) glBindTextureUnit(SL_UNIT_BASE_COLOR, gpu->texture(m.baseColorTexture).id());
            }
            if (topology == Topology::TrianglesAdjacency)
                gpu->drawAdjacency(item.mesh, scene->meshes[static_cast<std::size_t>(item.mesh)]);
            else
                gpu->draw(item.mesh);
        }
    }

    void bindItem(std::size_t i) override {
        bindOwnBlocks();
        drawList.bind(i);
    }

    void drawFullscreenTriangle() override {
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    gl::RenderState litState() const override {
        gl::RenderState s;
        s.depthFunc = GL_EQUAL;  // the base pass's visible surfaces, bit for bit (scene.vert: invariant)
        s.depthWrite = false;
        if (litMode == LitMode::OutputVisibility) return s;  // overwrite: one light's term per pixel
        s.blend = true;
        s.blendSrc = s.blendDst = GL_ONE;
        s.framebufferSrgb = true;
        return s;
    }

    void drawLit(const gl::RenderState& state) override {
        const Light& light = *currentLight;
        ShaderVariant variant;
        variant.ambient = false;
        variant.light = true;
        variant.lightType = light.type;
        variant.outputVisibility = litMode == LitMode::OutputVisibility;
        variant.screenVisibility = litMode == LitMode::ScreenVisibility;
        variant.projector = hasProjector(light);
        setTechnique(variant, light);
        gl::apply(state);
        drawShaded(variant);
    }

    void bindFrameTarget() override {
        const bool visibility = litMode == LitMode::OutputVisibility;
        glBindFramebuffer(GL_FRAMEBUFFER, visibility ? targets->visibility.id() : targets->frame.id());
        if (!visibility) targets->drawBuffers(false);
        glViewport(0, 0, targets->size.x, targets->size.y);
    }

    const gl::Buffer& adjacencyIndices(int mesh) override {
        return gpu->adjacencyIndices(mesh, scene->meshes[static_cast<std::size_t>(mesh)]);
    }

    gl::ScopedPass timeScope(const std::string& name) override { return gl::ScopedPass(*clock, name); }
    void count(const std::string& name, double value) override { counters.emplace_back(currentPass + "." + name, value); }
    void note(const std::string& text) override {
        if (std::find(notes.begin(), notes.end(), text) == notes.end()) notes.push_back(text);
    }
    const GlInfo& glInfo() const override { return context.info(); }

    // --- The renderer's own work --------------------------------------------------
    void bindOwnBlocks() {
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_FRAME, frameUbo.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_LIGHT, lightUbo.id());
    }

    Technique& technique(const std::string& name) {
        auto it = instances.find(name);
        if (it == instances.end()) {
            const TechniqueEntry* entry = findTechniqueEntry(name);
            if (!entry) throw Error("Renderer: unknown shadow technique '" + name + "'");
            it = instances.emplace(name, entry->create()).first;
        }
        return *it->second;
    }

    void setTechnique(ShaderVariant& variant, const Light& light) {
        const TechniqueEntry* entry = findTechniqueEntry(light.shadow.technique);
        variant.techniqueFile = entry->shaderFile;
        variant.techniqueVertexFile = entry->vertexShaderFile;
        variant.techniqueDefines = technique(light.shadow.technique).lightPassDefines(light);
        variant.techniqueIncludes = technique(light.shadow.technique).lightPassIncludes(light);
    }

    void setLight(std::size_t i) {
        currentLight = &scene->lights[i];
        const shared::LightUniforms u = lightUniforms(*currentLight);
        glNamedBufferSubData(lightUbo.id(), 0, sizeof u, &u);
        if (hasProjector(*currentLight)) glBindTextureUnit(SL_UNIT_PROJECTOR, gpu->texture(currentLight->projectorTexture).id());
    }

    static bool hasProjector(const Light& light) { return light.type == LightType::Spot && light.projectorTexture >= 0; }

    LightView view(std::size_t i) const { return {scene->lights[i], static_cast<int>(i)}; }

    // Draws every item with the renderer's shading program for `variant`
    // (textured or untextured per material).
    void drawShaded(ShaderVariant variant) {
        bindOwnBlocks();
        variant.baseColorTexture = false;
        const gl::Program& plain = programs.get(variant.program());
        const gl::Program* textured = nullptr;
        const gl::Program* current = nullptr;
        static const Material fallback;
        for (std::size_t i = 0; i < items.size(); ++i) {
            const DrawItem& item = items[i];
            const Material& m = item.material >= 0 ? scene->materials[static_cast<std::size_t>(item.material)] : fallback;
            const gl::Program* wanted = &plain;
            if (m.baseColorTexture >= 0) {
                if (!textured) {
                    variant.baseColorTexture = true;
                    textured = &programs.get(variant.program());
                }
                wanted = textured;
                glBindTextureUnit(SL_UNIT_BASE_COLOR, gpu->texture(m.baseColorTexture).id());
            }
            if (wanted != current) {
                wanted->use();
                current = wanted;
            }
            drawList.bind(i);
            gpu->draw(item.mesh);
        }
    }

    void beginFrame(const Scene& s, glm::ivec2 size, double timeSeconds) {
        bool infiniteFar = false;
        for (const Light& light : s.lights) infiniteFar = infiniteFar || technique(light.shadow.technique).needsInfiniteFar(light);
        scene = &s;
        items = s.drawItems();
        itemBounds.clear();
        itemPlanes.clear();
        itemConvex.clear();
        for (const DrawItem& item : items) {
            std::vector<glm::vec4>& convex = itemConvex.emplace_back();
            for (const glm::vec4& plane : gpu->convex(item.mesh)) convex.push_back(transformPlane(plane, item.worldFromObject));
            itemBounds.push_back(gpu->bounds(item.mesh).transformed(item.worldFromObject));
            const std::optional<glm::vec4>& plane = gpu->plane(item.mesh);
            itemPlanes.push_back(plane ? std::optional<glm::vec4>(transformPlane(*plane, item.worldFromObject)) : std::nullopt);
        }
        const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        info.emplace(FrameInfo{s, items, itemBounds, itemPlanes, itemConvex, size});
        info->viewFromWorld = s.camera.viewFromWorld();
        info->clipFromView = infiniteFar ? s.camera.clipFromViewInfiniteFar(aspect) : s.camera.clipFromView(aspect);
        info->clipFromWorld = info->clipFromView * info->viewFromWorld;
        info->timeSeconds = timeSeconds;
        info->frameIndex = frames;
        shared::FrameUniforms u{};
        u.clipFromWorld = info->clipFromWorld;
        u.cameraPosition = glm::vec4(s.camera.position, 1.0f);
        u.ambient = glm::vec4(s.ambient, 0.0f);
        glNamedBufferSubData(frameUbo.id(), 0, sizeof u, &u);
        drawList.upload(s, items);
    }

    void checkScene(const Scene& s) const {
        if (!gpu) throw Error("Renderer: no scene uploaded (call upload first)");
        if (s.meshes.size() != uploadedMeshes || s.textures.size() != uploadedTextures)
            throw Error("Renderer: the scene differs from the uploaded one (call upload again)");
        for (std::size_t i = 0; i < s.lights.size(); ++i) {
            const std::string reason = unsupportedReason(s.lights[i].shadow.technique, s.lights[i]);
            if (!reason.empty()) throw Error("Renderer: light " + std::to_string(i) + " ('" + s.lights[i].name + "'): " + reason);
        }
    }

    FrameStats frame(const Scene& scene, const RenderOptions& options, const std::vector<std::vector<float>>* screenVisibility);
    /// The base pass: depth, clears, ambient and light `baseLight` (-1: none).
    void basePass(const Scene& s, const RenderOptions& options, int baseLight, const std::vector<std::vector<float>>* screenVisibility);
    /// Each light but `baseLight`, its pass added on the base pass's depth.
    void otherLights(const Scene& s, int baseLight, const std::vector<std::vector<float>>* screenVisibility);
};

Renderer::Renderer(Context& context) : impl_(std::make_unique<Impl>(context)) {}
Renderer::~Renderer() = default;

void Renderer::upload(const Scene& scene) {
    impl_->gpu.emplace(scene);
    impl_->uploadedMeshes = scene.meshes.size();
    impl_->uploadedTextures = scene.textures.size();
}

FrameStats Renderer::render(const Scene& scene, const RenderOptions& options) { return impl_->frame(scene, options, nullptr); }

FrameStats Renderer::renderWithVisibility(const Scene& scene, const RenderOptions& options,
                                          const std::vector<std::vector<float>>& visibility) {
    const std::size_t pixels = static_cast<std::size_t>(std::max(options.width, 0)) * static_cast<std::size_t>(std::max(options.height, 0));
    if (visibility.size() != scene.lights.size())
        throw Error("Renderer::renderWithVisibility: " + std::to_string(visibility.size()) + " visibility images for " +
                    std::to_string(scene.lights.size()) + " lights");
    for (const auto& v : visibility)
        if (v.size() != pixels) throw Error("Renderer::renderWithVisibility: a visibility image does not match the render size");
    return impl_->frame(scene, options, &visibility);
}

namespace {
// Uploads rows top to bottom into GL's bottom-up texture.
void uploadVisibility(const FrameTargets& t, const std::vector<float>& values) {
    std::vector<float> flipped(values.size());
    const std::size_t row = static_cast<std::size_t>(t.size.x);
    for (int y = 0; y < t.size.y; ++y)
        std::copy_n(values.begin() + static_cast<long>((t.size.y - 1 - y) * row), row, flipped.begin() + static_cast<long>(y * row));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(t.visibilityIn.id(), 0, 0, 0, t.size.x, t.size.y, GL_RED, GL_FLOAT, flipped.data());
    glBindTextureUnit(SL_UNIT_SCREEN_VISIBILITY, t.visibilityIn.id());
}
} // namespace

void Renderer::Impl::basePass(const Scene& s, const RenderOptions& options, int baseLight,
                              const std::vector<std::vector<float>>* screenVisibility) {
    const glm::ivec2 size = targets->size;
    currentPass = "base";
    resetTechniqueSamplers();
    const gl::ScopedPass scope(*clock, currentPass);
    ShaderVariant variant;
    variant.writeSurfaces = options.surfaces;
    if (baseLight >= 0) {
        setLight(static_cast<std::size_t>(baseLight));
        variant.light = true;
        variant.lightType = currentLight->type;
        variant.projector = hasProjector(*currentLight);
        if (screenVisibility) {
            variant.screenVisibility = true;
            uploadVisibility(*targets, (*screenVisibility)[static_cast<std::size_t>(baseLight)]);
        } else {
            setTechnique(variant, *currentLight);
            technique(currentLight->shadow.technique).bindLightPass(*this, *info, view(static_cast<std::size_t>(baseLight)));
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targets->frame.id());
    targets->drawBuffers(options.surfaces);
    glViewport(0, 0, size.x, size.y);
    gl::RenderState state;
    state.framebufferSrgb = true;  // linear radiance in, sRGB bytes stored
    gl::apply(state);              // all writes on: the clears below obey the masks
    const glm::vec4 background(s.background, 1.0f), zero(0.0f);
    glClearNamedFramebufferfv(targets->frame.id(), GL_COLOR, 0, &background.x);
    if (options.surfaces) {
        glClearNamedFramebufferfv(targets->frame.id(), GL_COLOR, SL_TARGET_POSITION, &zero.x);
        glClearNamedFramebufferfv(targets->frame.id(), GL_COLOR, SL_TARGET_NORMAL, &zero.x);
    }
    glClearNamedFramebufferfi(targets->frame.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    drawShaded(variant);
    targets->drawBuffers(false);
}

void Renderer::Impl::otherLights(const Scene& s, int baseLight, const std::vector<std::vector<float>>* screenVisibility) {
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        if (static_cast<int>(i) == baseLight) continue;
        setLight(i);
        currentPass = "light[" + std::to_string(i) + "]";
        const gl::ScopedPass scope(*clock, currentPass);
        resetTechniqueSamplers();
        bindFrameTarget();
        if (screenVisibility) {
            litMode = LitMode::ScreenVisibility;
            uploadVisibility(*targets, (*screenVisibility)[i]);
            drawLit(litState());
            litMode = LitMode::Shade;
        } else {
            technique(s.lights[i].shadow.technique).renderLightPass(*this, *info, view(i));
        }
    }
}

FrameStats Renderer::Impl::frame(const Scene& s, const RenderOptions& options,
                                 const std::vector<std::vector<float>>* screenVisibility) {
    const auto cpuStart = std::chrono::steady_clock::now();
    checkScene(s);
    const GlInfo& gl = context.info();
    const int limit = std::min({gl.maxTextureSize, gl.maxViewportWidth, gl.maxViewportHeight});
    if (options.width < 1 || options.height < 1 || options.width > limit || options.height > limit)
        throw Error("render size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                    ": expected 1.." + std::to_string(limit) + " pixels per side (this GPU's limit)");
    const glm::ivec2 size(options.width, options.height);
    if (!targets || targets->size != size || (options.surfaces && !targets->surfaces)) targets.emplace(size, options.surfaces);
    beginFrame(s, size, options.timeSeconds);
    info->measureFloors = options.measureFloors;
    clock.emplace(clockKind(options.clock, gl));
    litMode = LitMode::Shade;
    counters.clear();
    notes.clear();

    // Techniques in use, each with its lights; they prepare their resources.
    std::map<std::string, std::vector<int>> lightsOf;
    for (std::size_t i = 0; i < s.lights.size(); ++i) lightsOf[s.lights[i].shadow.technique].push_back(static_cast<int>(i));
    for (const auto& [name, lights] : lightsOf) technique(name).prepare(*this, *info, lights);

    // 1. Shadow passes (the reference brings its own visibility: none).
    for (std::size_t i = 0; i < s.lights.size() && !screenVisibility; ++i) {
        Technique& t = technique(s.lights[i].shadow.technique);
        if (!t.hasShadowPass(s.lights[i])) continue;
        setLight(i);
        currentPass = "shadow[" + std::to_string(i) + "]";
        const gl::ScopedPass scope(*clock, currentPass);
        t.renderShadowPass(*this, *info, view(i));
    }

    // 2. Base pass: depth, stencil cleared, ambient, and the first light
    // whose technique needs no pass of its own after this one.
    int baseLight = -1;
    for (std::size_t i = 0; i < s.lights.size() && baseLight < 0; ++i)
        if (screenVisibility || technique(s.lights[i].shadow.technique).sharesBasePass(s.lights[i])) baseLight = static_cast<int>(i);
    basePass(s, options, baseLight, screenVisibility);

    // 3. Every other light: its technique's pass on the base pass's depth.
    otherLights(s, baseLight, screenVisibility);
    gl::apply(gl::RenderState{});
    resetTechniqueSamplers();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    FrameStats stats;
    stats.counters = counters;
    stats.notes = notes;
    for (auto& [name, ms] : clock->results()) stats.passes.push_back({name, ms});
    stats.clock = gl::toString(clock->kind());
    stats.baseLight = baseLight;
    glFinish();
    stats.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count();
    ++frames;
    lastFrameHadSurfaces = options.surfaces;
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
    const FrameTargets& t = *impl_->targets;
    return {t.size.x, t.size.y, readTexture<std::uint8_t>(t.color, t.size, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
}

std::vector<glm::vec3> Renderer::readVisibilityRgb(const Scene& scene, std::size_t lightIndex) {
    Impl& d = *impl_;
    if (!d.targets) throw Error("Renderer::readVisibility: nothing rendered yet");
    if (lightIndex >= scene.lights.size())
        throw Error("Renderer::readVisibility: light " + std::to_string(lightIndex) + " of " + std::to_string(scene.lights.size()));
    d.checkScene(scene);
    FrameTargets& t = *d.targets;
    d.beginFrame(scene, t.size, d.info ? d.info->timeSeconds : 0.0);
    d.clock.emplace(gl::ClockKind::Off);
    d.setLight(lightIndex);
    d.litMode = LitMode::OutputVisibility;
    d.currentPass = "visibility";
    Impl::resetTechniqueSamplers();
    d.bindFrameTarget();
    gl::apply(gl::RenderState{});
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(t.visibility.id(), GL_COLOR, 0, zero);
    try {
        d.technique(scene.lights[lightIndex].shadow.technique).renderLightPass(d, *d.info, d.view(lightIndex));
    } catch (...) {
        d.litMode = LitMode::Shade;
        throw;
    }
    d.litMode = LitMode::Shade;
    gl::apply(gl::RenderState{});
    Impl::resetTechniqueSamplers();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const auto rgba = readTexture<float>(t.visibilityOut, t.size, GL_RGBA, GL_FLOAT, 4);
    std::vector<glm::vec3> out(rgba.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = glm::vec3(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]);
    return out;
}

std::vector<float> Renderer::readVisibility(const Scene& scene, std::size_t lightIndex) {
    const auto rgb = readVisibilityRgb(scene, lightIndex);
    std::vector<float> out(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) out[i] = (rgb[i].r + rgb[i].g + rgb[i].b) / 3.0f;
    return out;
}

std::vector<DebugImage> Renderer::debugImages(const Scene& scene) {
    Impl& d = *impl_;
    if (!d.targets) throw Error("Renderer::debugImages: nothing rendered yet");
    d.checkScene(scene);
    d.beginFrame(scene, d.targets->size, d.info ? d.info->timeSeconds : 0.0);
    d.clock.emplace(gl::ClockKind::Off);
    std::vector<DebugImage> out;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        std::vector<DebugImage> images;
        d.setLight(i);
        d.technique(scene.lights[i].shadow.technique).debugImages(d, *d.info, d.view(i), images);
        for (DebugImage& image : images) {
            image.name = "light" + std::to_string(i) + "-" + image.name;
            image.light = static_cast<int>(i);
            out.push_back(std::move(image));
        }
    }
    gl::apply(gl::RenderState{});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

std::vector<LightFrustum> Renderer::lightFrustums(const Scene& scene) const {
    const Impl& d = *impl_;
    if (!d.targets) throw Error("Renderer::lightFrustums: nothing rendered yet");
    d.checkScene(scene);
    std::vector<LightFrustum> out;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const auto found = d.instances.find(scene.lights[i].shadow.technique);
        if (found == d.instances.end()) continue;  // not drawn yet: no camera
        std::vector<glm::mat4> matrices;
        found->second->lightFrustums(LightView{scene.lights[i], static_cast<int>(i)}, matrices);
        for (const glm::mat4& m : matrices) out.push_back({static_cast<int>(i), m});
    }
    return out;
}

void Renderer::blitToDefaultFramebuffer() const {
    if (!impl_->targets) throw Error("Renderer::blitToDefaultFramebuffer: nothing rendered yet");
    const FrameTargets& t = *impl_->targets;
    gl::apply(gl::RenderState{});  // no sRGB conversion: the bytes as they are
    glNamedFramebufferReadBuffer(t.frame.id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(t.frame.id(), 0, 0, 0, t.size.x, t.size.y, 0, 0, t.size.x, t.size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

SurfaceBuffer Renderer::readSurfaces() const {
    if (!impl_->targets) throw Error("Renderer::readSurfaces: nothing rendered yet");
    if (!impl_->lastFrameHadSurfaces)
        throw Error("Renderer::readSurfaces: the last frame did not write surfaces (render with RenderOptions::surfaces = true)");
    const FrameTargets& t = *impl_->targets;
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
