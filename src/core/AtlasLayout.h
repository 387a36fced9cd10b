#pragma once
// Where the shadow atlas's tiles go (technique map with `atlas`): square
// tiles of power-of-two sides packed into one square texture, shrunk, the
// largest first, until they fit. GPU-free, so it is tested on its own.
#include "core/Bounds.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace shadowlab {

/// What one light asks of the atlas: `tiles` tiles (a spot 1, a point
/// light's cube 6) of `side` texels each (a power of two; any other side
/// is taken as the largest power of two below it).
struct AtlasRequest {
    int tiles = 1;
    int side = 0;
};

/// Where one light's tiles went.
struct AtlasPlacement {
    int side = 0;                       ///< texels per side of each tile, at most the request's
    std::vector<glm::ivec2> origins;    ///< each tile's lower-left texel
    bool shrunk() const { return shrunkFrom > side; }
    int shrunkFrom = 0;                 ///< the side asked for
};

struct AtlasLayout {
    std::vector<AtlasPlacement> placed; ///< per request, in order
    double texelsUsed = 0.0;            ///< sum of the tiles' areas
    bool fits = true;                   ///< false: even at `minSide` the tiles exceed the atlas (placed is then empty)
    bool overBudget = false;            ///< the tiles at `minSide` alone exceed the budget (they fit the atlas)
};

/// Packs `requests` into an atlas of `size` texels a side (a power of
/// two; the sides asked for and `minSide` are rounded down to powers of
/// two first). While their area exceeds `budget` texels (0: the atlas's area;
/// at most it), the requests whose tiles have the largest side above
/// `minSide` are halved one after another in order until the area fits
/// (the lights nearest the camera give up texels first, no more are given
/// up than needed, and no light drops below `minSide`); tiles at `minSide` past the budget still fit
/// when the atlas holds them (AtlasLayout::overBudget). Tiles are placed in
/// decreasing size along a Z-order curve, which keeps each power-of-two
/// square whole and aligned: any set of such tiles whose area fits, fits.
AtlasLayout packAtlas(const std::vector<AtlasRequest>& requests, int size, int minSide, double budget = 0.0);

/// A tile's side for a light whose reach covers `extentPixels` pixels
/// across on screen: extent x texelsPerPixel rounded up to a power of two,
/// within [minSide, maxSide].
int tileSideFor(float extentPixels, float texelsPerPixel, int minSide, int maxSide);

/// tileSideFor with hysteresis: a tile that had side `previous` (0: none)
/// keeps it while extent x texelsPerPixel stays within
/// [kShrinkBelow, kGrowAbove] x previous and previous is within
/// [minSide, maxSide], so that a light moving a little does not move every
/// tile of the atlas (a changed side packs the atlas again: every tile is
/// new to its place and drawn, whatever the update budget).
int tileSideKeeping(float extentPixels, float texelsPerPixel, int minSide, int maxSide, int previous);
inline constexpr float kShrinkBelow = 0.45f;  ///< a kept side halves when the want falls below this share of it (tileSideFor would at 0.5)
inline constexpr float kGrowAbove = 1.1f;     ///< and doubles when the want rises above this share (tileSideFor would at 1)

/// The part of a point light's reach (the sphere of `range` around
/// `position`) that cube face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z) sees,
/// cut to `receivers` (where lookups can land): a world box around it. The
/// face's pyramid within the range lies at most `range` along the face's
/// axis and at most min(that, range / sqrt(2)) off it. Empty when no
/// receiver is there.
Bounds cubeFaceReach(const glm::vec3& position, float range, int face, const Bounds& receivers);

/// How many pixels across (the larger side of its screen rectangle, cut
/// to the frame) a world box covers through `clipFromWorld` on a frame of
/// `viewport` pixels: 0 when it is outside the frame; none when a corner
/// lies behind the eye (its projection is unbounded).
std::optional<float> screenExtentOf(const Bounds& box, const glm::mat4& clipFromWorld, glm::ivec2 viewport);

} // namespace shadowlab
