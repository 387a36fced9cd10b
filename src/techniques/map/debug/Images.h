#pragma once
// Technique "map": the images `shadowlab render --debug-images` writes of a
// light: its map (each cascade's; perspective depth linearised), a cube as
// a cross, the texel density over the frame and the cascades' colours.
#include "techniques/Technique.h"
#include "techniques/map/passes/Resources.h"

#include <vector>

namespace shadowlab::map {

// Only the kinds `kinds` wants: a map or cube read back costs its texels.
void debugImages(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, const MapLight& p,
                 const DebugImageKinds& kinds, std::vector<DebugImage>& out);

} // namespace shadowlab::map
