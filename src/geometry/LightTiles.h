#pragma once
// Which lights reach which screen tiles and depth slices (clusters: Olsson,
// Billeter and Assarsson, "Clustered Deferred and Forward Shading", 2012):
// the clustered light list of the pass that shades many lights at once
// (render/LightList.cpp uploads it, lighting.frag's LIGHT_LIST variant
// reads it). GPU-free, so it is tested on its own.
#include <shadowlab/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace shadowlab {

/// Where a light can reach, for binning: everywhere (a directional light,
/// or a range of 0) or a world-space sphere.
struct LightReach {
    bool everywhere = true;
    glm::vec3 centre{0.0f};
    float radius = 0.0f;  ///< scene units, > 0 unless everywhere
    /// A spot's cone inside the sphere (outer half-angle under 90 degrees):
    /// the points within `range` of `apex` at most the half-angle off
    /// `axis` (unit). Binning keeps a cluster only where both may reach.
    bool cone = false;
    glm::vec3 apex{0.0f}, axis{0.0f, 0.0f, -1.0f};
    float cosAngle = 1.0f, sinAngle = 0.0f, range = 0.0f;
};

/// A sphere around what `light` reaches: its range, or for a spot the
/// smallest sphere around the cone cut off at the range (through the apex
/// and the rim for an outer half-angle under 45 degrees, around the rim
/// above it) and, under 90 degrees, the cone itself; everywhere for a
/// directional light or a range of 0.
LightReach reachOf(const Light& light);

/// The screen rectangle (ndc: lo.x, lo.y, hi.x, hi.y, within -1..1) that
/// `r` may cover seen through `viewFromWorld` and the perspective
/// `clipFromView`: exact for a sphere in front of the eye, the whole frame
/// when it reaches the eye's plane or everywhere; none when it lies
/// outside one of the view's planes.
std::optional<glm::vec4> screenRectOf(const LightReach& r, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView);

/// The clusters of a `size` frame: tiles `tileSize` pixels a side (the
/// last row and column may be partial), each cut along the view into
/// `slices` depth slices, spaced evenly in log(depth) from where the
/// nearest sphere in view begins (the camera's near plane at the least;
/// slice 0 also holds what is nearer) to where the farthest sphere ends
/// (the last slice also holds what is farther): a pixel at view depth d
/// (its clip w) is in slice clamp(floor(log(d / sliceNear) * sliceScale),
/// 0, slices - 1). For each cluster, the lights whose reach may overlap
/// it. Conservative: a light that reaches a pixel is listed in its
/// cluster (each slice's depths widened by 10^-3 each way, so that the
/// shader's rounding never puts a pixel in a slice that leaves it out); a
/// light may be listed where it reaches nothing (the box of the cluster's
/// frustum overlaps its sphere, and the sphere around that box its cone,
/// or everywhere for a directional light).
struct LightTiles {
    glm::uvec2 tiles{0};               ///< across, down (from the bottom row: GL's window origin)
    std::uint32_t tileSize = 16;       ///< pixels
    std::uint32_t slices = 1;          ///< depth slices a tile
    float sliceNear = 1.0f;            ///< view depth where the slices start (slice 0 also holds what is nearer)
    float sliceScale = 0.0f;           ///< slices per unit of log(depth / sliceNear)
    /// Per cluster (index (slice * tiles.y + row) * tiles.x + column, rows
    /// from the bottom-left), its first index into `cells` and its count,
    /// then the light indices themselves in light order: the layout the
    /// shader reads (cells[2c], cells[2c + 1], cells[first + k]).
    std::vector<std::uint32_t> cells;
    std::size_t entries = 0;           ///< light indices listed over all clusters
    std::size_t culled = 0;            ///< lights outside the view, listed nowhere
    /// The slice of a pixel at view depth `d` (what the shader computes).
    std::uint32_t sliceOf(float d) const;
};


/// Bins `reach[k]` (light k of the list) into the clusters of the frame
/// seen through `viewFromWorld` and the perspective `clipFromView` (OpenGL
/// clip space, clip w = -z of the view; a far plane at infinity is fine).
LightTiles binLights(const std::vector<LightReach>& reach, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, glm::ivec2 size,
                     std::uint32_t tileSize, std::uint32_t slices);

} // namespace shadowlab
