// Cascaded shadow maps of a directional light (Cascades.h).
#include "geometry/Cascades.h"

#include "geometry/LightFitParts.h"
#include "geometry/Plane.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadowlab {

using fitparts::all;
using fitparts::diagonalOf;
using fitparts::directionalView;
using fitparts::nearestInPyramid;
using fitparts::visibleReceivers;


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

// A stabilised slice's depth range in light view `lightView`: the scene
// along the light, cut to what the slice's lookups can reach (`reads`,
// its frustum, within the scene's box), so the map's depth range is the
// slice's, not the whole scene's: moments leaked at casters' feet wherever
// depths a few decimetres apart became too close in a range of hundreds
// of metres. Casters nearer the light are pancaked onto the near plane
// (depth clamp). The ends are rounded out to 1/32 of the slice's box
// (`half`: its half width) so that they move by steps, rarely.
Bounds sliceDepth(const Bounds& scene, const glm::mat4& lightView, const glm::mat4& reads, float half) {
    Bounds depth = scene.transformed(lightView);
    if (scene.empty()) return depth;
    const Bounds world = frustumBounds(reads, glm::mat4(1.0f)).cutTo(scene);
    const Bounds reach = world.transformed(lightView);
    const float step = 0.0625f * half;
    if (!world.empty() && step > 0.0f) {
        depth.lo.z = std::max(depth.lo.z, std::floor(reach.lo.z / step) * step);
        depth.hi.z = std::min(depth.hi.z, std::ceil(reach.hi.z / step) * step);
    }
    return depth;
}

// What a slice's lookups read (a low sun over a street sees its square
// mostly as sky and ground past the street's ends): the receivers seen
// through `looked` (a clip-from-world), each box cut to that frustum's box
// in the world, then in the light's view (a ground under a low sun is a
// thin strip of the light's view, not the frustum's height).
Bounds lookupsOver(const FitInput& in, const glm::mat4& looked, const glm::mat4& lightView) {
    const Bounds frustum = frustumBounds(looked, lightView);
    const Bounds frustumWorld = frustumBounds(looked, glm::mat4(1.0f));
    Bounds out;
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (!in.items[i].receivesShadows || !mayIntersect(looked, in.itemBounds[i])) continue;
        const Bounds world = in.itemBounds[i].cutTo(frustumWorld);
        if (!world.empty()) out.add(world.transformed(lightView).cutTo(frustum));
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
    const Bounds depth = sliceDepth(scene, cam.viewFromWorld, reads.cameraClipFromWorld, half);
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
    cam.lookups = lookupsOver(in, looked.cameraClipFromWorld, cam.viewFromWorld);
    return cam;
}

} // namespace shadowlab
