#include "geometry/LightCamera.h"

#include "geometry/LightFitParts.h"

#include "geometry/Plane.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace shadowlab {

using fitparts::all;
using fitparts::diagonalOf;
using fitparts::directionalView;
using fitparts::lightViewOf;
using fitparts::nearestInPyramid;
using fitparts::visibleReceivers;

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


glm::mat4 directionalLightView(const glm::vec3& direction, const FitInput& in) {
    const Bounds scene = all(in);
    return lightViewOf(direction, scene, diagonalOf(scene));
}

float sceneDiagonal(const FitInput& in) { return diagonalOf(all(in)); }

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
