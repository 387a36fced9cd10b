#pragma once
// Technique "map": where on the screen a light's shadows can fall this
// frame (Technique::shadowedPixels), so that the base pass runs the test
// only there. A receiver is shadowed only where one of the filter's taps
// reads a texel that a caster covers, and a caster covers texels only
// inside its box's image in the map; the receivers those taps come from lie
// within the filter's footprint and the normal offset of that image, and
// between the light's near and far planes. So each caster drawn into the
// map gives a box in the light's clip space: its image widened by those
// texels, over the whole depth range; the screen rectangle around those
// boxes' corners holds every pixel the test could shadow.
#include "techniques/Technique.h"
#include "core/ScreenRect.h"
#include "techniques/map/MapLight.h"

#include <optional>
#include <vector>

namespace shadowlab::map {

/// At most this many rectangles a light (MapRegion.cpp merges the casters' into as few).
inline constexpr std::size_t kMaxRects = 8;

/// The pixels outside of which light `p`'s test finds every receiver lit:
/// a rectangle around each caster's box swept away from the light, those
/// that overlap merged (none: no caster); nothing when that is not known:
/// a cube, the atlas, cascades, a fit or warp made on the GPU or per point,
/// moments, the lecture's dither (its spread follows the map's size), a
/// negative polygon offset, or a box that reaches behind the light or the
/// viewer.
std::optional<std::vector<PixelRect>> shadowedPixels(const MapLight& p, const FrameInfo& frame);

} // namespace shadowlab::map
