#pragma once
// Technique "map": translucent casters (materials' alphaMode blend) colour
// the light. Each map layer (a 2D map's, or a cube face's) gets two more:
// the casters' colours multiplied together and their nearest depth, drawn
// where no opaque caster is nearer (the map's own depth, tested, not
// written); shadow_map.glsl's transmittanceAt reads them.
#include "techniques/Technique.h"
#include "techniques/map/Light.h"
#include "techniques/map/lookup/Block.h"
#include "techniques/map/passes/Arrays.h"

namespace shadowlab::map {

/// Whether item i is a translucent caster (its material's alphaMode is blend).
bool translucentCaster(const FrameInfo& frame, std::size_t i);
/// Whether any caster of the frame is translucent.
bool hasTranslucentCasters(const FrameInfo& frame);
/// The translucent casters into the transmittance of `p`'s layer c, seen
/// from its camera c (a cascade's, or the one map's).
void drawTranslucent(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p, std::size_t c);
/// A point light's translucent casters into its cube's transmittance
/// layers, face by face, after the opaque depth.
void drawCubeTranslucent(TechniqueHost& host, const FrameInfo& frame, const MapArray& g, const MapLight& p);

} // namespace shadowlab::map
