// The frame: which passes run in which order (Renderer.h); the renderer's state and its services to techniques: RendererImpl.h.
#include "render/RendererImpl.h"

#include "gl/Calls.h"
#include "gl/Debug.h"
#include "gl/SavedState.h"

#include <shadowlab/Techniques.h>

#include <chrono>
#include <set>
#include <cmath>

namespace shadowlab {

namespace {

gl::ClockKind clockKind(TimingClock clock, const GlInfo& info) {
    switch (clock) {
    case TimingClock::Off: return gl::ClockKind::Off;
    case TimingClock::Auto: return gl::clockFor(info.renderer);
    case TimingClock::CpuFinish: return gl::ClockKind::CpuFinish;
    case TimingClock::GpuTimestamp: return gl::ClockKind::GpuTimestamp;
    }
    return gl::ClockKind::Off;
}

} // namespace

Renderer::Renderer(Context& context) {
    const gl::CallerState kept(context.impl().adopted);
    impl_ = std::make_unique<Impl>(context);
}
Renderer::~Renderer() = default;

void Renderer::upload(const Scene& scene) {
    const gl::CallerState kept(impl_->context.impl().adopted);
    impl_->gpu.emplace(scene);
    impl_->uploadedMeshes = scene.meshes.size();
    ++impl_->uploads;
    impl_->uploadedTextures = scene.textures.size();
    gl::throwIfOutOfMemory("while uploading the scene's meshes and textures");
}

FrameStats Renderer::render(const Scene& scene, const RenderOptions& options) {
    const gl::CallerState kept(impl_->context.impl().adopted);  // Context::adoptCurrent: the caller's GL state back after the call
    return impl_->frame(scene, options, nullptr);
}

FrameStats Renderer::renderWithVisibility(const Scene& scene, const RenderOptions& options,
                                          const std::vector<std::vector<float>>& visibility) {
    const std::size_t pixels = static_cast<std::size_t>(std::max(options.width, 0)) * static_cast<std::size_t>(std::max(options.height, 0));
    if (visibility.size() != scene.lights.size())
        throw Error("Renderer::renderWithVisibility: " + std::to_string(visibility.size()) + " visibility images for " +
                    std::to_string(scene.lights.size()) + " lights");
    for (const auto& v : visibility)
        if (v.size() != pixels) throw Error("Renderer::renderWithVisibility: a visibility image does not match the render size");
    const gl::CallerState kept(impl_->context.impl().adopted);
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
    gl::textureSubImage2D(t.visibilityIn.id(), 0, 0, 0, t.size.x, t.size.y, GL_RED, GL_FLOAT, flipped.data());
    gl::bindTextureUnit(SL_UNIT_SCREEN_VISIBILITY, t.visibilityIn.id());
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
        variant.lightType = currentLight().type;
        variant.projector = hasProjector(currentLight());
        if (screenVisibility) {
            variant.screenVisibility = true;
            uploadVisibility(*targets, (*screenVisibility)[static_cast<std::size_t>(baseLight)]);
        } else {
            setTechnique(variant);
            technique(currentLight().shadow.technique).bindLightPass(*this, *info, view(static_cast<std::size_t>(baseLight)));
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targets->frame.id());
    targets->drawBuffers(options.surfaces);
    glViewport(0, 0, size.x, size.y);
    gl::RenderState state;
    state.framebufferSrgb = true;  // linear radiance in, sRGB bytes stored
    gl::apply(state);              // all writes on: the clears below obey the masks
    const glm::vec4 background(s.background, 1.0f), zero(0.0f);
    gl::clearNamedFramebufferfv(targets->frame.id(), GL_COLOR, 0, &background.x);
    if (options.surfaces) {
        gl::clearNamedFramebufferfv(targets->frame.id(), GL_COLOR, SL_TARGET_POSITION, &zero.x);
        gl::clearNamedFramebufferfv(targets->frame.id(), GL_COLOR, SL_TARGET_NORMAL, &zero.x);
    }
    if (depthPrepassed) {
        // A technique drew this frame's depth first (beginDepthPrepass): kept.
        count("depthPrepass", 1.0);
        const GLint none = 0;
        gl::clearNamedFramebufferiv(targets->frame.id(), GL_STENCIL, 0, &none);
        state.depthFunc = GL_LEQUAL;
        gl::apply(state);
    } else {
        gl::clearNamedFramebufferfi(targets->frame.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    }
    // The light's test only on items that receive shadows and where its
    // shadows can fall, the rest shaded lit without it (RegionDraw.cpp).
    // The rectangles split items, whose lit draw's fragments where the
    // test's drew already fail the depth test (LESS) before they are
    // shaded: not on a depth pre-pass (LEQUAL: they would pass). Neither
    // with the surfaces (compare's reference images, drawn as they were).
    const bool regions = baseLight >= 0 && !screenVisibility && options.shadowRegions && !options.surfaces;
    const std::optional<std::vector<PixelRect>> region =
        regions && !depthPrepassed ? technique(currentLight().shadow.technique).shadowedPixels(*info, view(static_cast<std::size_t>(baseLight)))
                                   : std::nullopt;
    if (regions)
        drawShadedByRegion(variant, state, region ? &*region : nullptr);
    else
        drawShaded(variant);
    targets->drawBuffers(false);
}

void Renderer::Impl::lightListPass(const Scene& s, const std::vector<int>& listed) {
    currentPass = "lights";
    const gl::ScopedPass scope(*clock, currentPass);
    // Each light's shadow in the atlas, if any, and what its technique binds for it.
    std::vector<glm::vec4> shadows;
    std::set<std::string> shadowed;
    for (int i : listed) {
        const std::string& name = s.lights[static_cast<std::size_t>(i)].shadow.technique;
        shadows.push_back(technique(name).listedShadow(view(static_cast<std::size_t>(i))));
        if (shadows.back().y > 0.0f) shadowed.insert(name);
    }
    lightList.upload(s, listed, shadows, info->viewFromWorld, info->clipFromView, targets->size);
    count("listed", static_cast<double>(listed.size()));
    count("tileEntries", static_cast<double>(lightList.tiles().entries));
    count("culled", static_cast<double>(lightList.tiles().culled));
    resetTechniqueSamplers();
    litMode = LitMode::Shade;
    bindFrameTarget();
    lightList.bind();
    for (const std::string& name : shadowed) technique(name).bindLightList(*this);
    ShaderVariant variant;
    variant.ambient = false;
    variant.lightList = true;
    variant.lightListShadows = !shadowed.empty();
    // One lookup fills the list's slot: one technique's listed shadows a pass.
    if (shadowed.size() > 1) throw Error("the light list: listed shadows of more than one technique (" + *shadowed.begin() + ", " + *std::next(shadowed.begin()) + ")");
    if (!shadowed.empty()) {
        variant.listShadowFile = technique(*shadowed.begin()).listShadowFile();
        if (variant.listShadowFile.empty()) throw Error("technique " + *shadowed.begin() + ": listed lights with shadows, and no Technique::listShadowFile to look them up");
    }
    gl::apply(litState());
    drawShaded(variant);
}

void Renderer::Impl::otherLights(const Scene& s, int baseLight, const std::vector<int>& listed,
                                 const std::vector<std::vector<float>>* screenVisibility) {
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        if (static_cast<int>(i) == baseLight) continue;
        if (std::find(listed.begin(), listed.end(), static_cast<int>(i)) != listed.end()) continue;
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
        throw InputError("render size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                    ": expected 1.." + std::to_string(limit) + " pixels per side (this GPU's limit)");
    const glm::ivec2 size(options.width, options.height);
    if (!targets || targets->size != size || (options.surfaces && !targets->surfaces)) targets.emplace(size, options.surfaces);
    beginFrame(s, size, options.timeSeconds);
    info->measureFloors = options.measureFloors;
    info->shadowRegions = options.shadowRegions;
    info->reuseShadowMaps = options.reuseShadowMaps;
    info->cacheShadowMaps = options.cacheShadowMaps;
    info->sceneUpload = uploads;
    clock.emplace(clockKind(options.clock, gl));
    litMode = LitMode::Shade;
    counters.clear();
    notes.clear();
    depthPrepassed = false;

    // Techniques in use, each with its lights; they prepare their resources.
    std::map<std::string, std::vector<int>> lightsOf;
    for (std::size_t i = 0; i < s.lights.size(); ++i) lightsOf[s.lights[i].shadow.technique].push_back(static_cast<int>(i));
    for (const auto& [name, lights] : lightsOf) technique(name).prepare(*this, *info, lights);

    // 1. Shadow passes (the reference brings its own visibility, and a
    // frame through the previous frame's maps keeps them: none).
    for (std::size_t i = 0; i < s.lights.size() && !screenVisibility && !options.reuseShadowMaps; ++i) {
        Technique& t = technique(s.lights[i].shadow.technique);
        if (!t.hasShadowPass(s.lights[i])) continue;
        setLight(i);
        currentPass = "shadow[" + std::to_string(i) + "]";
        const gl::ScopedPass scope(*clock, currentPass);
        t.renderShadowPass(*this, *info, view(i));
    }

    // 2. Base pass: depth (unless a shadow pass drew it first:
    // beginDepthPrepass), stencil cleared, ambient, and the first light
    // whose technique needs no pass of its own after this one.
    int baseLight = -1;
    for (std::size_t i = 0; i < s.lights.size() && baseLight < 0; ++i)
        if (screenVisibility || technique(s.lights[i].shadow.technique).sharesBasePass(s.lights[i])) baseLight = static_cast<int>(i);
    basePass(s, options, baseLight, screenVisibility);

    // 3. The lights without a shadow pass after the base pass (none, or a
    // map in the shadow atlas) beyond the base pass's, two or more of
    // them, in one pass over a clustered list; every other light: its
    // technique's pass. Both on the base pass's depth.
    std::vector<int> listed;
    for (std::size_t i = 0; i < s.lights.size() && options.groupLights && !screenVisibility; ++i)
        if (static_cast<int>(i) != baseLight && !hasProjector(s.lights[i]) && technique(s.lights[i].shadow.technique).joinsLightList(view(i)))
            listed.push_back(static_cast<int>(i));
    if (listed.size() < 2) listed.clear();
    if (!listed.empty()) lightListPass(s, listed);
    otherLights(s, baseLight, listed, screenVisibility);

    // 4. Translucent surfaces, blended over the rest, back to front.
    blendedPass(s, screenVisibility != nullptr);
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
    gl::throwIfOutOfMemory("while drawing the frame");
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
    gl::getTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(data.size() * sizeof(T)), data.data());
    const std::size_t row = static_cast<std::size_t>(size.x) * components;
    for (int y = 0; y < size.y / 2; ++y)
        std::swap_ranges(data.begin() + static_cast<long>(y * row), data.begin() + static_cast<long>((y + 1) * row),
                         data.begin() + static_cast<long>((size.y - 1 - y) * row));
    return data;
}
} // namespace

ImageRGBA8 Renderer::readColor() const {
    const gl::CallerState kept(impl_->context.impl().adopted);
    if (!impl_->targets) throw Error("Renderer::readColor: nothing rendered yet");
    const FrameTargets& t = *impl_->targets;
    return {t.size.x, t.size.y, readTexture<std::uint8_t>(t.color, t.size, GL_RGBA, GL_UNSIGNED_BYTE, 4)};
}

std::vector<glm::vec3> Renderer::readVisibilityRgb(const Scene& scene, std::size_t lightIndex) {
    const gl::CallerState kept(impl_->context.impl().adopted);
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
    gl::clearNamedFramebufferfv(t.visibility.id(), GL_COLOR, 0, zero);
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

std::vector<DebugImage> Renderer::debugImages(const Scene& scene, const DebugImageKinds& kinds) {
    const gl::CallerState kept(impl_->context.impl().adopted);
    Impl& d = *impl_;
    if (!d.targets) throw Error("Renderer::debugImages: nothing rendered yet");
    d.checkScene(scene);
    d.beginFrame(scene, d.targets->size, d.info ? d.info->timeSeconds : 0.0);
    d.clock.emplace(gl::ClockKind::Off);
    std::vector<DebugImage> out;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        std::vector<DebugImage> images;
        d.setLight(i);
        d.technique(scene.lights[i].shadow.technique).debugImages(d, *d.info, d.view(i), kinds, images);
        for (DebugImage& image : images) {
            if (!kinds.wants(image.kind)) continue;  // a technique that makes every kind regardless
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
    const gl::CallerState kept(impl_->context.impl().adopted);
    if (!impl_->targets) throw Error("Renderer::blitToDefaultFramebuffer: nothing rendered yet");
    const FrameTargets& t = *impl_->targets;
    gl::apply(gl::RenderState{});  // no sRGB conversion: the bytes as they are
    gl::namedFramebufferReadBuffer(t.frame.id(), GL_COLOR_ATTACHMENT0);
    gl::blitNamedFramebuffer(t.frame.id(), 0, 0, 0, t.size.x, t.size.y, 0, 0, t.size.x, t.size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

SurfaceBuffer Renderer::readSurfaces() const {
    const gl::CallerState kept(impl_->context.impl().adopted);
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
