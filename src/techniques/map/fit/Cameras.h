#pragma once
// Technique "map": each light's cameras for the frame (core/LightCamera
// fits them; the presets fix theirs) and which casters each camera draws.
#include "techniques/Technique.h"
#include "techniques/map/Light.h"
#include "techniques/map/fit/Sdsm.h"
#include "techniques/map/passes/Arrays.h"

#include <optional>

namespace shadowlab::map {

/// Fits `p`'s cameras for `light` (p.options and p.cube() already set): a
/// cube's six faces, a spot's frustum, a directional light's box or
/// cascades, or a preset's fixed camera.
/// `samples`: points in sdsmLightView()'s space that replace the
/// receivers' boxes for a directional light's one map (fit "sdsm" culls
/// with sdsmReach's; its cameras are fitted on the GPU: MapSdsm).
void fitCameras(MapLight& p, const Light& light, const FrameInfo& frame, const Bounds* samples = nullptr);

/// Fit "scene" with a size that follows the frame (MapOptions::size 0):
/// how many times wider the scene's box is, across a directional light,
/// than the tight fit's box around what the view sees (at least 1). The
/// frame's size times it gives the part of the map the view reads as many
/// texels a pixel as the tight fit's. 1 for other lights, cascades, warps
/// and presets.
float sceneFitWidening(const MapOptions& o, const Light& light, const FrameInfo& frame);

/// Whether `p` takes fit "sdsm" (a directional light, no preset).
bool usesSamples(const MapLight& p, const Light& light);

/// The light view a directional light's fit works in (core/LightCamera's
/// directionalLightView for this frame's items): the reduction's space.
glm::mat4 sdsmLightView(const Light& light, const FrameInfo& frame);

/// Cascades fitted on the GPU (fit "sdsm"): `p`'s cameras for culling
/// their casters, each around every slice the GPU may fit. With `seenFar`
/// (the far end of the depths a frame before saw, GpuFit::seenFar) the GPU
/// splits over it: each slice is the GPU's own but the first (from the
/// near plane: it starts at the nearest depth seen) and the last (up to
/// the reach: it ends at this frame's far end). Not known (0): each slice
/// from the near plane to its far end when split over the whole reach
/// (the GPU's, split over the depths seen, end no farther). Stabilised:
/// each slice's sphere (fitCascade); not: the box of what may be seen
/// in the slice (sdsmReach) with two texels more padding, or, warped,
/// every caster that matters for the slice.
void fitCullingCascades(MapLight& p, const Light& light, const FrameInfo& frame, float seenFar);

/// Where the points a fit "sdsm" may take lie, in sdsmLightView's space:
/// the boxes of the items that may be in the view `clipFromWorld` (the
/// frame's, or a slice of it), cut to its frustum, with the reduction's
/// relative margin. Fitted to it, a camera holds the one fitted to the
/// points themselves (whose casters over them are among the ones over
/// it): the CPU culls the casters of a map fitted on the GPU with it.
Bounds sdsmReach(const Light& light, const FrameInfo& frame, const glm::mat4& clipFromWorld);

/// The fit on the GPU's inputs for `p` (its cameras fitted, for the casters
/// that matter): the light view, the scene's diagonal, the map's size and
/// padding, the casters' boxes.
GpuFitInput gpuFitInput(const MapLight& p, const Light& light, const FrameInfo& frame);

/// How near the light the casters drawn into a spot's or point light's map
/// come (MapLight::nearestCaster): a point light's distance to the nearest
/// caster's box, a spot's least depth of one along its axis, at least the
/// camera's near plane; 0 when no caster is drawn. p's cameras fitted.
float nearestCaster(const MapLight& p, const Light& light, const FrameInfo& frame);

/// Whether item i is drawn into `camera`'s map: it may cast there, and its
/// bounds reach the frustum (an orthographic light's sides only: it clamps
/// depth). A moment map takes every caster in the frustum, the floors too:
/// its filtered moments must hold the receivers' own depths beside the
/// occluders', or an edge's blur would mix the occluder with the empty far
/// plane and light the receiver under it.
bool castsInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i, bool moments);

/// The texels of `camera`'s `size`-texel map that its lookups may read:
/// the box of its lookups (LightCamera::lookups: an orthographic camera's)
/// widened by what a lookup reads around its point (marginTexels of `o`);
/// nothing when that is not known, or under a preset (the lecture's dither
/// spreads with the map's size), where the whole map may be read.
std::optional<TexelRect> lookupTexels(const LightCamera& camera, const MapOptions& o, int size);

/// The texels of `camera`'s layer that light `p`'s pass clears and draws:
/// those its lookups may read (lookupTexels), where that is known and no
/// other pass reads around every texel (moments' blur, mipmaps, the packed
/// colour's scratch depth) and the camera is the CPU's own (not fitted on
/// the GPU) and the frame allows it (FrameInfo::shadowRegions); nothing:
/// the whole layer. A stabilised cascade's square holds its slice's
/// bounding sphere, most of it sky or past the receivers' ends.
std::optional<TexelRect> drawnTexels(const FrameInfo& frame, const MapArray& g, const MapLight& p, const LightCamera& camera);

/// The texels of a `size`-texel map that `box` may cover through the
/// perspective `clipFromWorld` (a texel of margin; the whole map when a
/// corner is behind the camera): a cube face's, an atlas tile's.
TexelRect projectedRect(const glm::mat4& clipFromWorld, const Bounds& box, int size);

} // namespace shadowlab::map
