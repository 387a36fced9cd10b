// Translucent (AlphaMode::Blend) surfaces: drawn last, over the lit opaque
// frame, farthest first. The base and light passes leave them out (they hold
// no depth, so the light passes' depth-EQUAL test and compare's surfaces see
// what is behind them); here each one gets all its terms before the next:
//   ambient:    colour = alpha * ambient + (1 - alpha) * colour
//   each light: colour += alpha * visibility * light
// which sums to alpha * (ambient + lights) over what was there. Visibility
// comes from the light's technique where its shader computes it per
// fragment (sharesBasePass: map, disc, none); stencil techniques (planar,
// volume) keep their shadow in the opaque surfaces' stencil, so on a
// translucent surface their light is unshadowed, and the frame says so.
#include "render/RendererImpl.h"

#include <algorithm>

namespace shadowlab {

void Renderer::Impl::blendedPass(const Scene& s, bool screenVisibility) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < items.size(); ++i)
        if (translucent(i)) order.push_back(i);
    if (order.empty()) return;
    currentPass = "blended";
    const gl::ScopedPass scope(*clock, currentPass);
    // Farthest first, by the distance from the eye to each item's bounds.
    std::vector<float> distance(items.size(), 0.0f);
    for (std::size_t i : order) {
        const glm::vec3 d = itemBounds[i].centre() - s.camera.position;
        distance[i] = glm::dot(d, d);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return distance[a] > distance[b]; });

    litMode = LitMode::Shade;
    bindFrameTarget();
    gl::RenderState over;
    over.depthWrite = false;  // the opaque depth tests them; they hide nothing behind them
    over.framebufferSrgb = true;
    over.blend = true;
    over.blendSrc = GL_SRC_ALPHA;
    over.blendDst = GL_ONE_MINUS_SRC_ALPHA;
    gl::RenderState add = over;
    add.blendDst = GL_ONE;

    for (std::size_t item : order) {
        const std::vector<std::size_t> one{item};
        resetTechniqueSamplers();
        ShaderVariant ambient;
        ambient.blended = true;
        gl::apply(over);
        drawShaded(ambient, &one);
        for (std::size_t i = 0; i < s.lights.size(); ++i) {
            setLight(i);
            resetTechniqueSamplers();
            ShaderVariant variant;
            variant.ambient = false;
            variant.light = true;
            variant.lightType = currentLight().type;
            variant.projector = hasProjector(currentLight());
            variant.blended = true;
            Technique& t = technique(currentLight().shadow.technique);
            if (!screenVisibility && t.sharesBasePass(currentLight())) {
                setTechnique(variant);
                t.bindLightPass(*this, *info, view(i));
            } else if (!screenVisibility) {
                note("light " + std::to_string(i) + " ('" + currentLight().name + "'): technique '" + currentLight().shadow.technique +
                     "' keeps its shadow in the stencil of opaque surfaces, so translucent (blend) surfaces are lit unshadowed");
            }
            gl::apply(add);
            drawShaded(variant, &one);
        }
    }
}

} // namespace shadowlab
