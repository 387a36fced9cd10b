// Technique "map": the screen rectangle a light's shadows can fall in (MapRegion.h).
#include "techniques/map/MapRegion.h"

#include "core/ShadowRegion.h"

#include "techniques/map/MapCameras.h"
#include "techniques/map/MapFilters.h"
#include "techniques/map/MapTranslucent.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadowlab::map {

namespace {

// Texels around a caster's image that a shadowed receiver's own image may
// lie within: the filter's footprint (what it may read around the point),
// the normal offset's reach (normalBias texels at most), and two for the
// rounding of the box's corners and the rasteriser's coverage.
float marginTexels(const MapOptions& o) { return filterInfo(o.filter).footprint(o) + std::max(o.normalBias, 0.0f) + 2.0f; }

// Whether item i is drawn into the map of `camera` (MapPass2D, MapTranslucent).
bool drawnInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i) {
    if (!frame.items[i].castsShadows) return false;
    return translucentCaster(frame, i) ? castsInto(camera, frame, i, true) : castsInto(camera, frame, i, false);
}

} // namespace

std::optional<std::vector<PixelRect>> shadowedPixels(const MapLight& p, const FrameInfo& frame) {
    const MapOptions& o = p.options;
    if (p.cube || o.atlas || !p.cascades.empty() || p.gpuFit || p.camera.warped) return std::nullopt;
    if (o.representation != MapRepresentation::Depth || o.filter == MapFilter::Dither4) return std::nullopt;
    if (o.slopeBias < 0.0f || o.offsetUnits < 0.0f) return std::nullopt;  // stored depths nearer than the casters
    const LightCamera& camera = p.camera;
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
        float margin = marginTexels(o) * camera.texelSize;
        if (camera.perspective) {
            float farthest = camera.nearPlane;
            for (int c = 0; c < 8; ++c)
                farthest = std::max(farthest, glm::dot(glm::mix(box.lo, box.hi, glm::vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1)) - lightPosition, axis));
            margin *= farthest;
        }
        box.lo -= margin;
        box.hi += margin;
        casters.push_back(box);
    }
    const RegionScene scene{frame.items, frame.itemBounds, frame.itemPlanes, frame.clipFromWorld, frame.viewport};
    return shadowRects(camera.clipFromWorld(), camera.perspective, casters, depthSlack, scene, kMaxShadowRects);
}

} // namespace shadowlab::map
