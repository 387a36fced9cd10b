#pragma once
// Technique "map": the shadow atlas's tiles one by one (atlas/Tiles.cpp):
// how large a light's reach is on screen, a tile's record for the lookups,
// which casters a tile draws, the atlas's samplers.
#include "techniques/Technique.h"
#include "techniques/map/Light.h"

#include "shadow_atlas_shared.h"

#include <glm/glm.hpp>

namespace shadowlab::map {

/// The depth a cleared texel holds: no caster before the far plane.
constexpr float kAtlasFar = 1.0f;

/// How many pixels across the light's reach covers on screen (0: out of view).
float screenExtent(const Light& light, const FrameInfo& frame);

/// A tile's record: its camera's clip space moved into its square of the
/// atlas (xy to its uv, z to 0..1), its outermost texels' centres, the
/// centres of the outermost texels its casters may cover (projectedRect's
/// margin keeps the casters a texel inside them, and a bilinear lookup
/// between those centres reads only cleared texels; at the tile's edge they
/// are the tile's own outermost centres), and the world size of a texel
/// per unit of distance along the camera's axis (2 / (side P[1][1]): a cube
/// face's P[1][1] is 1).
shared::AtlasTile tileOf(const glm::mat4& clipFromWorld, float projectionY, glm::ivec2 origin, int side, int atlas, const TexelRect& covered);

/// Whether item i is drawn into tile t of light p: a caster its camera can
/// see (a cube face's by its face mask, a spot's by its frustum: the same
/// culling as the light's own map).
bool castsIntoTile(const FrameInfo& frame, const MapLight& p, int t, std::size_t i);

/// The atlas's samplers: nearest depths (compare false) or bilinear compares.
gl::Sampler atlasSampler(bool compare);

} // namespace shadowlab::map
