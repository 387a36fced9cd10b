#pragma once
// Technique "map": what its light pass reads (shaders/shadow_map.glsl):
// the light's array on SL_UNIT_SHADOW_FIRST through the sampler its filter
// takes, PCSS's raw depths beside it, the translucent casters' layers.
#include "gl/Object.h"
#include "techniques/map/Light.h"
#include "techniques/map/options/Settings.h"
#include "techniques/map/passes/Arrays.h"

namespace shadowlab::map {

/// The samplers the light pass reads maps through (made once per context).
struct MapSamplers {
    gl::Sampler compareNearest{gl::NoCreate}, compareLinear{gl::NoCreate}, plainNearest{gl::NoCreate};
    gl::Sampler compareNearestMip{gl::NoCreate}, compareLinearMip{gl::NoCreate}, plainNearestMip{gl::NoCreate};
    gl::Sampler momentLinear{gl::NoCreate}, momentLinearMip{gl::NoCreate};
    /// For cube maps of reversed window depth (MapSettings: cubeWindowDepth).
    gl::Sampler compareNearestGreater{gl::NoCreate}, compareLinearGreater{gl::NoCreate};
    /// Makes them (once; a no-op after).
    void create();
};

/// Binds light `p`'s map (in array `g`) for the light pass. `translucent`:
/// the frame's arrays hold transmittance layers; `bilinearGrid`: the grid
/// filter takes bilinear compares (MapSettings: bilinearGrid).
/// `plain`: the depths through a sampler without comparison (MapSettings: plainFetch).
void bindLightPass(const MapLight& p, const MapArray& g, const MapSamplers& samplers, bool translucent, DepthTaps taps);

} // namespace shadowlab::map
