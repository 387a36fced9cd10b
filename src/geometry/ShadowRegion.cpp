// Where on the screen a light's shadows can fall (ShadowRegion.h).
#include "geometry/ShadowRegion.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

namespace shadowlab {

namespace {

// Casters times receivers above which shadowRects gives up.
constexpr double kMostPairs = 1e6;

// A box in the light's clip space, divided: the points of the box past the
// near plane (perspective; the corners there and where the edges cross
// it), and their bounds.
struct LightImage {
    std::vector<glm::vec3> points;
    glm::vec2 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    float zLo = std::numeric_limits<float>::max(), zHi = -std::numeric_limits<float>::max();
    bool empty() const { return points.empty(); }
    bool overlaps(const LightImage& o) const { return !(o.lo.x > hi.x || o.hi.x < lo.x || o.lo.y > hi.y || o.hi.y < lo.y); }
};

LightImage imageOf(const Bounds& box, const glm::mat4& lightClip, bool perspective) {
    LightImage out;
    std::array<glm::vec4, 8> clip;
    for (int c = 0; c < 8; ++c)
        clip[static_cast<std::size_t>(c)] = lightClip * glm::vec4(box.corner(c), 1.0f);
    // Past the near plane: z >= -w (an orthographic light keeps all: its map clamps depth).
    auto past = [&](const glm::vec4& p) { return perspective ? p.z + p.w : 1.0f; };
    auto add = [&](const glm::vec4& p) {
        const glm::vec3 ndc = glm::vec3(p) / p.w;
        out.points.push_back(ndc);
        out.lo = glm::min(out.lo, glm::vec2(ndc));
        out.hi = glm::max(out.hi, glm::vec2(ndc));
        out.zLo = std::min(out.zLo, ndc.z);
        out.zHi = std::max(out.zHi, ndc.z);
    };
    for (const glm::vec4& p : clip)
        if (past(p) >= 0.0f && p.w > 0.0f) add(p);
    if (!perspective) return out;
    for (int c = 0; c < 8; ++c)
        for (int axis = 1; axis < 8; axis <<= 1) {
            if (c & axis) continue;  // each edge once, from its lower corner
            const glm::vec4 &a = clip[static_cast<std::size_t>(c)], &b = clip[static_cast<std::size_t>(c | axis)];
            const float ea = past(a), eb = past(b);
            if ((ea < 0.0f) == (eb < 0.0f)) continue;
            const glm::vec4 p = glm::mix(a, b, ea / (ea - eb));
            if (p.w > 0.0f) add(p);
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

// pixelsAround, out to whole 4x4 blocks (the rasteriser's).
PixelRect pixelsOf(glm::vec2 lo, glm::vec2 hi, glm::ivec2 viewport) {
    const PixelRect r = pixelsAround(lo, hi, viewport);
    auto down4 = [](int v) { return v / 4 * 4; };  // v >= 0
    auto up4 = [](int v) { return (v + 3) / 4 * 4; };
    return PixelRect(down4(r.x), down4(r.y), std::min(up4(r.z), viewport.x), std::min(up4(r.w), viewport.y));
}

} // namespace

float TapReach::at(float distance) const { return within(distance, distance); }

float TapReach::within(float nearest, float farthest) const {
    if (!(nearest > 0.0f) || !(farthest >= nearest)) return std::numeric_limits<float>::infinity();
    return angle + world / nearest + (pcssSize > 0.0f ? pcssSize * std::max(1.0f / pcssNearest - 1.0f / farthest, 0.0f) : 0.0f);
}

std::vector<Bounds> piecesSeenFrom(const Bounds& box, const glm::vec3& light, int most) {
    if (box.empty()) return {};
    const float step = 0.5f * box.distanceTo(light);
    glm::ivec3 n(1);
    for (int a = 0; a < 3; ++a)
        if (step > 0.0f) n[a] = static_cast<int>(std::clamp(std::ceil((box.hi[a] - box.lo[a]) / step), 1.0f, static_cast<float>(std::max(most, 1))));
    // Piece k's side along axis a runs from edge(a, k) to edge(a, k + 1): the same float on both sides of a cut.
    const auto edge = [&](int a, int k) { return k == n[a] ? box.hi[a] : box.lo[a] + static_cast<float>(k) * (box.hi[a] - box.lo[a]) / static_cast<float>(n[a]); };
    std::vector<Bounds> out;
    for (int x = 0; x < n.x; ++x)
        for (int y = 0; y < n.y; ++y)
            for (int z = 0; z < n.z; ++z) {
                Bounds piece;
                piece.lo = glm::vec3(edge(0, x), edge(1, y), edge(2, z));
                piece.hi = glm::vec3(edge(0, x + 1), edge(1, y + 1), edge(2, z + 1));
                out.push_back(piece);
            }
    return out;
}

std::optional<std::vector<PixelRect>> centralRects(const glm::vec3& light, const Bounds& box, const TapReach& reach, const RegionScene& scene) {
    const glm::vec3 centre = box.centre();
    const float radius = 0.5f * glm::length(box.size()), distance = glm::length(centre - light);
    std::vector<PixelRect> rects;
    for (std::size_t i = 0; i < scene.items.size(); ++i) {
        if (!scene.items[i].receivesShadows) continue;
        const Bounds& r = scene.itemBounds[i];
        const PixelRect own = screenRectOf(r, scene.cameraClipFromWorld, scene.viewport);
        if (isEmpty(own)) continue;
        PixelRect rect = own;
        if (scene.itemPlanes[i]) {
            // Rays from the light through the box's corners, each tilted by
            // the taps' reach on the receiver to the corners of an octagon
            // around the cone of that reach; where all meet the plane (t >
            // 0) they bound the shadow there, else it is not bounded by them.
            const glm::vec4 plane = *scene.itemPlanes[i];
            const glm::vec3 n(plane);
            const float height = glm::dot(n, light) + plane.w;
            // The hits' extent on the screen, and the farthest from the light.
            float farthestHit = 0.0f;
            const auto hits = [&](float angle) {
                const float tilt = std::tan(std::min(angle, 1.4f));
                farthestHit = 0.0f;
                std::optional<Extent> seen(std::in_place);
                for (int c = 0; c < 8 && seen; ++c) {
                    const glm::vec3 u = box.corner(c) - light;
                    const glm::vec3 e1 = glm::normalize(std::abs(u.y) < 0.9f * glm::length(u) ? glm::cross(u, glm::vec3(0.0f, 1.0f, 0.0f)) : glm::cross(u, glm::vec3(1.0f, 0.0f, 0.0f)));
                    const glm::vec3 e2 = glm::normalize(glm::cross(u, e1));
                    // An octagon around the cone's circle: its corners 1 / cos(22.5 degrees) out.
                    const float across = tilt * glm::length(u) * 1.0823922f;
                    for (int k = 0; k < (tilt > 0.0f ? 8 : 1) && seen; ++k) {
                        const float turn = 0.78539816f * static_cast<float>(k);
                        const glm::vec3 ray = tilt > 0.0f ? u + across * (std::cos(turn) * e1 + std::sin(turn) * e2) : u;
                        const float along = glm::dot(n, ray);
                        const float t = -height / along;
                        if (std::abs(along) > 1e-12f && t > 0.0f && std::isfinite(t)) {
                            const glm::vec3 hit = light + t * ray;
                            seen->add(hit, glm::mat4(1.0f), scene.cameraClipFromWorld);
                            farthestHit = std::max(farthestHit, glm::length(hit - light));
                        } else
                            seen.reset();
                    }
                }
                return seen;
            };
            // The reach grows with the receiver's distance (pcss's search
            // and penumbra), which is no more than that of the plane's
            // points within the greatest reach (when they are bounded) or
            // of its box's farthest corner.
            const float nearest = std::abs(height);
            float farthest = r.farthestFrom(light);
            if (reach.pcssSize > 0.0f)
                if (const std::optional<Extent> widest = hits(reach.within(nearest, std::numeric_limits<float>::infinity())); widest && !widest->behind)
                    farthest = std::min(farthest, std::max(farthestHit, nearest));
            if (const std::optional<Extent> seen = hits(reach.within(nearest, farthest))) {
                if (seen->behind) return std::nullopt;
                rect = intersection(own, pixelsOf(seen->lo, seen->hi, scene.viewport));
            }
        } else {
            // Its bounding sphere against the box's widened by the reach, as angles from the light.
            const glm::vec3 to = r.centre() - light;
            const float rr = 0.5f * glm::length(r.size()), d = glm::length(to);
            const float nearest = r.distanceTo(light);
            const bool around = d <= rr || distance <= radius || !(nearest > 0.0f);
            if (!around) {
                const float apart = std::acos(std::clamp(glm::dot(to / d, (centre - light) / distance), -1.0f, 1.0f));
                if (apart > std::asin(std::min(rr / d, 1.0f)) + std::asin(std::min(radius / distance, 1.0f)) + reach.within(nearest, r.farthestFrom(light))) continue;
            }
        }
        if (!isEmpty(rect)) rects.push_back(rect);
    }
    return rects;
}

namespace {

// A view from a point light at `light` around `box`: looking along the
// mean direction to the box's corners, with the field (square) that holds
// them all and the box's nearest depth along that axis. Nothing when the
// corners spread over more than 80 degrees from it, or the box reaches the
// light's side.
struct PointLightView {
    glm::mat4 viewFromWorld{1.0f};
    float fovY = 0.0f;         // radians
    float nearestDepth = 0.0f; // the box's, along the view's axis, scene units
};

std::optional<PointLightView> pointLightView(const glm::vec3& light, const Bounds& box) {
    std::array<glm::vec3, 8> towards;
    glm::vec3 sum(0.0f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 d = box.corner(c) - light;
        const float length = glm::length(d);
        if (!(length > 0.0f)) return std::nullopt;
        towards[static_cast<std::size_t>(c)] = d;
        sum += d / length;
    }
    if (!(glm::length(sum) > 1e-3f)) return std::nullopt;
    const glm::vec3 axis = glm::normalize(sum);
    float widest = 1.0f, nearest = std::numeric_limits<float>::max();
    for (const glm::vec3& d : towards) {
        widest = std::min(widest, glm::dot(axis, glm::normalize(d)));
        nearest = std::min(nearest, glm::dot(axis, d));
    }
    if (widest < std::cos(glm::radians(80.0f)) || !(nearest > 0.0f)) return std::nullopt;
    const glm::vec3 up = std::abs(axis.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    // The square field's half-angle holds the widest corner's (a little more for rounding).
    return PointLightView{glm::lookAt(light, light + axis, up), 2.0f * std::acos(widest) * 1.02f + 1e-3f, nearest};
}

} // namespace

std::optional<std::vector<PixelRect>> pointCasterRects(const glm::vec3& light, const Bounds& box, float widen, const TapReach& taps,
                                                       const std::function<float(float)>& nearPlaneFor, float farPlane, const RegionScene& scene) {
    Bounds widened = box;
    widened.lo -= widen;
    widened.hi += widen;
    const std::optional<PointLightView> v = pointLightView(light, widened);
    if (!v) return centralRects(light, box, taps, scene);  // too wide a caster for a perspective view: in the world
    const float nearPlane = nearPlaneFor(v->nearestDepth);
    if (!(nearPlane > 0.0f)) return std::nullopt;
    const glm::mat4 clip = glm::perspective(v->fovY, 1.0f, nearPlane, farPlane) * v->viewFromWorld;
    return shadowRects(clip, true, {widened}, 4.0f, scene, kMaxShadowRects);  // every receiver past the near plane counts
}

std::optional<std::vector<PixelRect>> shadowRects(const glm::mat4& lightClip, bool perspective, const std::vector<Bounds>& casters,
                                                  float depthSlack, const RegionScene& scene, std::size_t most) {
    const glm::mat4 worldFromLightClip = glm::inverse(lightClip);
    const glm::mat4 planeToLightClip = glm::transpose(worldFromLightClip);  // a plane (n, d) into the light's clip space
    // The receivers in the light's clip space, for how deep a caster's box
    // need reach: a planar one's plane, else its box.
    struct Receiver {
        LightImage image;
        std::optional<glm::vec4> plane;
        std::size_t item = 0;
    };
    std::vector<Receiver> receivers;
    for (std::size_t i = 0; i < scene.items.size(); ++i) {
        if (!scene.items[i].receivesShadows) continue;
        Receiver r{imageOf(scene.itemBounds[i], lightClip, perspective), std::nullopt, i};
        if (r.image.empty()) continue;  // before the light's near plane: its test finds it lit
        if (scene.itemPlanes[i]) {
            const glm::vec4 plane = planeToLightClip * *scene.itemPlanes[i];
            if (std::abs(plane.z) > 1e-6f) r.plane = plane;  // not along the light
        }
        receivers.push_back(std::move(r));
    }
    // Every caster against every receiver: past a million pairs (a frame's
    // worth of work on the CPU), the test everywhere.
    if (double(casters.size()) * double(receivers.size()) > kMostPairs) return std::nullopt;
    std::vector<PixelRect> rects;
    for (const Bounds& box : casters) {
        const LightImage caster = imageOf(box, lightClip, perspective);
        if (caster.empty() || caster.lo.x > 1.0f || caster.hi.x < -1.0f || caster.lo.y > 1.0f || caster.hi.y < -1.0f) continue;  // beside the light's view
        const float zNear = std::max(caster.zLo - depthSlack, -1.0f);
        for (const Receiver& r : receivers) {
            if (!caster.overlaps(r.image) || r.image.zHi < zNear) continue;
            Extent seen;
            if (r.plane) {
                // Its plane where the box's points, swept along the light, land.
                for (const glm::vec3& k : caster.points) {
                    const float z = -(r.plane->x * k.x + r.plane->y * k.y + r.plane->w) / r.plane->z;
                    seen.add(glm::vec3(k.x, k.y, std::clamp(z, std::max(k.z - depthSlack, -1.0f), 1.0f)), worldFromLightClip, scene.cameraClipFromWorld);
                }
            } else {
                // Its image's box cut to the caster's column past its nearest depth.
                const glm::vec2 lo = glm::max(r.image.lo, caster.lo), hi = glm::min(r.image.hi, caster.hi);
                const float zLo = std::max(r.image.zLo, zNear), zHi = std::min(r.image.zHi + 1e-3f, 1.0f);
                for (int c = 0; c < 8; ++c)
                    seen.add(glm::vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? zHi : zLo), worldFromLightClip, scene.cameraClipFromWorld);
            }
            if (seen.behind) return std::nullopt;
            PixelRect rect = pixelsOf(seen.lo, seen.hi, scene.viewport);
            // Within its own box too (tighter than its image's box, which a
            // box turned to the light's axes outgrows).
            if (!r.plane) rect = intersection(rect, screenRectOf(scene.itemBounds[r.item], scene.cameraClipFromWorld, scene.viewport));
            if (!isEmpty(rect)) rects.push_back(rect);
        }
    }
    return mergedRects(std::move(rects), most);
}

} // namespace shadowlab
