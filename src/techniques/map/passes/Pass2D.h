#pragma once
// Technique "map": the shadow pass of a directional or spot light (passes/Pass2D.cpp).
#include "techniques/map/passes/Resources.h"

namespace shadowlab::map {

/// A directional or spot light's shadow pass: its map (or each cascade)
/// cleared and drawn, blurred (moments), the translucent layers, mipmaps.
void renderMapPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, MapLight& p);

} // namespace shadowlab::map
