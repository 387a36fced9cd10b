// Technique "map": shadow maps for directional and spot lights, the lecture's
// two passes (Wolberg; Ganovelli et al. §8.2-8.4; Navarro Rosales), and cube maps for point lights (Lawonn).
// Shadow pass: the casters that can reach the light's frustum, drawn from
// the light camera (src/core/LightCamera) into one layer of a texture array
// shared by every light with the same format and size, colour writes off
// (or depth packed into RGBA8); a point light's six faces are six layers of
// a cube-map array, filled in one geometry-shader pass or six passes.
// Light pass: shaders/shadow_map.glsl compares the fragment's depth in the
// light's texture space with the map, filtered as the light asks.
// This file is the Technique; docs/architecture.md lists the module's other files.
#include "techniques/map/Map.h"

#include "techniques/map/Cache.h"
#include "techniques/map/Variants.h"
#include "techniques/map/atlas/Atlas.h"
#include "techniques/map/atlas/Images.h"
#include "techniques/map/debug/Images.h"
#include "techniques/map/fit/Cameras.h"
#include "techniques/map/fit/Region.h"
#include "techniques/map/fit/Sdsm.h"
#include "techniques/map/options/OptionTable.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/CasterDraw.h"
#include "techniques/map/passes/CubePass.h"
#include "techniques/map/passes/Pass2D.h"
#include "techniques/map/passes/Resources.h"
#include "techniques/map/passes/Targets.h"
#include "techniques/map/passes/Translucent.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

namespace shadowlab {

namespace {

using namespace shadowlab::map;

// Given cascade splits lie between the camera's near and far planes (a
// slice outside the view is a map spent on nothing). The scene file check
// (map::unsupported) sees the light alone; this one needs the camera.
void checkSplitsInView(const MapOptions& o, const Light& light, const Camera& camera, int index) {
    if (cascadeCount(light, o) <= 1) return;
    std::string problem;
    const std::vector<float> splits = parseSplits(o, problem);
    if (splits.empty()) return;
    const std::string at = "lights[" + std::to_string(index) + "].shadow.map.cascadeSplits: \"" + text::escapeControl(o.cascadeSplits) + "\": ";
    if (splits.front() <= camera.nearPlane)
        throw InputError(at + "the first split must lie beyond the camera's near plane (camera.near " + text::numberText(camera.nearPlane) + ")");
    if (splits.back() >= camera.farPlane) {
        // A split a hair under the far plane may round onto it as a 32-bit float.
        const bool rounded = splits.back() == camera.farPlane;
        throw InputError(at + "the last split must lie before the camera's far plane (camera.far " + text::numberText(camera.farPlane) + ")" +
                    (rounded ? "; as a 32-bit float it is " + text::numberText(splits.back()) : ""));
    }
}

class ShadowMap final : public Technique {
public:
    void prepare(TechniqueHost& host, const FrameInfo& frame, std::span<const int> lights) override {
        if (frame.reuseShadowMaps) {
            for (int index : lights)
                if (!lights_.contains(index))
                    throw Error("RenderOptions::reuseShadowMaps: light " + std::to_string(index) + " has no shadow map from the previous frame");
            return;  // the maps and their cameras as the previous frame left them
        }
        // Each light's options for the frame, worked out once (size 0: the
        // frame's); everything after reads these (MapLight::options).
        std::map<int, MapOptions> options;
        for (int index : lights) options.emplace(index, optionsHere(host, frame, frame.scene.lights[static_cast<std::size_t>(index)]));
        // The same inputs as the maps were drawn from: keep them (cacheShadowMaps).
        const std::uint64_t inputs = mapInputs(frame, options);
        cached_ = frame.cacheShadowMaps && drawnFrom_ && *drawnFrom_ == inputs && lights_.size() == lights.size();
        noteHardPcss(host, frame, options);
        if (cached_) return;
        // The maps are refitted now and hold these inputs once a shadow pass
        // draws them (a frame lit by the reference's visibility draws none).
        drawnFrom_.reset();
        preparedFor_ = inputs;
        res_.software = gl::isSoftwareRasterizer(host.glInfo().renderer);
        res_.samplers.create();
        const bool atlas = allocateArrays(host, frame, options);
        std::map<int, MapLight> perLight;
        std::map<std::size_t, int> nextLayer;
        for (const auto& [index, o] : options) perLight.emplace(index, lightFor(frame, index, o, nextLayer));
        lights_ = std::move(perLight);
        if (atlas) {
            std::map<int, MapLight*> inAtlas;
            for (auto& [index, p] : lights_)
                if (p.options.atlas) inAtlas.emplace(index, &p);
            atlas_.layout(host, frame, inAtlas);
        }
    }

    bool hasShadowPass(const Light&) const override { return true; }

    void renderShadowPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view) override {
        if (cached_) {
            host.count("cached", 1.0);  // the previous frame's map, its inputs unchanged
            return;
        }
        MapLight& p = lights_.at(view.index);
        const Light& light = frame.scene.lights[static_cast<std::size_t>(view.index)];
        if (usesSamples(p, light)) {
            // Fit "sdsm": refitted to what the camera sees, reduced from
            // this frame's depth pre-pass (MapSdsm), before its pass.
            const auto scope = host.timeScope("sdsm");
            {
                const auto pre = host.timeScope("prepass");
                samples_.prepass(host, frame);
            }
            // Fitted on the GPU, no read-back. The CPU's cameras, around
            // where the samples may lie, cull (one map: its fit to where
            // they may be; cascades: fitCullingCascades).
            GpuFit& fitted = gpuFits_[view.index];
            const bool cascades = cascadeCount(light, p.options) > 1;
            const float seenFar = cascades ? fitted.seenFar() : 0.0f;
            if (cascades) {
                fitCullingCascades(p, light, frame, seenFar);
            } else {
                const Bounds reach = sdsmReach(light, frame, frame.clipFromWorld);
                fitCameras(p, light, frame, &reach);
            }
            const auto reduction = host.timeScope("reduce");
            GpuFitInput input = gpuFitInput(p, light, frame);
            if (seenFar > 0.0f) input.splitRange = glm::vec2(seenFar);
            samples_.fitOnGpu(host, frame, input, fitted.buffer());
            if (cascades) fitted.readSeenFarLater();
            p.setGpuFit(&fitted.buffer());
        }
        if (p.options.atlas)
            atlas_.draw(host, frame, p, view.index);
        else if (p.cube())
            renderCubePass(host, frame, view, res_, p);
        else
            renderMapPass(host, frame, view, res_, p);
        // The maps hold this frame's inputs, unless the atlas's update budget left some behind.
        drawnFrom_ = atlas_.behind() ? std::optional<std::uint64_t>() : std::optional<std::uint64_t>(preparedFor_);
    }

    std::string lightPassDefines(const LightView& view) const override { return lightPassVariant(view).defines(); }

    gl::IncludeAliases lightPassIncludes(const LightView& view) const override { return {{"@map_filter", lightPassVariant(view).kernelFile()}}; }

    std::optional<std::vector<glm::ivec4>> shadowedPixels(const FrameInfo& frame, const LightView& view) const override {
        // A frame through the previous frame's maps keeps their cameras, not
        // necessarily what they were drawn from.
        const auto found = lights_.find(view.index);
        if (frame.reuseShadowMaps || found == lights_.end() || found->second.options.atlas) return std::nullopt;
        return map::shadowedPixels(found->second, view.light, frame, res_.arrays[found->second.array].size());
    }

    bool joinsLightList(const LightView& view) const override { return lights_.at(view.index).options.atlas; }

    glm::vec4 listedShadow(const LightView& view) const override { return MapAtlas::shadowOf(lights_.at(view.index)); }

    std::string listShadowFile() const override { return "shadow_atlas_list.glsl"; }

    void bindLightList(TechniqueHost&) override { atlas_.bind(); }

    void bindLightPass(TechniqueHost&, const FrameInfo&, const LightView& view) override {
        const MapLight& p = lights_.at(view.index);
        if (p.options.atlas) {
            res_.block.uploadAtlas(p, view.light);
            atlas_.bind();
            return;
        }
        const MapArray& g = res_.arrays[p.array];
        res_.block.upload(p, g, view.light, res_.translucent);
        map::bindLightPass(p, g, res_.samplers, res_.translucent, depthTaps(p.options, p.cube(), res_.software));
    }

    void debugImages(TechniqueHost& host, const FrameInfo& frame, const LightView& view, const DebugImageKinds& kinds,
                     std::vector<DebugImage>& out) override {
        if (lights_.at(view.index).options.atlas) {
            // The atlas itself, once: with the first of its lights; the
            // light's own tiles are its shadow map.
            std::map<int, const MapLight*> inAtlas;
            for (const auto& [index, p] : lights_)
                if (p.options.atlas) inAtlas.emplace(index, &p);
            if (kinds.wants(DebugImageKind::Atlas) && inAtlas.begin()->first == view.index) out.push_back(atlasImage(atlas_, inAtlas));
            if (!kinds.wants(DebugImageKind::ShadowMap)) return;
            DebugImage tiles = atlasLightTiles(atlas_, lights_.at(view.index));
            if (!tiles.image.pixels.empty()) out.push_back(std::move(tiles));
            return;
        }
        map::debugImages(host, frame, view, res_, lights_.at(view.index), kinds, out);
    }

    void lightFrustums(const LightView& view, std::vector<glm::mat4>& out) const override {
        const auto found = lights_.find(view.index);
        if (found == lights_.end()) return;
        const MapLight& p = found->second;
        if (p.cube())
            out.insert(out.end(), p.cubeCamera().faceClipFromWorld.begin(), p.cubeCamera().faceClipFromWorld.end());
        else if (p.gpuFit())
            for (const glm::mat4& clip : readFittedClips(*p.gpuFit(), p.cascadeCount())) out.push_back(clip);  // the cameras the GPU fitted
        else
            for (const LightCamera& camera : p.cameras()) out.push_back(camera.clipFromWorld());
    }

private:
    // PCSS on a light of size 0 stays hard: said every frame, kept maps or not.
    static void noteHardPcss(TechniqueHost& host, const FrameInfo& frame, const std::map<int, MapOptions>& options) {
        for (const auto& [index, o] : options) {
            const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
            if (o.filter == MapFilter::Pcss && !(light.size > 0.0f))
                host.note("lights[" + std::to_string(index) + "].shadow.map.filter \"pcss\": the light's size is 0, so its shadows stay hard (set lights[" +
                          std::to_string(index) + "].size: a radius, or a directional light's angular diameter in degrees)");
        }
    }

    // The texture arrays for the lights' maps (lights with the same format
    // and size share one; those with `atlas` share the shadow atlas
    // instead), with transmittance layers when the frame has translucent
    // casters (alphaMode blend: they colour the light). Whether any light
    // is in the atlas.
    bool allocateArrays(TechniqueHost& host, const FrameInfo& frame, const std::map<int, MapOptions>& options) {
        std::map<ArrayKey, int> layersWanted, firstLightOf;
        bool atlas = false;
        for (const auto& [index, o] : options) {
            const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
            if (o.atlas) {
                atlas = true;
                continue;
            }
            const int limit = host.glInfo().maxTextureSize;
            if (o.size > limit)
                throw InputError("lights[" + std::to_string(index) + "].shadow.map.size: " + std::to_string(o.size) +
                            " texels is past this GPU's limit of " + std::to_string(limit));
            const bool cube = isCube(o, light);
            const ArrayKey key = ArrayKey::of(o, cube);
            layersWanted[key] += cube ? 1 : cascadeCount(light, o);
            firstLightOf.emplace(key, index);
        }
        res_.translucent = hasTranslucentCasters(frame);
        res_.holes = hasCastersWithHoles(frame);
        res_.arrays.allocate(layersWanted, firstLightOf, host.glInfo(), options.size(), res_.translucent,
                             atlas ? MapAtlas::bytesFor(frame.scene.shadowAtlas) : 0.0);
        if (res_.translucent) res_.arrays.addTransmittance();
        return atlas;
    }

    // Light `index`'s state for this frame: its options, its layers of its
    // array (nextLayer: each array's next free layer), its cameras fitted,
    // what it keeps of last frame's, its framebuffers. An atlas light gets
    // its cameras here and its tiles with the others' (MapAtlas::layout).
    MapLight lightFor(const FrameInfo& frame, int index, const MapOptions& o, std::map<std::size_t, int>& nextLayer) {
        const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
        MapLight p;
        p.options = o;
        if (isCube(p.options, light))
            p.kind = CubeMap{};
        else if (cascadeCount(light, p.options) > 1)
            p.kind = CascadeSet{};
        else
            p.kind = FlatMap{.spot = light.type == LightType::Spot};
        if (p.options.atlas) {
            p.atlas.emplace();  // its tiles: Atlas::layout, with the others'
            fitCameras(p, light, frame);
            return p;
        }
        p.array = res_.arrays.indexOf(ArrayKey::of(p.options, p.cube()));
        p.layer = nextLayer[p.array];
        nextLayer[p.array] += p.cube() ? 1 : cascadeCount(light, p.options);
        checkSplitsInView(p.options, light, frame.scene.camera, index);
        fitCameras(p, light, frame);
        if (auto old = lights_.find(index); old != lights_.end()) {
            // Fit "sdsm" refits in the shadow pass (renderShadowPass).
            if (usesSamples(p, light) && old->second.cascadeCount() == p.cascadeCount()) p.keepCamerasOf(old->second);
            if (!usesSamples(p, light)) p.setGpuFit(nullptr);
            p.keepTargetsOf(old->second, !p.cube() || cubeWindowDepth(p.options) == cubeWindowDepth(old->second.options));
        }
        attachTargets(p, res_.arrays[p.array]);
        return p;
    }

    // The light pass's variant for a light this frame prepared.
    LightPassVariant lightPassVariant(const LightView& view) const {
        return LightPassVariant::of(lights_.at(view.index).options, view.light, res_.software, res_.translucent);
    }

    // The light's options for this frame: its own (the preset was applied
    // as the scene was read), with a size that follows the frame (size 0)
    // resolved.
    static MapOptions optionsHere(TechniqueHost& host, const FrameInfo& frame, const Light& light) {
        MapOptions o = light.shadow.get<MapOptions>();
        // size 0: the frame's (Wolberg's lecture: the window's own size;
        // otherwise frameMapSize's texels per pixel, over the part of the
        // map the view reads: fit "scene" widens it by sceneFitWidening,
        // in steps of 256 texels, up to kFrameMapMaximum).
        if (o.size == 0) {
            const int frameSide = frameMapSize(frame.viewport.x, frame.viewport.y);
            const float widened = static_cast<float>(frameSide) * sceneFitWidening(o, light, frame);
            const int side = widened > static_cast<float>(frameSide) ? std::min((static_cast<int>(std::ceil(widened)) + 255) / 256 * 256, kFrameMapMaximum) : frameSide;
            o.size = std::clamp(isLecture2D(o, light) ? std::max(frame.viewport.x, frame.viewport.y) : std::max(side, frameSide), 16,
                                host.glInfo().maxTextureSize);
        }
        return o;
    }

    MapResources res_;
    MapAtlas atlas_;        ///< the lights with `atlas`
    SampleBounds samples_;  ///< fit "sdsm": the depth pre-pass and its reduction
    std::map<int, GpuFit> gpuFits_;  ///< fit "sdsm" on the GPU: each light's fitted cameras (MapLight::gpuFit)
    std::map<int, MapLight> lights_;
    std::optional<std::uint64_t> drawnFrom_;  ///< mapInputs of the frame the maps were drawn in
    std::uint64_t preparedFor_ = 0;           ///< mapInputs of this frame's fit
    bool cached_ = false;                     ///< this frame keeps them
};

} // namespace

TechniqueEntry mapTechnique() {
    TechniqueEntry entry = entryOf<ShadowMap>("map", "shadow_map.glsl");
    entry.vertexShaderFile = "shadow_map_vertex.glsl";
    return entry;
}

} // namespace shadowlab
