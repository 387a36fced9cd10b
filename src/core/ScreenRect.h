#pragma once
// Rectangles of pixels on the screen: what a box in the world covers there,
// and rectangles merged into fewer (the base pass runs a light's test in
// the rectangles its shadows can fall in: RenderOptions::shadowRegions). GPU-free.
#include "core/Bounds.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace shadowlab {

/// Pixels x0 <= x < x1, y0 <= y < y1 from the lower left, as glm::ivec4(x0, y0, x1, y1).
using PixelRect = glm::ivec4;

/// True when `r` holds no pixel.
inline bool isEmpty(const PixelRect& r) { return r.x >= r.z || r.y >= r.w; }

/// Its pixels.
inline double area(const PixelRect& r) { return isEmpty(r) ? 0.0 : double(r.z - r.x) * double(r.w - r.y); }

/// The pixels of a `viewport`-sized frame around clip-space (divided)
/// points from `lo` to `hi`, a pixel wider for rounding.
PixelRect pixelsAround(glm::vec2 lo, glm::vec2 hi, glm::ivec2 viewport);

/// The pixels of a `viewport`-sized frame that `box` may cover through
/// `clipFromWorld` (its corners' images, a pixel wider), or the whole frame
/// when a corner lies behind the viewer.
PixelRect screenRectOf(const Bounds& box, const glm::mat4& clipFromWorld, glm::ivec2 viewport);

/// More rectangles than this are merged into the one around them all.
inline constexpr std::size_t kMergeAtMost = 256;

/// `rects` with every two whose rectangle adds a tenth or less to the
/// pixels of both replaced by that rectangle, until none do, then the two
/// whose rectangle adds the fewest, until at most `most` remain (empty
/// ones dropped). Those left may overlap. More than kMergeAtMost: the
/// rectangle around them all.
std::vector<PixelRect> mergedRects(std::vector<PixelRect> rects, std::size_t most);

/// The pixels in both (empty when they share none).
inline PixelRect intersection(const PixelRect& a, const PixelRect& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::min(a.z, b.z), std::min(a.w, b.w)}; }

/// Whether `a` and `b` share a pixel.
inline bool overlaps(const PixelRect& a, const PixelRect& b) { return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w; }

} // namespace shadowlab
