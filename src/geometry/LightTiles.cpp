#include "geometry/LightTiles.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

// The tile rectangle (inclusive) a light may touch; empty (x0 > x1) when
// it is outside the view.
struct TileRect {
    int x0, y0, x1, y1;
};

// The bounds of k = a / d over a sphere of centre (a, d) and radius r, d the
// distance in front of the eye (> r): the slopes of the two tangents from
// the eye in that plane.
glm::vec2 slopes(float a, float d, float r) {
    const float root = r * std::sqrt(std::max(a * a + d * d - r * r, 0.0f));
    const float denominator = d * d - r * r;
    return {(a * d - root) / denominator, (a * d + root) / denominator};
}

TileRect rectOf(const LightReach& r, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, glm::ivec2 size,
                std::uint32_t tileSize, glm::ivec2 tiles) {
    const std::optional<glm::vec4> ndc = screenRectOf(r, viewFromWorld, clipFromView);
    if (!ndc) return {1, 1, 0, 0};
    const glm::vec2 pixels(size);
    const auto tile = [&](float v, float extent, int count) {
        const float pixel = (v * 0.5f + 0.5f) * extent;
        return std::clamp(static_cast<int>(std::floor(pixel / static_cast<float>(tileSize))), 0, count - 1);
    };
    return {tile(ndc->x, pixels.x, tiles.x), tile(ndc->y, pixels.y, tiles.y), tile(ndc->z, pixels.x, tiles.x), tile(ndc->w, pixels.y, tiles.y)};
}

// Whether the sphere (centre, radius) may meet r's cone with its apex
// and unit axis in the same coordinates: the sphere's centre is off the
// cone's side by less than its radius (measured across the side, which
// is within the radius of the nearest point of the cone when it is
// nearer than the radius), and neither wholly behind the apex nor past
// the range along the axis. Widened by 10^-3 of the radius and 10^-5.
bool sphereMeetsCone(const glm::vec3& centre, float radius, const glm::vec3& apex, const glm::vec3& axis, const LightReach& r) {
    const float margin = radius * 1.001f + 1e-5f;
    const glm::vec3 v = centre - apex;
    const float along = glm::dot(v, axis);
    const float across = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0f));
    if (r.cosAngle * across - r.sinAngle * along > margin) return false;  // off the side
    return along >= -margin && along <= r.range + margin;
}

} // namespace

std::optional<glm::vec4> screenRectOf(const LightReach& r, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView) {
    const glm::vec4 all(-1.0f, -1.0f, 1.0f, 1.0f);
    if (r.everywhere) return all;
    // Outside a side plane of the view (Gribb and Hartmann: the planes are
    // sums of clip matrix rows); a degenerate plane (the far plane at
    // infinity) is skipped.
    const glm::mat4 m = glm::transpose(clipFromView * viewFromWorld);  // m[i] is row i
    const glm::vec4 planes[6] = {m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[3] + m[2], m[3] - m[2]};
    for (const glm::vec4& p : planes) {
        const float length = glm::length(glm::vec3(p));
        if (!(length > 1e-12f)) continue;
        if ((glm::dot(glm::vec3(p), r.centre) + p.w) / length < -r.radius) return std::nullopt;
    }
    // The sphere's exact screen rectangle from its tangents through the
    // eye (a perspective camera looking down -z: clip w = -z); the whole
    // frame when the sphere reaches the eye's plane (its projection is
    // unbounded there).
    const glm::vec3 c = glm::vec3(viewFromWorld * glm::vec4(r.centre, 1.0f));
    const float d = -c.z;
    if (!(d > r.radius * 1.0001f + 1e-6f)) return all;
    const glm::vec2 kx = slopes(c.x, d, r.radius), ky = slopes(c.y, d, r.radius);
    // ndc = P[0][0] k - P[2][0] (x), P[1][1] k - P[2][1] (y), with z = -d.
    const glm::vec2 x = clipFromView[0][0] * kx - clipFromView[2][0], y = clipFromView[1][1] * ky - clipFromView[2][1];
    const glm::vec2 lo = glm::clamp(glm::vec2(std::min(x.x, x.y), std::min(y.x, y.y)), -1.0f, 1.0f);
    const glm::vec2 hi = glm::clamp(glm::vec2(std::max(x.x, x.y), std::max(y.x, y.y)), -1.0f, 1.0f);
    return glm::vec4(lo, hi);
}

LightReach reachOf(const Light& light) {
    LightReach r;
    if (light.type == LightType::Directional || !(light.range > 0.0f)) return r;  // everywhere
    r.everywhere = false;
    r.centre = light.position;
    r.radius = light.range;
    if (light.type == LightType::Spot) {
        const float angle = glm::radians(light.outerConeDeg);
        const glm::vec3 axis = glm::normalize(light.direction);
        const float along = angle < glm::radians(45.0f) ? light.range / (2.0f * std::cos(angle)) : light.range * std::cos(angle);
        const float radius = angle < glm::radians(45.0f) ? along : light.range * std::sin(angle);
        r.centre = light.position + axis * along;
        r.radius = radius * 1.001f;  // rounding: never smaller than the cone
        if (angle < glm::radians(89.0f)) {
            r.cone = true;
            r.apex = light.position;
            r.axis = axis;
            r.cosAngle = std::cos(angle);
            r.sinAngle = std::sin(angle);
            r.range = light.range;
        }
    }
    return r;
}

std::uint32_t LightTiles::sliceOf(float d) const {
    if (!(d > 0.0f) || slices <= 1) return 0;
    const float s = std::floor(std::log(d / sliceNear) * sliceScale);
    if (!(s > 0.0f)) return 0;
    return std::min(static_cast<std::uint32_t>(std::min(s, 1.0e6f)), slices - 1);
}

namespace {

// Each slice's depths, widened by 10^-3 each way (the first from the eye,
// the last to `far`, the farthest sphere's end).
std::vector<glm::vec2> sliceDepths(const LightTiles& t, float far) {
    std::vector<glm::vec2> depths(t.slices);
    for (std::uint32_t s = 0; s < t.slices; ++s)
        depths[s] = {s == 0 ? 0.0f : t.sliceNear * std::exp(static_cast<float>(s) / t.sliceScale) * (1.0f - 1e-3f),
                     (s + 1 == t.slices ? far : t.sliceNear * std::exp(static_cast<float>(s + 1) / t.sliceScale)) * (1.0f + 1e-3f)};
    return depths;
}

// The slopes x / d (axis 0) or y / d (axis 1) of the edges of `across`
// tiles of `tileSize` pixels over `extent` pixels (ndc = P[0][0] x / d -
// P[2][0] with d = -z, the same for y): across + 1 edges.
std::vector<float> tileSlopes(const glm::mat4& clipFromView, std::uint32_t tileSize, int across, int extent, int axis) {
    std::vector<float> s(static_cast<std::size_t>(across) + 1);
    for (int tile = 0; tile <= across; ++tile) {
        const float ndc = 2.0f * static_cast<float>(std::min(tile * static_cast<int>(tileSize), extent)) / static_cast<float>(extent) - 1.0f;
        s[static_cast<std::size_t>(tile)] = (ndc + clipFromView[2][axis]) / clipFromView[axis][axis];
    }
    return s;
}

// out.cells: every cluster's header (first, count) first, then each
// cluster's light indices in light order (`clusters`: each light's
// clusters; `perCluster`: each cluster's lights).
void packCells(LightTiles& out, const std::vector<std::vector<std::uint32_t>>& clusters, const std::vector<std::uint32_t>& perCluster) {
    const std::size_t count = perCluster.size();
    out.cells.assign(2 * count, 0);
    std::uint32_t next = static_cast<std::uint32_t>(2 * count);
    for (std::size_t t = 0; t < count; ++t) {
        out.cells[2 * t] = next;
        next += perCluster[t];
    }
    out.entries = next - 2 * count;
    out.cells.resize(next);
    std::vector<std::uint32_t> filled(count, 0);
    for (std::size_t k = 0; k < clusters.size(); ++k)
        for (const std::uint32_t t : clusters[k]) out.cells[out.cells[2 * t] + filled[t]++] = static_cast<std::uint32_t>(k);
    for (std::size_t t = 0; t < count; ++t) out.cells[2 * t + 1] = filled[t];
}

} // namespace

LightTiles binLights(const std::vector<LightReach>& reach, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, glm::ivec2 size,
                     std::uint32_t tileSize, std::uint32_t slices) {
    LightTiles out;
    out.tileSize = std::max<std::uint32_t>(tileSize, 1);
    out.slices = std::max<std::uint32_t>(slices, 1);
    const glm::ivec2 tiles((std::max(size.x, 1) + static_cast<int>(out.tileSize) - 1) / static_cast<int>(out.tileSize),
                           (std::max(size.y, 1) + static_cast<int>(out.tileSize) - 1) / static_cast<int>(out.tileSize));
    out.tiles = glm::uvec2(tiles);
    const std::size_t perSlice = static_cast<std::size_t>(tiles.x) * static_cast<std::size_t>(tiles.y);
    const std::size_t count = perSlice * out.slices;
    // The slices: from the camera's near plane (P[3][2] / (P[2][2] - 1) of a
    // GL perspective) to where the farthest sphere in view ends.
    const float near = clipFromView[3][2] / (clipFromView[2][2] - 1.0f);
    out.sliceNear = near > 0.0f && std::isfinite(near) ? near : 0.1f;
    std::vector<TileRect> rects;
    rects.reserve(reach.size());
    float far = 2.0f * out.sliceNear, nearest = std::numeric_limits<float>::infinity();
    for (const LightReach& r : reach) {
        rects.push_back(rectOf(r, viewFromWorld, clipFromView, size, out.tileSize, tiles));
        if (rects.back().x0 <= rects.back().x1 && !r.everywhere) {
            const float d = -(viewFromWorld * glm::vec4(r.centre, 1.0f)).z;
            far = std::max(far, d + r.radius);
            nearest = std::min(nearest, d - r.radius);
        }
    }
    // No sphere reaches nearer than `nearest`: the slices start there.
    if (std::isfinite(nearest) && nearest * 0.99f > out.sliceNear) out.sliceNear = nearest * 0.99f;
    far = std::max(far, 2.0f * out.sliceNear);
    out.sliceScale = static_cast<float>(out.slices) / std::log(far / out.sliceNear);
    // Each slice's depths and each tile's slopes (widened by 10^-4 where the clusters are tested).
    const std::vector<glm::vec2> depths = sliceDepths(out, far);
    const std::vector<float> columns = tileSlopes(clipFromView, out.tileSize, tiles.x, size.x, 0);  // each tile's edges
    const std::vector<float> rows = tileSlopes(clipFromView, out.tileSize, tiles.y, size.y, 1);
    // Each light's clusters, in cluster order within a slice's rows.
    std::vector<std::vector<std::uint32_t>> clusters(reach.size());
    std::vector<std::uint32_t> perCluster(count, 0);
    for (std::size_t k = 0; k < reach.size(); ++k) {
        const TileRect& rect = rects[k];
        if (rect.x0 > rect.x1) {
            ++out.culled;
            continue;
        }
        const LightReach& r = reach[k];
        // The cone in the clusters' coordinates (view x, y and depth -z).
        const glm::vec3 apex = glm::vec3(viewFromWorld * glm::vec4(r.apex, 1.0f)) * glm::vec3(1.0f, 1.0f, -1.0f);
        const glm::vec3 axis = glm::mat3(viewFromWorld) * r.axis * glm::vec3(1.0f, 1.0f, -1.0f);
        const glm::vec3 c = glm::vec3(viewFromWorld * glm::vec4(r.centre, 1.0f));
        const float d = -c.z;
        const std::uint32_t s0 = r.everywhere ? 0 : out.sliceOf((d - r.radius) * (1.0f - 2e-3f));
        const std::uint32_t s1 = r.everywhere ? out.slices - 1 : out.sliceOf((d + r.radius) * (1.0f + 2e-3f));
        const float radius = r.radius * 1.0001f + 1e-6f;
        for (std::uint32_t s = s0; s <= s1; ++s)
            for (int y = rect.y0; y <= rect.y1; ++y)
                for (int x = rect.x0; x <= rect.x1; ++x) {
                    if (!r.everywhere) {
                        // The box of the cluster's frustum (view x, y and depth) against the sphere.
                        const auto xi = static_cast<std::size_t>(x), yi = static_cast<std::size_t>(y);
                        const glm::vec2 kx(columns[xi] - 1e-4f, columns[xi + 1] + 1e-4f), ky(rows[yi] - 1e-4f, rows[yi + 1] + 1e-4f);
                        const glm::vec2 dz = depths[s];
                        const glm::vec3 lo(std::min(kx.x * dz.x, kx.x * dz.y), std::min(ky.x * dz.x, ky.x * dz.y), dz.x);
                        const glm::vec3 hi(std::max(kx.y * dz.x, kx.y * dz.y), std::max(ky.y * dz.x, ky.y * dz.y), dz.y);
                        const glm::vec3 p(c.x, c.y, d);
                        const glm::vec3 outside = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
                        if (glm::dot(outside, outside) > radius * radius) continue;
                        if (r.cone && !sphereMeetsCone(0.5f * (lo + hi), 0.5f * glm::length(hi - lo), apex, axis, r)) continue;
                    }
                    const std::uint32_t cluster = (s * static_cast<std::uint32_t>(tiles.y) + static_cast<std::uint32_t>(y)) * static_cast<std::uint32_t>(tiles.x) +
                                                  static_cast<std::uint32_t>(x);
                    clusters[k].push_back(cluster);
                    ++perCluster[cluster];
                }
    }
    packCells(out, clusters, perCluster);
    return out;
}

} // namespace shadowlab
