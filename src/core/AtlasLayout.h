#pragma once
// Where the shadow atlas's tiles go (technique map with `atlas`): square
// tiles of power-of-two sides packed into one square texture, shrunk, the
// largest first, until they fit. GPU-free, so it is tested on its own.
#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

/// What one light asks of the atlas: `tiles` tiles (a spot 1, a point
/// light's cube 6) of `side` texels each (a power of two).
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
};

/// Packs `requests` into an atlas of `size` texels a side (a power of
/// two). While their area exceeds the atlas's, every tile of the largest
/// side above `minSide` is halved (the lights nearest the camera give up
/// texels first, and no light drops below `minSide`). Tiles are placed in
/// decreasing size along a Z-order curve, which keeps each power-of-two
/// square whole and aligned: any set of such tiles whose area fits, fits.
AtlasLayout packAtlas(const std::vector<AtlasRequest>& requests, int size, int minSide);

/// A tile's side for a light whose reach covers `extentPixels` pixels
/// across on screen: extent x texelsPerPixel rounded up to a power of two,
/// within [minSide, maxSide].
int tileSideFor(float extentPixels, float texelsPerPixel, int minSide, int maxSide);

} // namespace shadowlab
