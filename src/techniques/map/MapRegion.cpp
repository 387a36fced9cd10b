// Technique "map": the screen rectangle a light's shadows can fall in (MapRegion.h).
#include "techniques/map/MapRegion.h"

#include "techniques/map/MapCameras.h"
#include "techniques/map/MapFilters.h"
#include "techniques/map/MapTranslucent.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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

// A box's image in the light's clip space: x, y and depth bounds; the
// whole space when a corner lies behind a perspective light.
struct LightImage {
    glm::vec2 lo{-1.0f}, hi{1.0f};
    float zLo = -1.0f, zHi = 1.0f;
    bool unbounded = true;
};

LightImage imageOf(const Bounds& box, const glm::mat4& lightClip) {
    LightImage out{glm::vec2(std::numeric_limits<float>::max()), glm::vec2(-std::numeric_limits<float>::max()),
                   std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(), false};
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
        const glm::vec4 clip = lightClip * glm::vec4(corner, 1.0f);
        if (!(clip.w > 1e-6f)) return LightImage{};
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        out.lo = glm::min(out.lo, glm::vec2(ndc));
        out.hi = glm::max(out.hi, glm::vec2(ndc));
        out.zLo = std::min(out.zLo, ndc.z);
        out.zHi = std::max(out.zHi, ndc.z);
    }
    return out;
}

// The pixels of points in the light's clip space (through the world),
// and whether one lies behind the viewer (then they bound nothing).
struct Extent {
    glm::vec2 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    bool behind = false;
    void add(const glm::vec3& ndc, const glm::mat4& worldFromLight, const glm::mat4& clipFromWorld) {
        const glm::vec4 world = worldFromLight * glm::vec4(ndc, 1.0f);
        const glm::vec4 seen = clipFromWorld * glm::vec4(glm::vec3(world) / world.w, 1.0f);
        if (!(seen.w > 1e-6f)) behind = true;
        lo = glm::min(lo, glm::vec2(seen) / seen.w);
        hi = glm::max(hi, glm::vec2(seen) / seen.w);
    }
};

// The pixels around clip-space points from `lo` to `hi`: a pixel wider
// for rounding, out to whole 4x4 blocks (the rasteriser's), in the frame.
PixelRect pixelsOf(glm::vec2 lo, glm::vec2 hi, glm::ivec2 viewport) {
    const glm::vec2 size(viewport);
    const glm::vec2 pixelLo = glm::clamp(glm::floor((lo * 0.5f + 0.5f) * size) - 1.0f, glm::vec2(0.0f), size);
    const glm::vec2 pixelHi = glm::clamp(glm::ceil((hi * 0.5f + 0.5f) * size) + 1.0f, glm::vec2(0.0f), size);
    auto down4 = [](float v) { return static_cast<int>(std::floor(v / 4.0f)) * 4; };
    auto up4 = [](float v) { return static_cast<int>(std::ceil(v / 4.0f)) * 4; };
    return PixelRect(down4(pixelLo.x), down4(pixelLo.y), std::min(up4(pixelHi.x), viewport.x), std::min(up4(pixelHi.y), viewport.y));
}

} // namespace

std::optional<std::vector<PixelRect>> shadowedPixels(const MapLight& p, const FrameInfo& frame) {
    const MapOptions& o = p.options;
    if (p.cube || o.atlas || !p.cascades.empty() || p.gpuFit || p.camera.warped) return std::nullopt;
    if (o.representation != MapRepresentation::Depth || o.filter == MapFilter::Dither4) return std::nullopt;
    if (o.slopeBias < 0.0f || o.offsetUnits < 0.0f) return std::nullopt;  // stored depths nearer than the casters
    const LightCamera& camera = p.camera;
    const glm::mat4 lightClip = camera.clipFromWorld();
    const glm::mat4 worldFromLightClip = glm::inverse(lightClip);
    const glm::mat4 planeToLightClip = glm::transpose(worldFromLightClip);  // a plane (n, d) into the light's clip space
    // The receivers in the light's clip space, for how deep a caster's box
    // need reach: a planar one's plane, else its box's farthest depth.
    struct Receiver {
        LightImage image;
        std::optional<glm::vec4> plane;
        std::size_t item = 0;
    };
    std::vector<Receiver> receivers;
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        if (!frame.items[i].receivesShadows) continue;
        Receiver r{imageOf(frame.itemBounds[i], lightClip), std::nullopt, i};
        if (frame.itemPlanes[i] && !r.image.unbounded) r.plane = planeToLightClip * *frame.itemPlanes[i];
        receivers.push_back(r);
    }
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
    const float depthSlack = 1.25f * 2.0f * (std::abs(o.constantBias) + offsetStored) + 1e-4f;
    const glm::vec3 axis = camera.axis();
    const glm::vec3 lightPosition = glm::vec3(glm::inverse(camera.viewFromWorld)[3]);
    std::vector<PixelRect> rects;
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        if (!drawnInto(camera, frame, i)) continue;
        glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        // The box widened by the margin (a texel's world size where the
        // box lies farthest, for a perspective light), and its image.
        Bounds box = frame.itemBounds[i];
        float texels = marginTexels(o) * camera.texelSize;
        if (camera.perspective) {
            float farthest = camera.nearPlane;
            for (int c = 0; c < 8; ++c)
                farthest = std::max(farthest, glm::dot(glm::mix(box.lo, box.hi, glm::vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1)) - lightPosition, axis));
            texels *= farthest;
        }
        box.lo -= texels;
        box.hi += texels;
        const LightImage caster = imageOf(box, lightClip);
        if (caster.unbounded) return std::nullopt;  // reaches behind the light
        if (caster.lo.x > 1.0f || caster.hi.x < -1.0f || caster.lo.y > 1.0f || caster.hi.y < -1.0f) continue;  // beside the map
        // The receivers under the box's image, each shadowed only where
        // that image falls on it, past the box's nearest depth less the
        // slack: a planar one (not along the light) on its plane, at the
        // box's corners swept away from the light onto it; any other within
        // its own image's box in the light's clip space, cut to the box's.
        const float zNear = std::max(caster.zLo - depthSlack, -1.0f);
        for (const Receiver& r : receivers) {
            if (r.image.lo.x > caster.hi.x || r.image.hi.x < caster.lo.x || r.image.lo.y > caster.hi.y || r.image.hi.y < caster.lo.y) continue;
            if (r.image.zHi < zNear) continue;  // nearer the light than the box
            Extent seen;
            if (r.plane && std::abs(r.plane->z) > 1e-6f) {
                for (int c = 0; c < 8; ++c) {
                    const glm::vec4 clip = lightClip * glm::vec4((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z, 1.0f);
                    const glm::vec3 k = glm::vec3(clip) / clip.w;
                    const float z = -(r.plane->x * k.x + r.plane->y * k.y + r.plane->w) / r.plane->z;
                    seen.add(glm::vec3(k.x, k.y, std::clamp(z, std::max(k.z - depthSlack, -1.0f), 1.0f)), worldFromLightClip, frame.clipFromWorld);
                }
            } else {
                const glm::vec2 lo = glm::max(r.image.lo, caster.lo), hi = glm::min(r.image.hi, caster.hi);
                const float zLo = std::max(r.image.zLo, zNear), zHi = std::min(r.image.zHi + 1e-3f, 1.0f);
                for (int c = 0; c < 8; ++c)
                    seen.add(glm::vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? zHi : zLo), worldFromLightClip, frame.clipFromWorld);
            }
            if (seen.behind) return std::nullopt;
            PixelRect rect = pixelsOf(seen.lo, seen.hi, frame.viewport);
            // Within its own box too (tighter than its image's box, which a
            // box turned to the light's axes outgrows).
            if (!r.plane) rect = intersection(rect, screenRectOf(frame.itemBounds[r.item], frame.clipFromWorld, frame.viewport));
            rects.push_back(rect);
        }
    }
    std::erase_if(rects, [](const PixelRect& r) { return isEmpty(r); });
    return mergedRects(std::move(rects), kMaxRects);
}

} // namespace shadowlab::map
