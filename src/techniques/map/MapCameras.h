#pragma once
// Technique "map": each light's cameras for the frame (core/LightCamera
// fits them; the presets fix theirs) and which casters each camera draws.
#include "techniques/Technique.h"
#include "techniques/map/MapLight.h"

namespace shadowlab::map {

/// Fits `p`'s cameras for `light` (p.options and p.cube already set): a
/// cube's six faces, a spot's frustum, a directional light's box or
/// cascades, or a preset's fixed camera.
void fitCameras(MapLight& p, const Light& light, const FrameInfo& frame);

/// Whether item i is drawn into `camera`'s map: it may cast there, and its
/// bounds reach the frustum (an orthographic light's sides only: it clamps
/// depth). A moment map takes every caster in the frustum, the floors too:
/// its filtered moments must hold the receivers' own depths beside the
/// occluders', or an edge's blur would mix the occluder with the empty far
/// plane and light the receiver under it.
bool castsInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i, bool moments);

} // namespace shadowlab::map
