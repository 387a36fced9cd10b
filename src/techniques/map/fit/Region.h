#pragma once
// Technique "map": where on the screen a light's shadows can fall this
// frame (Technique::shadowedPixels), so that the base pass runs the test
// only there. A receiver is shadowed only where one of the filter's taps
// reads a texel that a caster covers, and a caster covers texels only
// inside its box's image in the map; the receivers those taps come from lie
// within the filter's footprint and the normal offset of that image, and
// past the caster's nearest depth less what the offsets and biases move a
// compared depth. So each caster drawn into the map, its box widened by
// those texels, goes to core/ShadowRegion with that slack of depth.
#include "core/ScreenRect.h"
#include "techniques/Technique.h"
#include "techniques/map/Light.h"

#include <optional>
#include <vector>

namespace shadowlab::map {

/// The pixels outside of which light `p`'s test finds every receiver lit:
/// a rectangle around each caster's box swept away from the light, those
/// that overlap merged (none: no caster). A point light's cube: each
/// caster's box widened by its taps' reach, in a perspective light space
/// from the light around it. `size`: the map's texels a side. Nothing when
/// that is not known: the atlas, cascades, a fit or warp made on the GPU or
/// per point, moments, the lecture's dither (its spread follows the map's
/// size), a negative polygon offset, a light within a caster's box, or a
/// box that reaches behind the viewer.
std::optional<std::vector<PixelRect>> shadowedPixels(const MapLight& p, const Light& light, const FrameInfo& frame, int size);

} // namespace shadowlab::map
