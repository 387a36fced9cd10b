#pragma once
// Technique "map": the framebuffers on each light's layers (passes/Targets.cpp).
#include "techniques/map/passes/Resources.h"

namespace shadowlab::map {

/// Attaches the light's layer to its framebuffers when the array or the
/// layer changed (a new array gets a new framebuffer: the old one may still
/// name the deleted texture).
void attachTargets(MapLight& p, const MapArray& g);

} // namespace shadowlab::map
