#pragma once
// The renderer's state and the services it gives techniques
// (TechniqueHost). Its passes: Renderer.cpp (shadow, base and light passes,
// in frame()), BlendedPass.cpp (translucent surfaces, last); the host
// services: RendererHost.cpp.
#include "gl/Debug.h"
#include "core/ScreenRect.h"
#include "render/DrawList.h"
#include "render/FrameTargets.h"
#include "render/GpuScene.h"
#include "render/LightList.h"
#include "render/ShaderVariant.h"
#include "techniques/Registry.h"

#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>

#include "gl/Calls.h"
#include "shadowlab_shared.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

/// A light's block (also the clustered light list's entries).
shared::LightUniforms lightUniforms(const Light& light);

/// What drawLit draws: the light's shading, its visibility term (compare),
/// or the shading with the reference's visibility.
enum class LitMode { Shade, OutputVisibility, ScreenVisibility };

struct Renderer::Impl final : TechniqueHost {
    Context& context;
    gl::ProgramCache& programs;
    std::optional<GpuScene> gpu;
    std::size_t uploadedMeshes = 0, uploadedTextures = 0;
    std::uint64_t uploads = 0;  ///< Renderer::upload calls (FrameInfo::sceneUpload)
    std::optional<FrameTargets> targets;
    std::map<std::string, std::unique_ptr<Technique>, std::less<>> instances;
    DrawList drawList;
    LightList lightList;
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
    std::vector<std::int8_t> itemWinding;
    /// The opaque items nearest first (their boxes' centres along the
    /// view): drawShaded's order, so that the depth test rejects hidden
    /// fragments before they are shaded.
    std::vector<std::size_t> opaqueOrder;
    std::optional<FrameInfo> info;
    std::optional<gl::PassClock> clock;
    LitMode litMode = LitMode::Shade;
    bool depthPrepassed = false;  ///< this frame's depth drawn before the base pass (beginDepthPrepass)
    std::size_t currentIndex = 0; ///< the light being drawn, in Scene::lights (setLight)
    const Light& currentLight() const { return scene->lights[currentIndex]; }
    std::string currentPass;  // for count()
    std::vector<std::pair<std::string, double>> counters;
    std::vector<std::string> notes;

    // Techniques bind samplers to their units; none may leak into another's pass.
    static void resetTechniqueSamplers() {
        for (GLuint unit = SL_UNIT_SHADOW_FIRST; unit < SL_UNIT_SHADOW_FIRST + 8; ++unit) glBindSampler(unit, 0);
    }

    explicit Impl(Context& c) : context(c), programs(*c.impl().programs) {
        gl::namedBufferStorage(frameUbo.id(), sizeof(shared::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        gl::namedBufferStorage(lightUbo.id(), sizeof(shared::LightUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }

    // --- TechniqueHost ---------------------------------------------------------
    const gl::Program& program(const gl::ProgramKey& key) override { return programs.get(key); }
    void apply(const gl::RenderState& state) override { gl::apply(state); }

    void drawItems(ItemFilter filter, const gl::Program& prog, const std::function<bool(std::size_t)>& perItem,
                   Topology topology, const std::function<int(std::size_t)>& level) override;

    void bindItem(std::size_t i) override {
        bindOwnBlocks();
        drawList.bind(i);
    }

    void drawFullscreenTriangle() override {
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    gl::RenderState litState() const override;

    void drawLit(const gl::RenderState& state) override;

    bool beginDepthPrepass() override;
    const gl::Texture& frameDepth() const override { return targets->depthStencil; }

    void bindFrameTarget() override {
        const bool visibility = litMode == LitMode::OutputVisibility;
        glBindFramebuffer(GL_FRAMEBUFFER, visibility ? targets->visibility.id() : targets->frame.id());
        if (!visibility) targets->drawBuffers(false);
        glViewport(0, 0, targets->size.x, targets->size.y);
    }

    const std::vector<DetailLevel>& detailLevels(std::size_t item) override { return gpu->levels(items[item].mesh, *scene); }

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

    /// The light's technique into `variant` (its files, defines and slots).
    void setTechnique(ShaderVariant& variant);  ///< the current light's (setLight)

    /// Makes light i current: its block uploaded, its projector bound.
    void setLight(std::size_t i);

    static bool hasProjector(const Light& light) { return light.type == LightType::Spot && light.projectorTexture >= 0; }

    LightView view(std::size_t i) const { return {scene->lights[i], static_cast<int>(i)}; }

    // Draws with the renderer's shading program for `variant` (textured or
    // untextured per material) the items in `only`, or every opaque one.
    void drawShaded(ShaderVariant variant, const std::vector<std::size_t>* only = nullptr);
    /// drawShaded, the light's test (in `variant`) run only on items that
    /// receive shadows, in the pixels of `region` (its technique's
    /// shadowedPixels; null: anywhere), and the rest shaded lit without it,
    /// under `state` (RegionDraw.cpp).
    void drawShadedByRegion(const ShaderVariant& variant, const gl::RenderState& state, const std::vector<PixelRect>* region);

    /// Whether item i is a translucent (AlphaMode::Blend) surface.
    bool translucent(std::size_t i) const {
        const int m = items[i].material;
        return m >= 0 && scene->materials[static_cast<std::size_t>(m)].alphaMode == AlphaMode::Blend;
    }

    void beginFrame(const Scene& s, glm::ivec2 size, double timeSeconds);

    void checkScene(const Scene& s) const;

    FrameStats frame(const Scene& scene, const RenderOptions& options, const std::vector<std::vector<float>>* screenVisibility);
    /// The base pass: depth, clears, ambient and light `baseLight` (-1: none).
    void basePass(const Scene& s, const RenderOptions& options, int baseLight, const std::vector<std::vector<float>>* screenVisibility);
    /// The lights in `listed` (indices, at least one) in one pass over the
    /// clustered light list, added on the base pass's depth.
    void lightListPass(const Scene& s, const std::vector<int>& listed);
    /// Each light but `baseLight` and those in `listed`, its pass added on the base pass's depth.
    void otherLights(const Scene& s, int baseLight, const std::vector<int>& listed, const std::vector<std::vector<float>>* screenVisibility);
    /// Translucent surfaces over the lit frame, back to front (BlendedPass.cpp).
    void blendedPass(const Scene& s, bool screenVisibility);
};

} // namespace shadowlab
