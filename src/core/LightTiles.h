#pragma once
// Which lights reach which screen tiles: the tiled light list of the pass
// that shades many lights at once (render/LightList.cpp uploads it,
// lighting.frag's LIGHT_LIST variant reads it). GPU-free, so it is tested
// on its own.
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
};

/// A sphere around what `light` reaches: its range, or for a spot the
/// smallest sphere around the cone cut off at the range (through the apex
/// and the rim for an outer half-angle under 45 degrees, around the rim
/// above it); everywhere for a directional light or a range of 0.
LightReach reachOf(const Light& light);

/// The screen rectangle (ndc: lo.x, lo.y, hi.x, hi.y, within -1..1) that
/// `r` may cover seen through `viewFromWorld` and the perspective
/// `clipFromView`: exact for a sphere in front of the eye, the whole frame
/// when it reaches the eye's plane or everywhere; none when it lies
/// outside one of the view's planes.
std::optional<glm::vec4> screenRectOf(const LightReach& r, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView);

/// The tiles of a `size` frame, `tileSize` pixels a side (the last row and
/// column may be partial), and for each the lights whose reach may overlap
/// it. Conservative: a light that reaches a pixel is listed in its tile;
/// a light may be listed where it reaches nothing (its sphere's screen
/// rectangle, or the whole frame when the sphere reaches the eye's plane).
struct LightTiles {
    glm::uvec2 tiles{0};               ///< across, down (from the bottom row: GL's window origin)
    std::uint32_t tileSize = 16;       ///< pixels
    /// Per tile (row-major from the bottom-left), its first index into
    /// `cells` and its count, then the light indices themselves: the layout
    /// the shader reads (cells[2t], cells[2t + 1], cells[first + k]).
    std::vector<std::uint32_t> cells;
    std::size_t entries = 0;           ///< light indices listed over all tiles
    std::size_t culled = 0;            ///< lights outside the view, listed nowhere
};

/// Bins `reach[k]` (light k of the list) into tiles of the frame seen
/// through `viewFromWorld` and the perspective `clipFromView` (OpenGL clip
/// space, clip w = -z of the view; a far plane at infinity is fine).
LightTiles binLights(const std::vector<LightReach>& reach, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView, glm::ivec2 size,
                     std::uint32_t tileSize);

} // namespace shadowlab
