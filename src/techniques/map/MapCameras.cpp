// Technique "map": the lights' cameras and their casters (MapCameras.h).
#include "techniques/map/MapCameras.h"

#include "techniques/map/MapFilters.h"
#include "techniques/map/MapSettings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace shadowlab::map {

namespace {

// What core/LightCamera's fits take for `p`'s map this frame, with the
// samples a fit "sdsm" takes, if any.
FitInput fitInputOf(const MapLight& p, const FrameInfo& frame, const Bounds* samples = nullptr) {
    return FitInput{frame.itemBounds, frame.items,          frame.itemPlanes,
                    frame.itemConvex, frame.clipFromWorld, p.options.size,
                    footprint(p.options), filterInfo(p.options.filter).rawDepth, samples};
}

// The frame's width over its height.
float aspectOf(const FrameInfo& frame) { return static_cast<float>(frame.viewport.x) / static_cast<float>(std::max(frame.viewport.y, 1)); }

// A directional light's cascades: the view's depth split into slices
// (core/LightCamera: cascadeSplits, fitCascade), one camera each.
// Where stabilised slices end: the camera's far plane, or nearer where the
// whole scene ends: the distance from the eye to the farthest corner of the
// scene's box (the same whichever way the camera turns), rounded up to the
// next power of 2^(1/4), so that the slices stay put while the camera
// moves and change by whole steps, rarely. Ending at a far plane far past
// the scene (300 m over a 200 m ground) spread the first slice's texels so
// thin that a 3 cm slab's shadow nearly vanished.
float stableReach(const Camera& camera, const FitInput& in) {
    Bounds scene;
    for (const Bounds& b : in.itemBounds) scene.add(b);
    if (scene.empty()) return camera.farPlane;
    const glm::vec3 farthest = glm::max(glm::abs(scene.lo - camera.position), glm::abs(scene.hi - camera.position));
    const float reach = glm::length(farthest);
    if (!(reach > camera.nearPlane)) return camera.farPlane;
    const float stepped = std::exp2(std::ceil(4.0f * std::log2(reach)) / 4.0f);
    return std::clamp(stepped, camera.nearPlane * 2.0f, camera.farPlane);
}

// Fit "sdsm": the view depths the camera sees, [near, far] along its axis
// (reduced from its depth pre-pass), within the camera's planes.
// Stabilised, in whole steps of 2^(1/4) with headroom (near two steps
// below the nearest depth seen, far one past the farthest), kept from frame
// to frame (`kept`) while the depths seen stay inside it and it is at most
// four steps too wide at the near end and three at the far: the splits stay
// put as the camera moves (each change moves every slice's texel grid: a
// frame of flips), and follow a view that changes.
glm::vec2 sampledRange(const Camera& camera, glm::vec2 seen, bool stabilize, glm::vec2 kept) {
    float near = std::max(seen.x, camera.nearPlane), far = std::min(seen.y, camera.farPlane);
    if (stabilize) {
        const float step = std::exp2(0.25f);
        if (kept.y > kept.x && kept.x <= near && far <= kept.y && near <= kept.x * std::pow(step, 4.0f) &&
            kept.y <= far * std::pow(step, 3.0f))
            return kept;
        near = std::exp2((std::floor(4.0f * std::log2(near)) - 2.0f) / 4.0f);
        far = std::exp2((std::ceil(4.0f * std::log2(far)) + 1.0f) / 4.0f);
    }
    near = std::max(near, camera.nearPlane);
    far = std::clamp(far, near * 1.01f, camera.farPlane);
    return {near, far};
}

// The view a warped map is warped for: the frame's camera and warpNear.
LightWarp lightWarp(const FrameInfo& frame, const MapOptions& o) {
    const glm::mat4 worldFromView = glm::inverse(frame.viewFromWorld);
    return LightWarp{glm::vec3(worldFromView[3]), -glm::normalize(glm::vec3(worldFromView[2])), o.warpNear};
}

void fitCascades(MapLight& p, const Light& light, const FrameInfo& frame, const FitInput& in, const glm::vec2* seenDepths,
                 const std::vector<Bounds>* sliceSamples) {
    const Camera& camera = frame.scene.camera;
    const float aspect = aspectOf(frame);
    // Stabilised slices must not move with the camera: they end at a reach
    // that changes by steps (stableReach); tight ones at the farthest
    // receiver it sees; sdsm's over the depths the camera sees.
    const float near = camera.nearPlane;
    float far = p.options.stabilize ? stableReach(camera, in) : viewReach(camera, in);
    // Fit "sdsm": the slices end at the farthest depth seen (never past the
    // tight fit's end) and the first starts at the nearest one, but the
    // splits are placed from the camera's near plane, as the tight fit's:
    // placed from the nearest depth seen, the logarithmic scheme's splits
    // (near^(1 - i/N) far^(i/N)) all move out with it, and the near slices,
    // where a texel covers the most pixels, got fewer texels a metre than
    // the tight fit's (docs/techniques.md).
    float first = near;
    if (seenDepths) {
        p.sampledDepths = sampledRange(camera, *seenDepths, p.options.stabilize, p.sampledDepths);
        far = std::max(std::min(far, p.sampledDepths.y), near * 1.01f);
        first = p.sampledDepths.x;
    }
    std::string problem;  // checked when the scene was read (the registry's unsupported())
    const std::vector<float> given = parseSplits(p.options, problem);
    p.cascadeFar = cascadeSplits(near, far, p.options.cascades, p.options.cascadeLambda, given);
    if (!(first < p.cascadeFar.front())) first = near;  // nothing seen before the first split: the slice as the tight fit's
    p.cascades.clear();
    // A slice's lookups reach into the next cascade over its far blend
    // share: cascade c is read from slice c - 1's near end on (conservative).
    const LightWarp viewWarp = lightWarp(frame, p.options);
    for (std::size_t c = 0; c < p.cascadeFar.size(); ++c) {
        const float sliceNear = c == 0 ? first : p.cascadeFar[c - 1];
        // A warped slice's near plane stands for the slice's own near end at the least.
        LightWarp warp = viewWarp;
        warp.nearDistance = std::max(warp.nearDistance, sliceNear);
        // Not stabilised, sdsm: the slice's own samples instead of its receivers' boxes.
        FitInput sliceIn = in;
        if (sliceSamples && c < sliceSamples->size() && !p.options.stabilize) sliceIn.visibleSamples = &(*sliceSamples)[c];
        p.cascades.push_back(fitCascade(glm::normalize(light.direction), camera, aspect, sliceNear, p.cascadeFar[c], p.options.stabilize, sliceIn,
                                        c < 2 ? first : p.cascadeFar[c - 2], p.options.warp == MapWarp::Lispsm ? &warp : nullptr));
    }
    p.firstSliceNear = first;
    p.camera = p.cascades.front();
    const glm::mat4& v = frame.viewFromWorld;
    p.viewForward = -glm::vec3(v[0][2], v[1][2], v[2][2]);
}

// The map's fit option as core/LightCamera takes it.
LightFit lightFit(MapFit fit) { return fit == MapFit::Scene ? LightFit::Scene : LightFit::Tight; }

// Casters the fit found unable to shadow anything visible are skipped.
bool mayCast(const LightCamera& camera, std::size_t item) { return camera.casts.empty() || camera.casts[item] != 0; }

// Directional lights clamp depth, so only the four side planes cull.
bool mayIntersectSides(const glm::mat4& clipFromWorld, const Bounds& box) {
    glm::mat4 flattened = clipFromWorld;
    for (int c = 0; c < 4; ++c) flattened[c][2] = 0.0f;  // z' = 0: never beyond near or far
    return mayIntersect(flattened, box);
}

} // namespace

bool usesSamples(const MapLight& p, const Light& light) {
    return p.options.fit == MapFit::Sdsm && p.options.preset == MapPreset::Default && light.type == LightType::Directional;
}

glm::mat4 sdsmLightView(const Light& light, const FrameInfo& frame) {
    const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld};
    return directionalLightView(glm::normalize(light.direction), in);
}

bool fitsOnGpu(const MapLight& p, const Light& light) {
    if (!usesSamples(p, light)) return false;
    return cascadeCount(light, p.options) == 1 || (p.options.stabilize && p.options.warp == MapWarp::None);
}

void fitCullingCascades(MapLight& p, const Light& light, const FrameInfo& frame, float seenFar) {
    fitCameras(p, light, frame);  // the slices over the whole stabilised reach
    const FitInput in = fitInputOf(p, frame);
    const Camera& camera = frame.scene.camera;
    const float aspect = aspectOf(frame);
    const float near = camera.nearPlane;
    // The GPU splits over seenFar when it is known (its far end a frame
    // before), and its last slice ends anywhere up to the reach; not known,
    // over this frame's far end, anywhere up to the reach (the splits above).
    std::vector<float> ends = p.cascadeFar;
    if (seenFar > 0.0f) {
        std::string problem;  // checked when the scene was read
        ends = cascadeSplits(near, seenFar, p.options.cascades, p.options.cascadeLambda, parseSplits(p.options, problem));
        ends.back() = std::max(ends.back(), p.cascadeFar.back());
    }
    // A thousandth more at either end: the GPU's splits are the same sums in
    // other float arithmetic; the first slice and the second's lookups from
    // the near plane (they start at the nearest depth seen).
    const std::size_t n = ends.size();
    for (std::size_t c = 0; c < n; ++c) {
        const bool known = seenFar > 0.0f;
        const float sliceNear = known && c > 0 ? ends[c - 1] * 0.999f : near;
        const float readFrom = known && c > 1 ? ends[c - 2] * 0.999f : near;
        const float sliceFar = std::min(ends[c] * 1.001f, camera.farPlane);
        p.cascades[c] = fitCascade(glm::normalize(light.direction), camera, aspect, std::max(sliceNear, near), std::max(sliceFar, sliceNear * 1.001f), true,
                                   in, std::max(readFrom, near));
    }
    p.camera = p.cascades.front();
}

Bounds sdsmReach(const Light& light, const FrameInfo& frame) {
    const glm::mat4 view = sdsmLightView(light, frame);
    const Bounds frustum = frustumBounds(frame.clipFromWorld, view);
    Bounds seen;
    for (std::size_t i = 0; i < frame.items.size(); ++i)
        if (mayIntersect(frame.clipFromWorld, frame.itemBounds[i])) seen.add(frame.itemBounds[i].transformed(view));
    seen.lo = glm::max(seen.lo, frustum.lo);
    seen.hi = glm::min(seen.hi, frustum.hi);
    if (seen.empty()) return Bounds{};
    // The reduction's margin (MapSdsm), at least as wide as the points' own.
    const glm::vec3 margin(1e-4f * glm::length(seen.size()));
    seen.lo -= margin;
    seen.hi += margin;
    return seen;
}

GpuFitInput gpuFitInput(const MapLight& p, const Light& light, const FrameInfo& frame) {
    const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld};
    GpuFitInput g;
    g.samplesView = sdsmLightView(light, frame);
    g.lightView = g.samplesView;
    g.diagonal = sceneDiagonal(in);
    g.size = static_cast<float>(p.options.size);
    g.padding = footprint(p.options);
    g.cascades = cascadeCount(light, p.options);
    if (g.cascades == 1 && p.camera.warped) {
        // Warped (the light not along the view): the camera's turned view (fitDirectional), the warp's parameters.
        const LightWarp warp = lightWarp(frame, p.options);
        g.warped = true;
        g.lightView = p.camera.viewFromWorld;
        g.sinGamma = warpAxis(glm::normalize(light.direction), &warp)->sinGamma;
        g.warpNear = warp.nearDistance;
        g.eye = warp.eye;
        g.forward = warp.forward;
    }
    if (g.cascades == 1) {
        for (std::size_t i = 0; i < frame.items.size(); ++i)
            if (p.camera.casts.empty() ? frame.items[i].castsShadows : p.camera.casts[i] != 0) g.casters.push_back(frame.itemBounds[i].transformed(g.lightView));
        return g;
    }
    // Cascades: the view and the splits' settings (fitCascades, fitCascade).
    const Camera& camera = frame.scene.camera;
    for (const Bounds& b : frame.itemBounds) g.scene.add(b);
    const float aspect = aspectOf(frame);
    g.camera = glm::vec4(camera.nearPlane, camera.farPlane, std::tan(glm::radians(camera.fovYDeg) * 0.5f), aspect);
    g.eye = camera.position;
    g.forward = glm::normalize(camera.target - camera.position);
    const glm::mat4 view = camera.viewFromWorld();
    g.right = glm::vec3(view[0][0], view[1][0], view[2][0]);
    g.up = glm::vec3(view[0][1], view[1][1], view[2][1]);
    g.reach = stableReach(camera, in);
    g.lambda = p.options.cascadeLambda;
    std::string problem;  // checked when the scene was read
    g.given = parseSplits(p.options, problem);
    return g;
}

glm::vec2 sliceDistances(const MapLight& p, std::size_t c) {
    if (c == 0) return {p.firstSliceNear, p.cascadeFar[0]};
    // The slice before fades into this cascade over its far blend share
    // (shadow_map_shared.h cascadeBlend): those points read this map too.
    const float before = p.cascadeFar[c - 1], start = c > 1 ? p.cascadeFar[c - 2] : 0.0f;
    return {std::max(before - p.options.cascadeBlend * (before - start), p.firstSliceNear), p.cascadeFar[c]};
}

void fitCameras(MapLight& p, const Light& light, const FrameInfo& frame, const Bounds* samples, const glm::vec2* seenDepths,
                const std::vector<Bounds>* sliceSamples) {
    const FitInput in = fitInputOf(p, frame, samples);
    if (p.cube) {
        const auto [nearPlane, farPlane] = cubeNearFar(p.options);
        p.cubeCamera = fitCube(light, lightFit(p.options.fit), in, nearPlane, farPlane);
    }
    if (p.options.preset == MapPreset::LearnOpenGL && light.type == LightType::Directional)
        p.camera = learnOpenGlCamera(light, p.options.size);
    else if (light.type == LightType::Point && !p.cube)  // preset "lecture-000"
        p.camera = lecturePointCamera(light, p.options.size);
    else if (p.cube)
        ;  // the cube's cameras above
    else if (light.type == LightType::Spot)
        p.camera = fitSpot(light, lightFit(p.options.fit), in);
    else if (cascadeCount(light, p.options) > 1)
        fitCascades(p, light, frame, in, seenDepths, sliceSamples);
    else {
        const LightWarp warp = lightWarp(frame, p.options);
        p.camera = fitDirectional(glm::normalize(light.direction), lightFit(p.options.fit), in, p.options.warp == MapWarp::Lispsm ? &warp : nullptr);
    }
    // The presets' fixed cameras skip what shadows nothing too (a ground
    // plane under everything): their maps stay the peers', drawn with less.
    if (!p.cube && p.camera.casts.empty()) {
        p.camera.casts = castersThatMatter(towardsLight(light), p.camera.viewFromWorld, in);
    }
    p.nearestCaster = p.options.filter == MapFilter::Pcss && (p.cube || light.type == LightType::Spot) ? nearestCaster(p, light, frame) : 0.0f;
}

float nearestCaster(const MapLight& p, const Light& light, const FrameInfo& frame) {
    const glm::vec3 axis = p.camera.axis();  // a spot's
    float nearest = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        if (!frame.items[i].castsShadows) continue;
        const Bounds& box = frame.itemBounds[i];
        if (p.cube) {
            if (p.faceMask(i) == 0) continue;
            nearest = std::min(nearest, glm::length(glm::max(glm::max(box.lo - light.position, light.position - box.hi), glm::vec3(0.0f))));
        } else if (castsInto(p.camera, frame, i, false)) {
            // The box's least depth along the axis: per axis the side the axis leaves behind.
            const glm::vec3 corner = glm::mix(box.hi, box.lo, glm::vec3(glm::greaterThanEqual(axis, glm::vec3(0.0f))));
            nearest = std::min(nearest, glm::dot(corner - light.position, axis));
        }
    }
    if (!std::isfinite(nearest)) return 0.0f;
    // Nothing nearer than the camera's near plane is drawn.
    return std::max(nearest, p.cube ? p.cubeCamera.nearPlane : p.camera.nearPlane);
}

bool castsInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i, bool moments) {
    if (!moments && !mayCast(camera, i)) return false;
    const glm::mat4 lightClip = camera.clipFromWorld();
    return !camera.perspective ? mayIntersectSides(lightClip, frame.itemBounds[i]) : mayIntersect(lightClip, frame.itemBounds[i]);
}

TexelRect projectedRect(const glm::mat4& clipFromWorld, const Bounds& box, int size) {
    float lo[2] = {1.0f, 1.0f}, hi[2] = {-1.0f, -1.0f};
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
        const glm::vec4 clip = clipFromWorld * glm::vec4(corner, 1.0f);
        if (!(clip.w > 1e-6f)) return TexelRect::whole().clamped(size);
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], clip[a] / clip.w);
            hi[a] = std::max(hi[a], clip[a] / clip.w);
        }
    }
    auto texel = [&](float ndc) { return static_cast<int>(std::floor((ndc * 0.5f + 0.5f) * static_cast<float>(size))); };
    return TexelRect{texel(lo[0]) - 1, texel(lo[1]) - 1, texel(hi[0]) + 2, texel(hi[1]) + 2}.clamped(size);
}

} // namespace shadowlab::map
