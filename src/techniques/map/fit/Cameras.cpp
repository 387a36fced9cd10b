// Technique "map": the lights' cameras and their casters (fit/Cameras.h).
#include "techniques/map/fit/Cameras.h"

#include "geometry/Cascades.h"
#include "techniques/map/options/Filters.h"
#include "techniques/map/options/Settings.h"

#include <shadowlab/Error.h>

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
    const float reach = scene.farthestFrom(camera.position);
    if (!(reach > camera.nearPlane)) return camera.farPlane;
    const float stepped = std::exp2(std::ceil(4.0f * std::log2(reach)) / 4.0f);
    return std::clamp(stepped, camera.nearPlane * 2.0f, camera.farPlane);
}

// Where the slices start: the nearest receiver the view may see
// (viewNearest: its box), not the camera's near plane, so that the first
// slice holds receivers (a near plane of 0.05 m over receivers from 5.8 m
// on left slice 0 empty and the whole frame on slice 1's coarse texels);
// at most half the splits' far end. Stabilised: stepped down to a power
// of 2^(1/4), so that it stays put while the camera moves (as stableReach).
float cascadeStart(const Camera& camera, const FitInput& in, bool stabilize, float far) {
    float start = std::min(viewNearest(camera, in), 0.5f * far);
    if (stabilize && start > camera.nearPlane) start = std::exp2(std::floor(4.0f * std::log2(start)) / 4.0f);
    return std::max(start, camera.nearPlane);
}

// The view a warped map is warped for: the frame's camera and warpNear.
LightWarp lightWarp(const FrameInfo& frame, const MapOptions& o) {
    const glm::mat4 worldFromView = glm::inverse(frame.viewFromWorld);
    return LightWarp{glm::vec3(worldFromView[3]), -glm::normalize(glm::vec3(worldFromView[2])), o.warpNear};
}

void fitCascades(MapLight& p, const Light& light, const FrameInfo& frame, const FitInput& in) {
    const Camera& camera = frame.scene.camera;
    if (camera.orthoHeight > 0.0f) throw UnsupportedError("map: cascades split a perspective view; with camera.orthoHeight set use cascades 1");
    const float aspect = aspectOf(frame);
    // Stabilised slices must not move with the camera: they end at a reach
    // that changes by steps (stableReach); tight ones at the farthest
    // receiver it sees. (Fit "sdsm" splits over the depths the camera
    // sees, on the GPU: shadow_map_sdsm_cascades.comp.)
    const float far = p.options.stabilize ? stableReach(camera, in) : viewReach(camera, in);
    std::string problem;  // checked when the scene was read (the registry's unsupported())
    const std::vector<float> given = parseSplits(p.options, problem);
    const float near = cascadeStart(camera, in, p.options.stabilize, given.empty() ? far : given.front());
    CascadeSet& set = *p.cascadeSet();
    set.start = near;
    set.far = cascadeSplits(near, far, p.options.cascades, p.options.cascadeLambda, given);
    set.cameras.clear();
    // A slice's lookups reach into the next cascade over its far blend
    // share: cascade c is read from slice c - 1's near end on for its depth
    // range (conservative), and from where that share starts (the shader's
    // cascadeBlend: that share of the slice, at its far end, the slice
    // before it counted from 0), a thousandth nearer, for its casters.
    const LightWarp viewWarp = lightWarp(frame, p.options);
    for (std::size_t c = 0; c < set.far.size(); ++c) {
        const float sliceNear = c == 0 ? near : set.far[c - 1];
        const float blended = c == 0 ? near : sliceNear - std::max(p.options.cascadeBlend, 0.0f) * (sliceNear - (c < 2 ? 0.0f : set.far[c - 2]));
        // A warped slice's near plane stands for the slice's own near end at the least.
        LightWarp warp = viewWarp;
        warp.nearDistance = std::max(warp.nearDistance, sliceNear);
        set.cameras.push_back(fitCascade(glm::normalize(light.direction), camera, aspect, sliceNear, set.far[c], p.options.stabilize, in,
                                         c < 2 ? near : set.far[c - 2], p.options.warp == MapWarp::Lispsm ? &warp : nullptr,
                                         std::max(0.999f * blended, near)));
    }
    p.camera = set.cameras.front();
    const glm::mat4& v = frame.viewFromWorld;
    set.viewForward = -glm::vec3(v[0][2], v[1][2], v[2][2]);
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

float sceneFitWidening(const MapOptions& o, const Light& light, const FrameInfo& frame) {
    if (o.fit != MapFit::Scene || light.type != LightType::Directional || o.preset != MapPreset::Default || o.warp != MapWarp::None ||
        cascadeCount(light, o) > 1)
        return 1.0f;
    const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld};
    const glm::vec3 direction = glm::normalize(light.direction);
    const float scene = fitDirectional(direction, LightFit::Scene, in).texelSize;
    const float tight = fitDirectional(direction, LightFit::Tight, in).texelSize;
    return tight > 0.0f && scene > tight ? scene / tight : 1.0f;
}

glm::mat4 sdsmLightView(const Light& light, const FrameInfo& frame) {
    const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld};
    return directionalLightView(glm::normalize(light.direction), in);
}

void fitCullingCascades(MapLight& p, const Light& light, const FrameInfo& frame, float seenFar) {
    fitCameras(p, light, frame);  // the slices over the whole reach (stabilised: stableReach; else viewReach)
    const FitInput in = fitInputOf(p, frame);
    const Camera& camera = frame.scene.camera;
    const float aspect = aspectOf(frame);
    CascadeSet& set = *p.cascadeSet();
    const float near = set.start;  // fitCascades' (the GPU's camera.x: gpuFitInput)
    // The GPU splits over seenFar when it is known (its far end a frame
    // before), and its last slice ends anywhere up to the reach; not known,
    // over this frame's far end, anywhere up to the reach (the splits above).
    const bool known = seenFar > 0.0f;
    std::vector<float> ends = set.far;
    if (known) {
        std::string problem;  // checked when the scene was read
        ends = cascadeSplits(near, seenFar, p.options.cascades, p.options.cascadeLambda, parseSplits(p.options, problem));
        ends.back() = std::max(ends.back(), set.far.back());
    }
    // A thousandth more at either end: the GPU's splits are the same sums in
    // other float arithmetic; the first slice and the second's lookups from
    // the near plane (they start at the nearest depth seen).
    const std::size_t n = ends.size();
    const glm::vec3 direction = glm::normalize(light.direction);
    for (std::size_t c = 0; c < n; ++c) {
        const float sliceNear = known && c > 0 ? ends[c - 1] * 0.999f : near;
        const float readFrom = known && c > 1 ? ends[c - 2] * 0.999f : near;
        const float sliceFar = std::max(std::min(ends[c] * 1.001f, camera.farPlane), sliceNear * 1.001f);
        if (p.options.stabilize) {
            set.cameras[c] = fitCascade(direction, camera, aspect, std::max(sliceNear, near), sliceFar, true, in, std::max(readFrom, near));
            continue;
        }
        // Not stabilised: the GPU fits the slice to its samples, which lie
        // in the view between where its lookups start (the slice before's
        // blend share, after readFrom) and its far end. The camera over the
        // box of what may be seen there, padded by two texels more than the
        // filter's footprint (the GPU's box lies within it, so its texels
        // are no larger), culls; warped, the GPU's texels far from the view
        // may be larger than any box of the CPU's says, so only the casters
        // that matter for the slice cull.
        const glm::mat4 sliceClip = glm::perspective(glm::radians(camera.fovYDeg), aspect, std::max(readFrom, near), sliceFar) * camera.viewFromWorld();
        FitInput sliceIn = in;
        sliceIn.cameraClipFromWorld = sliceClip;
        // Warped: the GPU's view and warp (the block takes their flag and axes from it).
        LightWarp warp = lightWarp(frame, p.options);
        warp.nearDistance = std::max(warp.nearDistance, std::max(sliceNear, near));
        LightCamera cam = fitDirectional(direction, LightFit::Tight, sliceIn, p.options.warp == MapWarp::Lispsm ? &warp : nullptr);
        Bounds region = cam.warped ? Bounds{} : sdsmReach(light, frame, sliceClip);
        if (region.empty()) {
            region = Bounds{};
            for (const Bounds& b : frame.itemBounds) region.add(b.transformed(cam.viewFromWorld));
        }
        if (!region.empty()) {
            const float pad = std::max(region.hi.x - region.lo.x, region.hi.y - region.lo.y) * (in.paddingTexels + 2.0f) / static_cast<float>(std::max(in.size, 1));
            cam.clipFromView = glm::ortho(region.lo.x - pad, region.hi.x + pad, region.lo.y - pad, region.hi.y + pad, cam.nearPlane, cam.farPlane);
        }
        set.cameras[c] = cam;
    }
    p.camera = set.cameras.front();
}

Bounds sdsmReach(const Light& light, const FrameInfo& frame, const glm::mat4& clipFromWorld) {
    const glm::mat4 view = sdsmLightView(light, frame);
    const Bounds frustum = frustumBounds(clipFromWorld, view);
    Bounds seen;
    for (std::size_t i = 0; i < frame.items.size(); ++i)
        if (mayIntersect(clipFromWorld, frame.itemBounds[i])) seen.add(frame.itemBounds[i].transformed(view));
    seen = seen.cutTo(frustum);
    if (seen.empty()) return Bounds{};
    // The reduction's margin (MapSdsm), at least as wide as the points' own.
    const glm::vec3 margin(1e-4f * glm::length(seen.size()));
    seen.lo -= margin;
    seen.hi += margin;
    return seen;
}

namespace {

// Warped (the light not along the view: p.camera, one map's or cascade 0's,
// is): the camera's turned view (fitDirectional) and the warp's parameters.
void warpedBy(GpuFitInput& g, const MapLight& p, const Light& light, const FrameInfo& frame) {
    if (!p.camera.warped) return;
    const LightWarp warp = lightWarp(frame, p.options);
    g.warped = true;
    g.lightView = p.camera.viewFromWorld;
    g.sinGamma = warpAxis(glm::normalize(light.direction), &warp)->sinGamma;
    g.warpNear = warp.nearDistance;
    g.eye = warp.eye;
    g.forward = warp.forward;
}

} // namespace

GpuFitInput gpuFitInput(const MapLight& p, const Light& light, const FrameInfo& frame) {
    const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld};
    GpuFitInput g;
    g.samplesView = sdsmLightView(light, frame);
    g.lightView = g.samplesView;
    g.diagonal = sceneDiagonal(in);
    g.size = static_cast<float>(p.options.size);
    g.padding = footprint(p.options);
    g.cascades = cascadeCount(light, p.options);
    if (g.cascades == 1) {
        warpedBy(g, p, light, frame);
        for (std::size_t i = 0; i < frame.items.size(); ++i)
            if (p.camera.casts.empty() ? frame.items[i].castsShadows : p.camera.casts[i] != 0) g.casters.push_back(frame.itemBounds[i].transformed(g.lightView));
        return g;
    }
    // Cascades: the view and the splits' settings (fitCascades, fitCascade).
    const Camera& camera = frame.scene.camera;
    for (const Bounds& b : frame.itemBounds) g.scene.add(b);
    const float aspect = aspectOf(frame);
    g.reach = p.options.stabilize ? stableReach(camera, in) : viewReach(camera, in);
    // The splits start where the receivers in view may (cascadeStart), as the CPU's do.
    std::string problem;  // checked when the scene was read
    g.given = parseSplits(p.options, problem);
    g.camera = glm::vec4(cascadeStart(camera, in, p.options.stabilize, g.given.empty() ? g.reach : g.given.front()), camera.farPlane, std::tan(glm::radians(camera.fovYDeg) * 0.5f), aspect);
    g.eye = camera.position;
    g.forward = glm::normalize(camera.target - camera.position);
    const glm::mat4 view = camera.viewFromWorld();
    g.right = glm::vec3(view[0][0], view[1][0], view[2][0]);
    g.up = glm::vec3(view[0][1], view[1][1], view[2][1]);
    g.stabilize = p.options.stabilize;
    if (g.stabilize) g.receiversWindow = receiversWindow(in, g.lightView, g.size / std::max(g.size - 2.0f * g.padding, 1.0f));
    g.lambda = p.options.cascadeLambda;
    g.blend = p.options.cascadeBlend;
    if (g.stabilize) return g;
    // Not stabilised: each slice fitted as fitDirectional fits one map, in
    // the light's view (warped: the turned view of cascade 0's CPU camera,
    // the slices' alike), cut by the casters that matter for the whole view
    // (each slice's own are among them).
    warpedBy(g, p, light, frame);
    const std::vector<std::uint8_t> casts = castersThatMatter(towardsLight(light), g.lightView, fitInputOf(p, frame));
    for (std::size_t i = 0; i < frame.items.size(); ++i)
        if (casts[i] != 0) g.casters.push_back(frame.itemBounds[i].transformed(g.lightView));
    return g;
}

void fitCameras(MapLight& p, const Light& light, const FrameInfo& frame, const Bounds* samples) {
    const FitInput in = fitInputOf(p, frame, samples);
    if (p.cube()) {
        const auto [nearPlane, farPlane] = cubeNearFar(p.options);
        p.cubeMap().camera = fitCube(light, lightFit(p.options.fit), in, nearPlane, farPlane);
    }
    if (p.options.preset == MapPreset::LearnOpenGL && light.type == LightType::Directional)
        p.camera = learnOpenGlCamera(light, p.options.size);
    else if (light.type == LightType::Point && !p.cube())  // preset "lecture-000"
        p.camera = lecturePointCamera(light, p.options.size);
    else if (p.cube())
        ;  // the cube's cameras above
    else if (light.type == LightType::Spot)
        p.camera = fitSpot(light, lightFit(p.options.fit), in);
    else if (cascadeCount(light, p.options) > 1)
        fitCascades(p, light, frame, in);
    else {
        const LightWarp warp = lightWarp(frame, p.options);
        p.camera = fitDirectional(glm::normalize(light.direction), lightFit(p.options.fit), in, p.options.warp == MapWarp::Lispsm ? &warp : nullptr);
    }
    // The presets' fixed cameras skip what shadows nothing too (a ground
    // plane under everything): their maps stay the peers', drawn with less.
    if (!p.cube() && p.camera.casts.empty()) {
        p.camera.casts = castersThatMatter(towardsLight(light), p.camera.viewFromWorld, in);
    }
    const float nearest = p.options.filter == MapFilter::Pcss && (p.cube() || light.type == LightType::Spot) ? nearestCaster(p, light, frame) : 0.0f;
    if (FlatMap* flat = std::get_if<FlatMap>(&p.kind)) flat->nearestCaster = nearest;
    if (p.cube()) p.cubeMap().nearestCaster = nearest;
}

float nearestCaster(const MapLight& p, const Light& light, const FrameInfo& frame) {
    const glm::vec3 axis = p.camera.axis();  // a spot's
    float nearest = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        if (!frame.items[i].castsShadows) continue;
        const Bounds& box = frame.itemBounds[i];
        if (p.cube()) {
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
    return std::max(nearest, p.cube() ? p.cubeCamera().nearPlane : p.camera.nearPlane);
}

bool castsInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i, bool moments) {
    if (!moments && !mayCast(camera, i)) return false;
    const glm::mat4 lightClip = camera.clipFromWorld();
    return !camera.perspective ? mayIntersectSides(lightClip, frame.itemBounds[i]) : mayIntersect(lightClip, frame.itemBounds[i]);
}

std::optional<TexelRect> lookupTexels(const LightCamera& camera, const MapOptions& o, int size) {
    if (!camera.lookups || camera.perspective || camera.warped || o.preset != MapPreset::Default) return std::nullopt;
    if (camera.lookups->empty()) return TexelRect{};
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 clip = camera.clipFromView * glm::vec4(camera.lookups->corner(c), 1.0f);  // w = 1
        const glm::vec2 texel = (glm::vec2(clip) * 0.5f + 0.5f) * static_cast<float>(size);
        lo = glm::min(lo, texel);
        hi = glm::max(hi, texel);
    }
    if (!std::isfinite(lo.x + lo.y + hi.x + hi.y)) return std::nullopt;
    const float margin = marginTexels(o), n = static_cast<float>(size);
    const glm::vec2 first = glm::clamp(glm::floor(lo - margin), 0.0f, n), last = glm::clamp(glm::ceil(hi + margin), 0.0f, n);
    if (!(first.x < last.x && first.y < last.y)) return TexelRect{};  // the box lies off the map
    return TexelRect{static_cast<int>(first.x), static_cast<int>(first.y), static_cast<int>(last.x), static_cast<int>(last.y)};
}

std::optional<TexelRect> drawnTexels(const FrameInfo& frame, const MapArray& g, const MapLight& p, const LightCamera& camera) {
    if (!frame.shadowRegions || g.hasMoments() || g.mipmaps() || isPacked(g.format()) || p.gpuFit()) return std::nullopt;
    if (p.options.outside == MapOutside::Repeat) return std::nullopt;  // a lookup outside reads the map tiled: any texel
    return lookupTexels(camera, p.options, g.size());
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
    // A huge box (a plane of size 1e20) projects far past an int's range,
    // or to no number at all: the rectangle is the map's clamped to a
    // texel past its sides before the conversion (it was INT_MIN - 1).
    if (!std::isfinite(lo[0]) || !std::isfinite(lo[1]) || !std::isfinite(hi[0]) || !std::isfinite(hi[1])) return TexelRect::whole().clamped(size);
    auto texel = [&](float ndc) { return static_cast<int>(std::floor((std::clamp(ndc, -2.0f, 2.0f) * 0.5f + 0.5f) * static_cast<float>(size))); };
    return TexelRect{texel(lo[0]) - 1, texel(lo[1]) - 1, texel(hi[0]) + 2, texel(hi[1]) + 2}.clamped(size);
}

} // namespace shadowlab::map
