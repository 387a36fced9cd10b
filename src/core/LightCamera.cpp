#include "core/LightCamera.h"

#include "core/Plane.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace shadowlab {

namespace {

// False when every point lies beyond one of the clip volume's six planes:
// then so does their convex hull.
bool hullMayIntersect(const glm::mat4& clipFromWorld, std::span<const glm::vec3> points) {
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (const glm::vec3& point : points) {
        const glm::vec4 p = clipFromWorld * glm::vec4(point, 1.0f);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.z < -p.w;
        outside[5] += p.z > p.w;
    }
    for (int plane = 0; plane < 6; ++plane)
        if (outside[plane] == static_cast<int>(points.size())) return false;
    return true;
}

} // namespace

bool mayIntersect(const glm::mat4& clipFromWorld, const Bounds& box) {
    if (box.empty()) return false;
    glm::vec3 corners[8];
    for (int c = 0; c < 8; ++c) corners[c] = glm::vec3((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
    return hullMayIntersect(clipFromWorld, corners);
}

bool shadowMayReach(const Bounds& caster, const glm::vec3& direction, const Bounds& scene, float pad, bool bothWays,
                    const glm::mat4& clipFromWorld) {
    if (caster.empty() || scene.empty()) return !caster.empty();
    const glm::vec3 l = glm::normalize(direction);
    const glm::vec3 lo = caster.lo - glm::vec3(pad), hi = caster.hi + glm::vec3(pad);
    const glm::vec3 sceneLo = glm::min(scene.lo, lo), sceneHi = glm::max(scene.hi, hi);
    // How far along l (and -l) a corner may go before it leaves the scene's
    // box: the farthest over the corners, so the hull holds every sweep.
    const auto exit = [&](const glm::vec3& p, const glm::vec3& d) {
        float t = std::numeric_limits<float>::max();
        for (int a = 0; a < 3; ++a) {
            if (d[a] > 0.0f) t = std::min(t, (sceneHi[a] - p[a]) / d[a]);
            else if (d[a] < 0.0f) t = std::min(t, (sceneLo[a] - p[a]) / d[a]);
        }
        return std::max(t, 0.0f);
    };
    glm::vec3 corners[8];
    float forward = 0.0f, backward = 0.0f;
    for (int c = 0; c < 8; ++c) {
        corners[c] = glm::vec3((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        forward = std::max(forward, exit(corners[c], l));
        if (bothWays) backward = std::max(backward, exit(corners[c], -l));
    }
    // The hull's vertices: each corner swept both ways (the box lies between).
    glm::vec3 swept[16];
    for (int c = 0; c < 8; ++c) {
        swept[2 * c] = corners[c] - backward * l;
        swept[2 * c + 1] = corners[c] + forward * l;
    }
    return hullMayIntersect(clipFromWorld, swept);
}

namespace {

Bounds all(const FitInput& in) {
    Bounds b;
    for (const Bounds& item : in.itemBounds) b.add(item);
    return b;
}

// Bounds (in `to` space) of the receivers the camera may see.
Bounds visibleReceivers(const FitInput& in, const glm::mat4& to) {
    Bounds b;
    for (std::size_t i = 0; i < in.items.size(); ++i)
        if (in.items[i].receivesShadows && mayIntersect(in.cameraClipFromWorld, in.itemBounds[i]))
            b.add(in.itemBounds[i].transformed(to));
    return b;
}

} // namespace

Bounds frustumBounds(const glm::mat4& cameraClipFromWorld, const glm::mat4& to) {
    const glm::mat4 worldFromClip = glm::inverse(cameraClipFromWorld);
    Bounds b;
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 ndc((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : -1.0f, 1.0f);
        const glm::vec4 w = worldFromClip * ndc;
        b.add(glm::vec3(to * glm::vec4(glm::vec3(w) / w.w, 1.0f)));
    }
    return b;
}

glm::vec4 towardsLight(const Light& light) {
    return light.type == LightType::Directional ? glm::vec4(-glm::normalize(light.direction), 0.0f) : glm::vec4(light.position, 1.0f);
}

std::vector<std::uint8_t> castersThatMatter(const glm::vec4& towardsLight, const glm::mat4& lightView, const FitInput& in) {
    std::vector<std::size_t> receivers;
    for (std::size_t i = 0; i < in.items.size(); ++i)
        if (in.items[i].receivesShadows && mayIntersect(in.cameraClipFromWorld, in.itemBounds[i])) receivers.push_back(i);
    const float margin = 1e-5f * std::max(glm::length(all(in).size()), 1e-3f);
    const bool directional = towardsLight.w == 0.0f;
    std::vector<std::uint8_t> out(in.items.size(), 0);
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (!in.items[i].castsShadows) continue;
        const std::optional<glm::vec4>& plane = i < in.itemPlanes.size() ? in.itemPlanes[i] : std::nullopt;
        const std::vector<glm::vec4>* convex = i < in.itemConvex.size() && !in.itemConvex[i].empty() ? &in.itemConvex[i] : nullptr;
        if (!directional && convex && strictlyInside(*convex, glm::vec3(towardsLight), margin)) {
            // From inside a convex mesh every point inside it is seen
            // directly: only receivers reaching outside can be shadowed.
            for (std::size_t r : receivers)
                if (r != i && !boxInside(*convex, in.itemBounds[r], margin)) {
                    out[i] = 1;
                    break;
                }
            continue;
        }
        if (!plane) {
            // Other casters: the fit's footprint and the light's frustum decide.
            out[i] = !receivers.empty();
            continue;
        }
        // A planar caster shadows neither itself nor anything on the light's
        // side of its plane; across a directional light it must also overlap.
        const Bounds caster = directional ? in.itemBounds[i].transformed(lightView) : Bounds{};
        for (std::size_t r : receivers) {
            if (r == i || !reachesBehind(*plane, towardsLight, in.itemBounds[r], margin)) continue;
            if (directional) {
                const Bounds b = in.itemBounds[r].transformed(lightView);
                if (caster.hi.x < b.lo.x || caster.lo.x > b.hi.x || caster.hi.y < b.lo.y || caster.lo.y > b.hi.y || caster.hi.z < b.lo.z) continue;
            }
            out[i] = 1;
            break;
        }
    }
    return out;
}

namespace {

// A directional light's camera before its box: looking along `direction`
// from the scene's centre moved back by its diagonal (every depth negative
// in view space; fixed while the scene is), with the casters that matter
// for what `in`'s camera sees.
float diagonalOf(const Bounds& scene) { return scene.empty() ? 1.0f : std::max(glm::length(scene.size()), 1e-3f); }

// `up`: the view's +y (a warp's axis); lightCameraUp's when not given.
glm::mat4 lightViewOf(const glm::vec3& direction, const Bounds& scene, float diagonal, const glm::vec3* up = nullptr) {
    const glm::vec3 centre = scene.empty() ? glm::vec3(0.0f) : scene.centre();
    return glm::lookAt(centre - direction * diagonal, centre, up ? *up : lightCameraUp(direction));
}

LightCamera directionalView(const glm::vec3& direction, const FitInput& in, const Bounds& scene, float diagonal, const glm::vec3* up = nullptr) {
    LightCamera cam;
    cam.viewFromWorld = lightViewOf(direction, scene, diagonal, up);
    cam.casts = castersThatMatter(glm::vec4(-direction, 0.0f), cam.viewFromWorld, in);
    return cam;
}

} // namespace

glm::mat4 directionalLightView(const glm::vec3& direction, const FitInput& in) {
    const Bounds scene = all(in);
    return lightViewOf(direction, scene, diagonalOf(scene));
}

float sceneDiagonal(const FitInput& in) { return diagonalOf(all(in)); }

namespace {

} // namespace

std::optional<WarpAxis> warpAxis(const glm::vec3& direction, const LightWarp* warp) {
    if (!warp) return std::nullopt;
    const glm::vec3 across = warp->forward - glm::dot(warp->forward, direction) * direction;
    const float sinGamma = glm::length(across);
    if (sinGamma < 0.02f) return std::nullopt;
    return WarpAxis{glm::normalize(across), sinGamma};
}

namespace {

// LiSPSM: `region` (light view space, the light looking down -z, the view's
// direction across the light along +y) seen through a perspective whose
// centre lies n below the region along y, so that texels shrink towards the
// camera; n from Wimmer et al.'s n_opt = (z0 + sqrt(z0 z1)) / sin(gamma), z0
// and z1 the nearest and farthest view distances of the region's corners
// (z0 at least the near distance), gamma the angle between view and light.
void warpRegion(LightCamera& cam, const Bounds& region, const LightWarp& warp, float sinGamma, const FitInput& in) {
    const glm::mat4 worldFromView = glm::inverse(cam.viewFromWorld);
    float z0 = std::numeric_limits<float>::max(), z1 = 0.0f;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 v((c & 1) ? region.hi.x : region.lo.x, (c & 2) ? region.hi.y : region.lo.y, (c & 4) ? region.hi.z : region.lo.z);
        const float distance = glm::dot(glm::vec3(worldFromView * glm::vec4(v, 1.0f)) - warp.eye, warp.forward);
        z0 = std::min(z0, distance);
        z1 = std::max(z1, distance);
    }
    z0 = std::max(z0, warp.nearDistance);
    z1 = std::max(z1, z0);
    const float depth = std::max(region.hi.y - region.lo.y, 1e-6f);
    const float n = std::max((z0 + std::sqrt(z0 * z1)) / sinGamma, 1e-3f * depth);
    const float f = n + depth;
    // The perspective along +y: x and z over t = y - (lo.y - n), t in [n, f] to y' in [-1, 1].
    const glm::vec3 centre(0.5f * (region.lo.x + region.hi.x), region.lo.y - n, 0.5f * (region.lo.z + region.hi.z));
    const float a = (f + n) / (f - n), b = -2.0f * n * f / (f - n);
    glm::mat4 perspective(0.0f);  // column-major: [col][row]
    perspective[0][0] = n;
    perspective[1][1] = a;
    perspective[3][1] = b;
    perspective[2][2] = n;
    perspective[1][3] = 1.0f;
    const glm::mat4 warped = perspective * glm::translate(glm::mat4(1.0f), -centre);
    Bounds box;
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 q = warped * glm::vec4((c & 1) ? region.hi.x : region.lo.x, (c & 2) ? region.hi.y : region.lo.y,
                                               (c & 4) ? region.hi.z : region.lo.z, 1.0f);
        box.add(glm::vec3(q) / q.w);
    }
    // Pad by the filter's footprint, in texels of the warped map.
    const glm::vec2 texel = glm::vec2(box.hi - box.lo) / static_cast<float>(std::max(in.size, 1));
    box.lo -= glm::vec3(texel * in.paddingTexels, 0.0f);
    box.hi += glm::vec3(texel * in.paddingTexels, 0.0f);
    const float zPad = 1e-4f * (box.hi.z - box.lo.z) + 1e-12f;
    box.lo.z -= zPad;
    box.hi.z += zPad;
    // To clip space: x, y across, z from the light (warped z grows towards it: the nearest at -1).
    glm::mat4 fit(1.0f);
    fit[0][0] = 2.0f / (box.hi.x - box.lo.x);
    fit[1][1] = 2.0f / (box.hi.y - box.lo.y);
    fit[2][2] = -2.0f / (box.hi.z - box.lo.z);
    fit[3] = glm::vec4(-(box.hi.x + box.lo.x) / (box.hi.x - box.lo.x), -(box.hi.y + box.lo.y) / (box.hi.y - box.lo.y),
                       (box.hi.z + box.lo.z) / (box.hi.z - box.lo.z), 1.0f);
    cam.clipFromView = fit * warped;
    // A texel's world size: across, (box width / size) t / n; along the
    // view, (box height / size) t^2 / |b| (y' = a + b / t).
    cam.warped = true;
    cam.warpU = texel.x / n;
    cam.warpV = texel.y / std::abs(b);
    const glm::vec4 rowY(cam.viewFromWorld[0][1], cam.viewFromWorld[1][1], cam.viewFromWorld[2][1], cam.viewFromWorld[3][1]);
    cam.warpPlane = glm::vec4(glm::vec3(rowY), rowY.w - centre.y);
    cam.texelSize = std::max(cam.warpU * n, cam.warpV * n * n);
}

} // namespace

LightCamera fitDirectional(const glm::vec3& direction, LightFit fit, const FitInput& in, const LightWarp* warp) {
    const Bounds scene = all(in);
    const float diagonal = diagonalOf(scene);
    const std::optional<WarpAxis> axis = fit == LightFit::Scene ? std::nullopt : warpAxis(direction, warp);
    // Warped: the light's view turned so that the view's direction across the light is +y.
    LightCamera cam = directionalView(direction, in, scene, diagonal, axis ? &axis->axis : nullptr);
    Bounds region; // light view space: x, y across the light, z = -distance from the eye
    if (fit == LightFit::Scene) {
        // The lecture's box: sides equal to the diagonal, centred on the scene.
        const float h = 0.5f * diagonal;
        region.add(glm::vec3(-h, -h, -diagonal - h));
        region.add(glm::vec3(h, h, -diagonal + h));
    } else {
        if (in.visibleSamples) {
            region = *in.visibleSamples;  // the receiver points the camera sees, reduced from its depth (SDSM)
            // Given in directionalLightView's space: a warp's turned view takes their box's corners.
            if (axis) region = region.transformed(cam.viewFromWorld * glm::inverse(lightViewOf(direction, scene, diagonal)));
        } else {
            // The receivers the camera may see, clipped to its frustum.
            const Bounds frustum = frustumBounds(in.cameraClipFromWorld, cam.viewFromWorld);
            region = visibleReceivers(in, cam.viewFromWorld);
            if (!region.empty()) region = region.cutTo(frustum);
        }
        if (region.empty()) {  // nothing visible receives: any small valid box
            region = Bounds{};
            region.add(glm::vec3(-1.0f, -1.0f, -diagonal - 1.0f));
            region.add(glm::vec3(1.0f, 1.0f, -diagonal + 1.0f));
        }
        // Only where a caster lies between the light and a receiver can a
        // shadow fall: the region shrinks to the casters' footprint over it
        // (receivers outside the map are lit, which is then exact), and the
        // casters over it raise its near side (towards the light).
        Bounds casters;
        for (std::size_t i = 0; i < in.items.size(); ++i) {
            if (!cam.casts[i]) continue;
            const Bounds c = in.itemBounds[i].transformed(cam.viewFromWorld);
            if (c.empty() || c.hi.x < region.lo.x || c.lo.x > region.hi.x || c.hi.y < region.lo.y || c.lo.y > region.hi.y) continue;
            casters.add(c);
        }
        if (!casters.empty()) {
            region.lo.x = std::max(region.lo.x, casters.lo.x);
            region.lo.y = std::max(region.lo.y, casters.lo.y);
            region.hi.x = std::min(region.hi.x, casters.hi.x);
            region.hi.y = std::min(region.hi.y, casters.hi.y);
            region.hi.z = std::max(region.hi.z, casters.hi.z);
        }
    }
    if (axis) {
        const float depthPad = 1e-3f * diagonal;
        cam.nearPlane = -region.hi.z - depthPad;
        cam.farPlane = -region.lo.z + depthPad;
        warpRegion(cam, region, *warp, axis->sinGamma, in);
        cam.perspective = false;
        return cam;
    }
    // Pad by the filter's footprint, in texels of the final size.
    const float extent = std::max(region.hi.x - region.lo.x, region.hi.y - region.lo.y);
    const float pad = extent * in.paddingTexels / static_cast<float>(std::max(in.size, 1));
    region.lo -= glm::vec3(pad, pad, 0.0f);
    region.hi += glm::vec3(pad, pad, 0.0f);
    const float depthPad = 1e-3f * diagonal;
    cam.nearPlane = -region.hi.z - depthPad;
    cam.farPlane = -region.lo.z + depthPad;
    cam.clipFromView = glm::ortho(region.lo.x, region.hi.x, region.lo.y, region.hi.y, cam.nearPlane, cam.farPlane);
    cam.texelSize = std::max(region.hi.x - region.lo.x, region.hi.y - region.lo.y) / static_cast<float>(std::max(in.size, 1));
    cam.perspective = false;
    return cam;
}

std::vector<float> cascadeSplits(float near, float far, int count, float lambda, const std::vector<float>& given) {
    std::vector<float> out;
    for (int i = 1; i < count; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(count);
        const float scheme = lambda * near * std::pow(far / near, t) + (1.0f - lambda) * (near + (far - near) * t);
        const float split = given.empty() ? scheme : given[static_cast<std::size_t>(i - 1)];
        // Increasing and inside (near, far), 10^-5 of the range left
        // for each slice: none is empty.
        const float step = 1e-5f * (far - near);
        const float lo = (out.empty() ? near : out.back()) + step;
        out.push_back(std::clamp(split, lo, std::max(lo, far - step * static_cast<float>(count - i))));
    }
    out.push_back(far);
    return out;
}

namespace {

// The view-space box around the boxes of the receivers that may be in view
// (viewReach, viewNearest); empty when none is.
Bounds receiversInView(const Camera& camera, const FitInput& in) {
    const glm::mat4 view = camera.viewFromWorld();
    Bounds out;
    for (std::size_t i = 0; i < in.items.size(); ++i)
        if (in.items[i].receivesShadows && mayIntersect(in.cameraClipFromWorld, in.itemBounds[i])) out.add(in.itemBounds[i].transformed(view));
    return out;
}

} // namespace

float viewReach(const Camera& camera, const FitInput& in) {
    const Bounds seen = receiversInView(camera, in);
    const float reach = seen.empty() ? camera.nearPlane : std::max(camera.nearPlane, -seen.lo.z);
    return std::clamp(reach, camera.nearPlane * 1.001f, camera.farPlane);
}

glm::vec4 receiversWindow(const FitInput& in, const glm::mat4& lightView, float grow) {
    Bounds receivers;
    for (std::size_t i = 0; i < in.items.size(); ++i)
        if (in.items[i].receivesShadows) receivers.add(in.itemBounds[i]);
    if (receivers.empty()) return glm::vec4(0.0f);
    // The casters that can shadow a receiver: not a plane with every
    // receiver on its lit side or in it (a ground under the scene).
    const glm::vec3 towards = glm::vec3(lightView[0][2], lightView[1][2], lightView[2][2]);  // the view's +z: towards the light
    Bounds casters;
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (!in.items[i].castsShadows) continue;
        if (i < in.itemPlanes.size() && in.itemPlanes[i]) {
            const glm::vec4 plane = *in.itemPlanes[i];
            const float lit = glm::dot(glm::vec3(plane), towards) >= 0.0f ? 1.0f : -1.0f;  // the sign of the lit side
            const float slack = 1e-4f * glm::length(receivers.size());
            bool shadowsNone = true;
            for (int c = 0; c < 8 && shadowsNone; ++c) shadowsNone = lit * (glm::dot(glm::vec3(plane), receivers.corner(c)) + plane.w) >= -slack;
            if (shadowsNone) continue;
        }
        casters.add(in.itemBounds[i]);
    }
    // Texels off every caster's footprint across the light are lit, and a
    // lookup past the window reads the lit border: the window need only
    // hold the receivers under the casters (a 1.5 m bunny on an 8 m
    // ground: the bunny's footprint).
    Bounds seen = receivers.transformed(lightView);
    if (casters.empty()) return glm::vec4(0.0f);
    const Bounds shadowing = casters.transformed(lightView);
    for (int a = 0; a < 2; ++a) {
        seen.lo[a] = std::max(seen.lo[a], shadowing.lo[a]);
        seen.hi[a] = std::min(seen.hi[a], shadowing.hi[a]);
        if (!(seen.lo[a] <= seen.hi[a])) return glm::vec4(0.0f);  // no caster over any receiver: the sphere's window
    }
    glm::vec4 out(0.0f);
    for (int a = 0; a < 2; ++a) {
        const float want = 0.5f * (seen.hi[a] - seen.lo[a]) * grow;
        out[a] = want > 0.0f ? std::exp2(std::ceil(8.0f * std::log2(want)) / 8.0f) : 0.0f;
        out[a + 2] = 0.5f * (seen.hi[a] + seen.lo[a]);
    }
    return out;
}

namespace {

// The nearest distance along a camera's axis (-z of `view`) of the part of
// world box `box` inside the pyramid |x| <= tanX (-z), |y| <= tanY (-z) of
// that view; infinity when none of it is inside. Exact: a vertex of the
// box cut by the pyramid is a vertex of a box face clipped by the
// pyramid's four sides (or the apex, inside the box).
float nearestInPyramid(const Bounds& box, const glm::mat4& view, float tanX, float tanY) {
    if (box.distanceTo(glm::vec3(glm::inverse(view)[3])) <= 0.0f) return 0.0f;  // the apex is inside
    std::array<glm::vec3, 8> corner;
    for (int c = 0; c < 8; ++c) corner[static_cast<std::size_t>(c)] = glm::vec3(view * glm::vec4(box.corner(c), 1.0f));
    static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    // Inside where side(p, k) <= 0: +-x or +-y against tanHalf (-z).
    const auto side = [tanX, tanY](const glm::vec3& p, int k) { return k < 2 ? (k == 0 ? p.x : -p.x) + tanX * p.z : (k == 2 ? p.y : -p.y) + tanY * p.z; };
    float nearest = std::numeric_limits<float>::infinity();
    std::vector<glm::vec3> polygon, clipped;
    for (const auto& face : kFaces) {
        polygon.assign({corner[static_cast<std::size_t>(face[0])], corner[static_cast<std::size_t>(face[1])], corner[static_cast<std::size_t>(face[2])],
                        corner[static_cast<std::size_t>(face[3])]});
        for (int k = 0; k < 4 && !polygon.empty(); ++k) {  // Sutherland-Hodgman against side k
            clipped.clear();
            for (std::size_t v = 0; v < polygon.size(); ++v) {
                const glm::vec3 &a = polygon[v], &b = polygon[(v + 1) % polygon.size()];
                const float fa = side(a, k), fb = side(b, k);
                if (fa <= 0.0f) clipped.push_back(a);
                if ((fa < 0.0f) != (fb < 0.0f) && fa != fb) clipped.push_back(a + (b - a) * (fa / (fa - fb)));
            }
            polygon.swap(clipped);
        }
        for (const glm::vec3& p : polygon)
            if (p.z < 0.0f) nearest = std::min(nearest, -p.z);
    }
    return nearest;
}

} // namespace

float viewNearest(const Camera& camera, const FitInput& in) {
    const Bounds seen = receiversInView(camera, in);
    const float nearest = seen.empty() ? camera.farPlane : std::min(camera.farPlane, -seen.hi.z);
    return std::clamp(nearest, camera.nearPlane, camera.farPlane);
}

namespace {

// A stabilised cascade's casters (its box holds the slice's whole sphere
// and the scene's depth, so the box's sides alone keep most of the scene):
// those whose box, in light view, overlaps across the light the box of the
// receivers seen in `reads` (the depth range whose lookups read this
// cascade), widened by `pad` (the filter's footprint), and is not wholly
// beyond it from the light (unless in.planeReachesBeyond). A caster
// outside cannot write a texel a lookup there reads, or only farther from
// the light than the receiver looking it up, where a comparison comes out
// the same with it or without it. Nor can one whose shadow misses the
// slice: the volume its shadow can fill (shadowMayReach) must cross the
// slice's frustum; the light-view box of a far slice holds the near ones.
std::vector<std::uint8_t> castersOverSlice(const LightCamera& cam, const glm::vec3& direction, const FitInput& reads, float pad) {
    std::vector<std::uint8_t> out(reads.items.size(), 0);  // cam.casts (castersThatMatter) and over the slice
    Bounds region = visibleReceivers(reads, cam.viewFromWorld);
    if (region.empty()) return out;
    const Bounds frustum = frustumBounds(reads.cameraClipFromWorld, cam.viewFromWorld);
    region.lo = glm::max(region.lo, frustum.lo) - glm::vec3(pad, pad, 0.0f);
    region.hi = glm::min(region.hi, frustum.hi) + glm::vec3(pad, pad, 0.0f);
    const Bounds scene = all(reads);
    for (std::size_t i = 0; i < reads.items.size(); ++i) {
        if (!reads.items[i].castsShadows || (!cam.casts.empty() && !cam.casts[i])) continue;
        const Bounds b = reads.itemBounds[i].transformed(cam.viewFromWorld);
        out[i] = b.hi.x >= region.lo.x && b.lo.x <= region.hi.x && b.hi.y >= region.lo.y && b.lo.y <= region.hi.y &&
                 (reads.planeReachesBeyond || b.hi.z >= region.lo.z) &&
                 shadowMayReach(reads.itemBounds[i], direction, scene, pad, reads.planeReachesBeyond, reads.cameraClipFromWorld);
    }
    return out;
}

} // namespace

LightCamera fitCascade(const glm::vec3& direction, const Camera& camera, float aspect, float near, float far, bool stabilize, const FitInput& in,
                       float readFrom, const LightWarp* warp, float castsFrom) {
    const float tanHalf = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    FitInput slice = in;
    slice.cameraClipFromWorld = glm::perspective(glm::radians(camera.fovYDeg), aspect, near, far) * camera.viewFromWorld();
    if (!stabilize) return fitDirectional(direction, LightFit::Tight, slice, warp);

    // A view of fixed orientation and origin: it moves with neither the camera nor the slice.
    const Bounds scene = all(in);
    const float diagonal = diagonalOf(scene);
    LightCamera cam = directionalView(direction, slice, scene, diagonal);
    // The slice's bounding sphere, centred on the view axis where the near
    // and far corners are equally far (k: a corner's distance from the axis
    // per unit of depth), radius rounded up to 1/64 of a unit: it depends
    // on the slice alone, not on where the camera is or turns.
    const float k2 = (1.0f + aspect * aspect) * tanHalf * tanHalf;
    const float along = std::min(0.5f * (far + near) * (1.0f + k2), far);
    float radius = std::sqrt((far - along) * (far - along) + k2 * far * far);
    radius = std::ceil(radius * 64.0f) / 64.0f;
    const glm::vec3 eye = camera.position, forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 sphere = glm::vec3(cam.viewFromWorld * glm::vec4(eye + forward * along, 1.0f));
    // The box: the sphere plus the filter's footprint, its centre on the texel grid.
    const float size = static_cast<float>(std::max(in.size, 1));
    const float grow = size / std::max(size - 2.0f * in.paddingTexels, 1.0f);
    const float half = radius * grow;
    // Per axis of the light's view, where every receiver's box (the scene's,
    // not the slice's: it does not move with the camera) is narrower than
    // the sphere, the window is that box instead, centred on it: a ground
    // under a low sun is a strip of the light's view a sixth as tall as
    // wide at 10 degrees, and a sphere's square gave its texels six times
    // the size along the light that the strip needs. Its half width rounded
    // up to a power of 2^(1/8), so that receivers that move change it by
    // steps, rarely; otherwise fixed as the camera moves, like the sphere's.
    const glm::vec4 window = receiversWindow(in, cam.viewFromWorld, grow);
    glm::vec2 halves(half), centre(sphere);
    for (int a = 0; a < 2; ++a)
        if (window[a] > 0.0f && window[a] < half) {
            halves[a] = window[a];
            centre[a] = window[a + 2];
        }
    const glm::vec2 texels = 2.0f * halves / size;
    const float texel = std::max(texels.x, texels.y);
    const glm::vec2 snapped = glm::floor(centre / texels + 0.5f) * texels;
    FitInput reads = in;
    const float from = readFrom > 0.0f ? std::min(readFrom, near) : near;
    reads.cameraClipFromWorld = glm::perspective(glm::radians(camera.fovYDeg), aspect, from, far) * camera.viewFromWorld();
    // Depth: the scene along the light, cut to what the slice's lookups
    // can reach (its frustum within the scene's box), so the map's depth
    // range is the slice's, not the whole scene's: moments leaked at
    // casters' feet wherever depths a few decimetres apart became too
    // close in a range of hundreds of metres. Casters nearer the light are
    // pancaked onto the near plane (depth clamp). The ends are rounded
    // out to 1/32 of the slice's box so that they move by steps, rarely.
    Bounds depth = scene.transformed(cam.viewFromWorld);
    if (!scene.empty()) {
        const Bounds world = frustumBounds(reads.cameraClipFromWorld, glm::mat4(1.0f)).cutTo(scene);
        const Bounds reach = world.transformed(cam.viewFromWorld);
        const float step = 0.0625f * half;
        if (!world.empty() && step > 0.0f) {
            depth.lo.z = std::max(depth.lo.z, std::floor(reach.lo.z / step) * step);
            depth.hi.z = std::min(depth.hi.z, std::ceil(reach.hi.z / step) * step);
        }
    }
    const float depthPad = 1e-3f * diagonal;
    cam.nearPlane = scene.empty() ? 0.0f : -depth.hi.z - depthPad;
    cam.farPlane = scene.empty() ? 2.0f * diagonal : -depth.lo.z + depthPad;
    cam.clipFromView = glm::ortho(snapped.x - halves.x, snapped.x + halves.x, snapped.y - halves.y, snapped.y + halves.y, cam.nearPlane, cam.farPlane);
    cam.texelSize = texel;
    cam.texelAxes = texels;
    cam.perspective = false;
    // The casters: over where the lookups of this cascade start, which may lie past readFrom.
    FitInput looked = reads;
    if (castsFrom > from)
        looked.cameraClipFromWorld = glm::perspective(glm::radians(camera.fovYDeg), aspect, std::min(castsFrom, far), far) * camera.viewFromWorld();
    cam.casts = castersOverSlice(cam, direction, looked, (in.paddingTexels + 2.0f) * texel);
    // What its lookups read (a low sun over a street sees its square mostly
    // as sky and ground past the street's ends): the receivers seen over the
    // same depths, each box cut to the frustum's box in the world, then in
    // the light's view (a ground under a low sun is a thin strip of the
    // light's view, not the frustum's height).
    const Bounds frustum = frustumBounds(looked.cameraClipFromWorld, cam.viewFromWorld);
    const Bounds frustumWorld = frustumBounds(looked.cameraClipFromWorld, glm::mat4(1.0f));
    cam.lookups = Bounds{};
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (!in.items[i].receivesShadows || !mayIntersect(looked.cameraClipFromWorld, in.itemBounds[i])) continue;
        const Bounds world = in.itemBounds[i].cutTo(frustumWorld);
        if (!world.empty()) cam.lookups->add(world.transformed(cam.viewFromWorld).cutTo(frustum));
    }
    return cam;
}

LightCamera fitSpot(const Light& light, LightFit fit, const FitInput& in) {
    LightCamera cam;
    const glm::vec3 axis = glm::normalize(light.direction);
    cam.viewFromWorld = glm::lookAt(light.position, light.position + axis, lightCameraUp(axis));
    cam.perspective = true;
    cam.casts = castersThatMatter(towardsLight(light), cam.viewFromWorld, in);
    // Far: the farthest projection on the axis of what must be covered.
    Bounds covered;
    if (fit == LightFit::Scene) covered = all(in);
    else covered = visibleReceivers(in, glm::mat4(1.0f));
    if (covered.empty()) covered = all(in);
    float far = 0.0f;
    for (int c = 0; c < 8 && !covered.empty(); ++c) {
        const glm::vec3 corner((c & 1) ? covered.hi.x : covered.lo.x, (c & 2) ? covered.hi.y : covered.lo.y,
                               (c & 4) ? covered.hi.z : covered.lo.z);
        far = std::max(far, glm::dot(corner - light.position, axis));
    }
    if (light.range > 0.0f) far = std::min(far, light.range);
    far = std::max(far, 1e-3f);
    // The field of view just contains the outer cone, plus the padding.
    const float halfAngle = glm::radians(light.outerConeDeg);
    const float tanHalf = std::tan(halfAngle) * (1.0f + 2.0f * in.paddingTexels / static_cast<float>(std::max(in.size, 1)));
    const float fovY = 2.0f * std::atan(tanHalf);
    // Near: as far out as the casters inside the map's pyramid allow: the
    // nearest point of each caster's box within it (a floor under a
    // horizontal spot reaches under the light, but the pyramid meets it
    // metres out; its box's nearest corner put the near plane at far / 10^4,
    // where 16 bits of depth held nothing: glass-panel with depth16 lost
    // every shadow).
    float near = far;
    const glm::mat4 probe = glm::perspective(fovY, 1.0f, far * 1e-4f, far) * cam.viewFromWorld;
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (!cam.casts[i] || !mayIntersect(probe, in.itemBounds[i])) continue;
        near = std::min(near, nearestInPyramid(in.itemBounds[i], cam.viewFromWorld, tanHalf, tanHalf));
    }
    near = std::clamp(near * 0.99f, far * 1e-4f, far * 0.999f);
    cam.nearPlane = near;
    cam.farPlane = far;
    cam.clipFromView = glm::perspective(fovY, 1.0f, near, far);
    cam.texelSize = 2.0f * tanHalf / static_cast<float>(std::max(in.size, 1));
    return cam;
}

glm::mat4 cubeFaceView(const glm::vec3& position, int face) {
    // GL's cube-map faces: the direction each looks along and its up vector
    // (the t axis of a face runs down its image, hence the negative ups).
    static const glm::vec3 directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const auto f = static_cast<std::size_t>(std::clamp(face, 0, 5));
    return glm::lookAt(position, position + directions[f], ups[f]);
}

CubeCamera fitCube(const Light& light, LightFit fit, const FitInput& in, float nearPlane, float farPlane) {
    CubeCamera cam;
    cam.position = light.position;
    Bounds covered = fit == LightFit::Scene ? all(in) : visibleReceivers(in, glm::mat4(1.0f));
    if (covered.empty()) covered = all(in);
    float far = 0.0f;
    for (int c = 0; c < 8 && !covered.empty(); ++c) {
        const glm::vec3 corner((c & 1) ? covered.hi.x : covered.lo.x, (c & 2) ? covered.hi.y : covered.lo.y,
                               (c & 4) ? covered.hi.z : covered.lo.z);
        far = std::max(far, glm::length(corner - light.position));
    }
    if (light.range > 0.0f) far = std::min(far, light.range);
    far = std::max(far * 1.001f, 1e-3f);
    cam.farPlane = farPlane > 0.0f ? farPlane : far;
    cam.nearPlane = nearPlane > 0.0f ? nearPlane : cam.farPlane * 1e-4f;
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, cam.nearPlane, cam.farPlane);
    for (int f = 0; f < 6; ++f) cam.faceClipFromWorld[static_cast<std::size_t>(f)] = projection * cubeFaceView(light.position, f);
    const std::vector<std::uint8_t> casts = castersThatMatter(towardsLight(light), glm::mat4(1.0f), in);
    cam.faceMasks.assign(in.items.size(), 0);
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (!casts[i]) continue;
        std::uint8_t mask = 0;
        for (int f = 0; f < 6; ++f)
            if (mayIntersect(cam.faceClipFromWorld[static_cast<std::size_t>(f)], in.itemBounds[i])) mask = static_cast<std::uint8_t>(mask | (1u << f));
        cam.faceMasks[i] = mask;
    }
    return cam;
}

} // namespace shadowlab
