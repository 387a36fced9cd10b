#pragma once
// Technique "map": the shadow atlas and each light's tiles as debug images
// (atlas/Images.cpp), for `render --debug atlas` and the viewer's panel.
#include "techniques/map/atlas/Atlas.h"

#include <map>

namespace shadowlab::map {

/// `atlas` as an image (DebugImageKind::Atlas): the part its tiles
/// use, at most `maxSide` pixels a side (every k-th texel), each tile's
/// depths stretched over their own range, near dark, and each light's
/// tiles (`lights`: index -> state) outlined in a hue of its own.
DebugImage atlasImage(const MapAtlas& atlas, const std::map<int, const MapLight*>& lights, int maxSide = 1024);
/// One light's own tiles in `atlas` (DebugImageKind::ShadowMap: its map) side by
/// side, bottom-aligned (a spot's one, a cube's six in face order
/// +X..-Z, each face at its own side), each stretched over its own
/// depths, near dark; values: their depths, tile after tile, rows as GL
/// stores them.
DebugImage atlasLightTiles(const MapAtlas& atlas, const MapLight& p);

} // namespace shadowlab::map
