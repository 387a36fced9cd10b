// Technique "map": the screen rectangle a light's shadows can fall in (fit/Region.h).
#include "techniques/map/fit/Region.h"

#include "geometry/ShadowRegion.h"

#include "techniques/map/fit/Cameras.h"
#include "techniques/map/options/Filters.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/Translucent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace shadowlab::map {

namespace {

// Whether item i is drawn into the map of `camera` (MapPass2D, MapTranslucent).
bool drawnInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i) {
    if (!frame.items[i].castsShadows) return false;
    return translucentCaster(frame, i) ? castsInto(camera, frame, i, true) : castsInto(camera, frame, i, false);
}

} // namespace

std::optional<std::vector<PixelRect>> cubeShadowedPixels(const MapLight& p, const Light& light, const FrameInfo& frame, int size) {
    const MapOptions& o = p.options;
    if (o.atlas || o.representation != MapRepresentation::Depth) return std::nullopt;
    if (o.slopeBias < 0.0f || o.offsetUnits < 0.0f) return std::nullopt;  // stored depths nearer than the casters
    const glm::vec3 lamp = light.position;
    const float far = p.cubeCamera().farPlane, perDistance = 2.0f / static_cast<float>(size);
    const bool pcss = o.filter == MapFilter::Pcss;
    // The receivers: the nearest to the light, the farthest from the viewer
    // (a filter radius grows with it); every item: the farthest from the light.
    const glm::vec3 eye = glm::vec3(glm::inverse(frame.viewFromWorld)[3]);
    float nearestReceiver = std::numeric_limits<float>::max(), viewerFar = 0.0f, farthest = 0.0f;
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        const Bounds& box = frame.itemBounds[i];
        for (int c = 0; c < 8; ++c) {
            farthest = std::max(farthest, glm::length(box.corner(c) - lamp));
            if (frame.items[i].receivesShadows) viewerFar = std::max(viewerFar, glm::length(box.corner(c) - eye));
        }
        if (frame.items[i].receivesShadows) nearestReceiver = std::min(nearestReceiver, box.distanceTo(lamp));
    }
    // How far a receiver's taps reach across its ray: texels (a bilinear
    // footprint, the normal offset, two for rounding) as an angle, the
    // grid's, pcf20's and poisson's radius (world units at the receiver,
    // growing with the viewer's distance), and for pcss its blocker search
    // (the light's size over the receiver's distance at most) and its
    // filter (the size over the blockers' distance, no nearer than the
    // nearest caster) as angles.
    const float texelAngle = (1.5f + std::max(o.normalBias, 0.0f) + 2.0f) * perDistance;
    float angle = texelAngle;
    const bool radial = o.filter == MapFilter::Grid || o.filter == MapFilter::Pcf20 || o.filter == MapFilter::Poisson;
    const float reach = radial ? 1.7320508f * o.diskRadius * (1.0f + std::max(o.diskGrowth, 0.0f) * viewerFar / far) : 0.0f;
    if (pcss) {
        if (!(p.nearestCaster() > 0.0f) || !(nearestReceiver > 0.0f)) return std::nullopt;
        angle += light.size / std::min(p.nearestCaster(), nearestReceiver);
    }
    // How much nearer the light than a caster a receiver it shadows may be
    // (world units): the constant bias (the presets' in world units, else
    // in stored depth, distance / far) and the normal offset, a quarter
    // more; pcss, whose taps compare with the receiver's plane extended,
    // any distance.
    const float bias = usesPresetBias(o, true) ? std::abs(o.constantBias) : std::abs(o.constantBias) * far;
    const float slack = 1.25f * (bias + (std::max(o.normalBias, 0.0f) + 2.0f) * perDistance * far) + 1e-4f * far;
    const RegionScene scene{frame.items, frame.itemBounds, frame.itemPlanes, frame.clipFromWorld, frame.viewport};
    // Each caster's box widened by the taps' reach where it lies farthest;
    // too wide for a perspective view, its corners' rays tilted by the
    // reach at each receiver.
    const TapReach taps{texelAngle, reach, pcss ? light.size : 0.0f, pcss ? p.nearestCaster() : 1.0f};
    const auto nearPlaneFor = [&](float nearestDepth) {
        return pcss ? 0.5f * std::min(nearestDepth, nearestReceiver) : std::max(nearestDepth - slack, 1e-3f * nearestDepth);
    };
    std::vector<PixelRect> rects;
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        if (!frame.items[i].castsShadows || p.faceMask(i) == 0) continue;
        if (pcss) {
            // Its search and penumbra reach furthest on the receivers
            // farthest from the light: the caster in pieces, each with the
            // receivers its shadow may fall on (centralRects bounds their
            // distance), rays through their corners.
            for (const Bounds& piece : piecesSeenFrom(frame.itemBounds[i], lamp, 8)) {
                const auto some = centralRects(lamp, piece, taps, scene);
                if (!some) return std::nullopt;
                rects.insert(rects.end(), some->begin(), some->end());
            }
            continue;
        }
        const Bounds& box = frame.itemBounds[i];
        float boxFar = 0.0f;
        for (int c = 0; c < 8; ++c) boxFar = std::max(boxFar, glm::length(box.corner(c) - lamp));
        const auto some = pointCasterRects(lamp, box, angle * boxFar + reach, taps, nearPlaneFor, 1.01f * farthest + 1.0f, scene);
        if (!some) return std::nullopt;
        rects.insert(rects.end(), some->begin(), some->end());
    }
    return mergedRects(std::move(rects), kMaxShadowRects);
}

std::optional<std::vector<PixelRect>> shadowedPixels(const MapLight& p, const Light& light, const FrameInfo& frame, int size) {
    if (p.cube()) return cubeShadowedPixels(p, light, frame, size);
    const MapOptions& o = p.options;
    if (o.atlas || p.gpuFit()) return std::nullopt;
    if (o.outside == MapOutside::Repeat) return std::nullopt;  // shadows anywhere outside the map, by design
    if (o.representation != MapRepresentation::Depth || o.filter == MapFilter::Dither4) return std::nullopt;
    if (o.slopeBias < 0.0f || o.offsetUnits < 0.0f) return std::nullopt;  // stored depths nearer than the casters
    const RegionScene scene{frame.items, frame.itemBounds, frame.itemPlanes, frame.clipFromWorld, frame.viewport};
    // A pixel is shadowed only by the casters of the map it reads: each
    // cascade's (a slice's lookups, and the slice before's where it fades
    // into this one), so the rectangles of every cascade's casters together.
    std::vector<PixelRect> rects;
    for (const LightCamera& camera : p.cameras()) {
        if (camera.warped) return std::nullopt;
        // How far nearer the light than a caster a receiver it shadows may
        // be, in the light's clip depth (twice stored depth): a shadowed
        // receiver's compared depth lies past the caster's stored one, and its
        // own depth differs from that by the normal offset (up to normalBias
        // texels; perspective: its change of stored depth is largest at the
        // near plane) and the constant bias; biases that lower the compared
        // depth (the presets', the receiver plane's) only keep it nearer. A
        // quarter more for rounding.
        const float range = camera.farPlane - camera.nearPlane;
        const float offsetWorld = (std::max(o.normalBias, 0.0f) + 2.0f) * camera.texelSize;
        const float offsetStored = (camera.perspective ? camera.farPlane : 1.0f) * offsetWorld / range;
        // PCSS compares each tap with the receiver's plane extended to it, which
        // may pass a caster farther from the light than the receiver itself:
        // there the whole depth range counts.
        const float depthSlack = o.filter == MapFilter::Pcss ? 4.0f : 1.25f * 2.0f * (std::abs(o.constantBias) + offsetStored) + 1e-4f;
        // Each caster drawn into the map, its box widened by the margin (a
        // texel's world size where the box lies farthest, for a perspective light).
        const glm::vec3 axis = camera.axis();
        const glm::vec3 lightPosition = glm::vec3(glm::inverse(camera.viewFromWorld)[3]);
        std::vector<Bounds> casters;
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            if (!drawnInto(camera, frame, i)) continue;
            Bounds box = frame.itemBounds[i];
            float margin = marginTexels(o) * camera.texelSize;  // a shadowed receiver's image lies this near a caster's
            if (camera.perspective) {
                float farthest = camera.nearPlane;
                for (int c = 0; c < 8; ++c)
                    farthest = std::max(farthest, glm::dot(box.corner(c) - lightPosition, axis));
                margin *= farthest;
            }
            box.lo -= margin;
            box.hi += margin;
            casters.push_back(box);
        }
        const auto some = shadowRects(camera.clipFromWorld(), camera.perspective, casters, depthSlack, scene, kMaxShadowRects);
        if (!some) return std::nullopt;
        rects.insert(rects.end(), some->begin(), some->end());
    }
    return mergedRects(std::move(rects), kMaxShadowRects);
}

} // namespace shadowlab::map
