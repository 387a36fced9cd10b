// The services the renderer gives techniques (TechniqueHost) and the
// frame's shared steps: lights, technique variants, shaded draws.
#include "render/RendererImpl.h"

#include "geometry/Plane.h"
#include "gl/Calls.h"

#include <shadowlab/Error.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

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

void Renderer::Impl::drawItems(ItemFilter filter, const gl::Program& prog, const std::function<bool(std::size_t)>& perItem,
                               Topology topology, const std::function<int(std::size_t)>& level) {
    bindOwnBlocks();
    prog.use();
    for (std::size_t i = 0; i < items.size(); ++i) {
        const DrawItem& item = items[i];
        if ((filter == ItemFilter::Casters && !item.castsShadows) || (filter == ItemFilter::Receivers && !item.receivesShadows) ||
            (filter == ItemFilter::Opaque && translucent(i)))
            continue;
        if (perItem && !perItem(i)) continue;
        drawList.bind(i);
        // An alpha-tested caster's holes come from its texture (alpha_test.h).
        if (item.material >= 0) {
            const Material& m = scene->materials[static_cast<std::size_t>(item.material)];
            if (m.alphaTested() && m.baseColorTexture >= 0) gl::bindTextureUnit(SL_UNIT_BASE_COLOR, gpu->texture(m.baseColorTexture).id());
        }
        if (topology == Topology::TrianglesAdjacency)
            gpu->drawAdjacency(item.mesh, scene->meshes[static_cast<std::size_t>(item.mesh)]);
        else if (level)
            gpu->drawLevel(item.mesh, level(i));
        else
            gpu->draw(item.mesh);
    }
}

bool Renderer::Impl::beginDepthPrepass() {
    if (depthPrepassed) return false;
    glBindFramebuffer(GL_FRAMEBUFFER, targets->frame.id());
    targets->drawBuffers(false);
    glViewport(0, 0, targets->size.x, targets->size.y);
    gl::apply(gl::RenderState{});  // depth writes on: the clear obeys the masks
    gl::clearNamedFramebufferfi(targets->frame.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    depthPrepassed = true;
    return true;
}

gl::RenderState Renderer::Impl::litState() const {
    gl::RenderState s;
    s.depthFunc = GL_EQUAL;  // the base pass's visible surfaces, bit for bit (scene.vert: invariant)
    s.depthWrite = false;
    if (litMode == LitMode::OutputVisibility) return s;  // overwrite: one light's term per pixel
    s.blend = true;
    s.blendSrc = s.blendDst = GL_ONE;
    s.framebufferSrgb = true;
    return s;
}

void Renderer::Impl::drawLit(const gl::RenderState& state) {
    const Light& light = currentLight();
    ShaderVariant variant;
    variant.ambient = false;
    variant.light = true;
    variant.lightType = light.type;
    variant.outputVisibility = litMode == LitMode::OutputVisibility;
    variant.screenVisibility = litMode == LitMode::ScreenVisibility;
    variant.projector = hasProjector(light);
    setTechnique(variant);
    gl::apply(state);
    drawShaded(variant);
}

void Renderer::Impl::setTechnique(ShaderVariant& variant) {
    const LightView light = view(currentIndex);
    const TechniqueEntry* entry = findTechniqueEntry(light.light.shadow.technique);
    variant.techniqueFile = entry->shaderFile;
    variant.techniqueVertexFile = entry->vertexShaderFile;
    variant.techniqueDefines = technique(light.light.shadow.technique).lightPassDefines(light);
    variant.techniqueIncludes = technique(light.light.shadow.technique).lightPassIncludes(light);
}

void Renderer::Impl::setLight(std::size_t i) {
    currentIndex = i;
    const shared::LightUniforms u = lightUniforms(currentLight());
    gl::namedBufferSubData(lightUbo.id(), 0, sizeof u, &u);
    if (hasProjector(currentLight())) gl::bindTextureUnit(SL_UNIT_PROJECTOR, gpu->texture(currentLight().projectorTexture).id());
}

void Renderer::Impl::drawShaded(ShaderVariant variant, const std::vector<std::size_t>* only) {
    bindOwnBlocks();
    // The programs this draw list needs, by (base colour texture, alpha test).
    const gl::Program* byKind[4] = {nullptr, nullptr, nullptr, nullptr};
    const gl::Program* current = nullptr;
    static const Material fallback;
    const std::vector<std::size_t>& order = only ? *only : opaqueOrder;  // translucent items: drawn last, blended (blendedPass)
    for (const std::size_t i : order) {
        const DrawItem& item = items[i];
        const Material& m = item.material >= 0 ? scene->materials[static_cast<std::size_t>(item.material)] : fallback;
        const bool textured = m.baseColorTexture >= 0, masked = m.alphaMode == AlphaMode::Mask;
        const gl::Program*& wanted = byKind[(textured ? 1 : 0) | (masked ? 2 : 0)];
        if (!wanted) {
            variant.baseColorTexture = textured;
            variant.alphaTest = masked;
            wanted = &programs.get(variant.program());
        }
        if (textured) gl::bindTextureUnit(SL_UNIT_BASE_COLOR, gpu->texture(m.baseColorTexture).id());
        if (wanted != current) {
            wanted->use();
            current = wanted;
        }
        drawList.bind(i);
        gpu->draw(item.mesh);
    }
}

void Renderer::Impl::beginFrame(const Scene& s, glm::ivec2 size, double timeSeconds) {
    bool infiniteFar = false;
    for (const Light& light : s.lights) infiniteFar = infiniteFar || technique(light.shadow.technique).needsInfiniteFar(light);
    if (infiniteFar && s.camera.orthoHeight > 0.0f)
        throw UnsupportedError("camera.orthoHeight: shadow volumes need a perspective camera (their far caps lie at infinity); set camera.orthoHeight 0 or another technique");
    scene = &s;
    items = s.drawItems();
    itemBounds.clear();
    itemPlanes.clear();
    itemConvex.clear();
    itemWinding.clear();
    for (const DrawItem& item : items) {
        // A mirroring transform turns the mesh's winding round.
        const int winding = gpu->winding(item.mesh) * (glm::determinant(glm::mat3(item.worldFromObject)) < 0.0f ? -1 : 1);
        itemWinding.push_back(static_cast<std::int8_t>(winding));
        std::vector<glm::vec4>& convex = itemConvex.emplace_back();
        for (const glm::vec4& plane : gpu->convex(item.mesh)) convex.push_back(transformPlane(plane, item.worldFromObject));
        itemBounds.push_back(gpu->bounds(item.mesh).transformed(item.worldFromObject));
        const std::optional<glm::vec4>& plane = gpu->plane(item.mesh);
        itemPlanes.push_back(plane ? std::optional<glm::vec4>(transformPlane(*plane, item.worldFromObject)) : std::nullopt);
    }
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    info.emplace(FrameInfo{s, items, itemBounds, itemPlanes, itemConvex, itemWinding, size});
    info->viewFromWorld = s.camera.viewFromWorld();
    info->clipFromView = infiniteFar ? s.camera.clipFromViewInfiniteFar(aspect) : s.camera.clipFromView(aspect);
    info->clipFromWorld = info->clipFromView * info->viewFromWorld;
    // Nearest first: a fragment behind one already drawn fails the depth
    // test before it is shaded (a rasteriser tests depth early where the
    // shader neither discards nor writes depth). Ties keep the scene's order.
    opaqueOrder.clear();
    std::vector<float> viewDepth(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (translucent(i)) continue;
        opaqueOrder.push_back(i);
        const float z = itemBounds[i].empty() ? 0.0f : -(info->viewFromWorld * glm::vec4(itemBounds[i].centre(), 1.0f)).z;
        viewDepth[i] = std::isfinite(z) ? z : 0.0f;
    }
    std::stable_sort(opaqueOrder.begin(), opaqueOrder.end(), [&](std::size_t a, std::size_t b) { return viewDepth[a] < viewDepth[b]; });
    info->timeSeconds = timeSeconds;
    info->frameIndex = frames;
    shared::FrameUniforms u{};
    u.clipFromWorld = info->clipFromWorld;
    u.cameraPosition = glm::vec4(s.camera.position, 1.0f);
    u.ambient = glm::vec4(s.ambient, 0.0f);
    gl::namedBufferSubData(frameUbo.id(), 0, sizeof u, &u);
    drawList.upload(s, items);
}

void Renderer::Impl::checkScene(const Scene& s) const {
    if (!gpu) throw Error("Renderer: no scene uploaded (call upload first)");
    if (s.meshes.size() != uploadedMeshes || s.textures.size() != uploadedTextures)
        throw Error("Renderer: the scene differs from the uploaded one (call upload again)");
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const std::string reason = unsupportedReason(s.lights[i].shadow.technique, s.lights[i]);
        if (!reason.empty()) throw InputError("Renderer: light " + std::to_string(i) + " ('" + s.lights[i].name + "'): " + reason);
    }
}

} // namespace shadowlab
