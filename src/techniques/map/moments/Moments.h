#pragma once
// Technique "map": filterable moment maps (VSM, EVSM, MSM; shaders
// shadow_map_shared.h momentsOf, shadow_map.glsl momentVisibility): a
// layer's moments made from its depth and blurred (their constants:
// moments/Constants.h).
#include "techniques/Technique.h"
#include "techniques/map/lookup/Block.h"
#include "techniques/map/moments/Constants.h"
#include "techniques/map/passes/Arrays.h"

namespace shadowlab::map {

/// The moments of one layer, made from the depth its shadow pass left
/// (g.depth's layer) and blurred: across into the scratch texture, then
/// down into the moment layer; with radius 0, straight into the layer.
/// `spot`: the depth is a spot's perspective depth (linearised first).
void makeMoments(TechniqueHost& host, MapBlock& block, const MapArray& g, int layer, int radius, bool spot);

} // namespace shadowlab::map
