#pragma once
// Technique "map": the shadow pass of a point light's cube (passes/CubePass.cpp).
#include "techniques/map/passes/Resources.h"

namespace shadowlab::map {

/// A point light's cube: its faces cleared where they hold or will hold
/// casters, then the casters drawn once through the geometry shader (each
/// triangle to the faces it touches) or once per face they touch.
void renderCubePass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, MapLight& p);

} // namespace shadowlab::map
