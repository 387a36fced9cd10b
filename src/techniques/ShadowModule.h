#pragma once
// The interface every shadow technique implements, one module per technique
// (src/techniques/<Technique>.cpp). The renderer owns one module per light
// and calls it around that light's additive lighting pass.
#include "render/ShaderVariant.h"

#include <shadowlab/Scene.h>

#include <functional>
#include <memory>

namespace shadowlab {

class GpuScene;

/// What a technique may use while rendering one light.
struct LightPassContext {
    const Scene& scene;
    const Light& light;
    int lightIndex;
    const std::vector<DrawItem>& items;   ///< world transforms resolved
    const GpuScene& gpu;
    glm::mat4 clipFromWorld;              ///< the camera's
    glm::ivec2 viewport;                  ///< pixels
    /// Draws every item with the camera's lighting program for `variant`
    /// (the technique sets its fields first); additive blend, depth EQUAL.
    std::function<void(const ShaderVariant& variant)> drawLit;
};

class ShadowModule {
public:
    virtual ~ShadowModule() = default;
    /// Whether renderShadowPass does anything (only such passes are timed).
    virtual bool hasShadowPass() const { return false; }
    /// Runs before the base pass: render shadow maps and the like, with the
    /// technique's own framebuffer and state.
    virtual void renderShadowPass(const LightPassContext&) {}
    /// Draws the light's contribution. Sets its variant fields and binds its
    /// resources, then calls ctx.drawLit (stencil techniques wrap it).
    virtual void renderLightPass(const LightPassContext& ctx, ShaderVariant variant) { ctx.drawLit(variant); }
};

/// The module for `technique`; the renderer recreates it when a light's technique changes.
std::unique_ptr<ShadowModule> createShadowModule(ShadowTechnique technique);

} // namespace shadowlab
