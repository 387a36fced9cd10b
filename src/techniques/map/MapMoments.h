#pragma once
// Technique "map": filterable moment maps (VSM, EVSM, MSM; shaders
// shadow_map_shared.h momentsOf, shadow_map.glsl momentVisibility): their
// constants, and a layer's moments made from its depth and blurred.
#include "techniques/Technique.h"
#include "techniques/map/MapArrays.h"
#include "techniques/map/MapBlock.h"

#include <glm/glm.hpp>

#include <string>

namespace shadowlab::map {

/// The exponents of EVSM's warps (32-bit floats: 40 and 40, under the
/// about 42 that e^(2c) allows; a negative 5, as MJP's sample, left 0.054 %
/// false lit on cascades-field against 0.040 %; 16-bit: 5.54 each, the
/// most e^(2c) allows under 65504) and
/// MSM's and VSM's floors; every program that writes or reads moments gets
/// them as defines (MapVariants), the clear colour is made from them.
struct MomentConstants {
    double evsmPositive = 40.0;  ///< MAP_EVSM_POSITIVE
    double evsmNegative = 40.0;  ///< MAP_EVSM_NEGATIVE
    double momentBias = 3e-6;    ///< MAP_MOMENT_BIAS: MSM's pull towards the middle (32-bit: 3e-5 leaked 0.67 % at casters' feet on cascades-field; 1e-6 and less turn two-depth regions noisy)
    double minVariance = 1e-6;   ///< MAP_MIN_VARIANCE: VSM's floor
    static MomentConstants of(MapMomentFormat format);
};
/// The moments of one layer, made from the depth its shadow pass left
/// (g.depth's layer) and blurred: across into the scratch texture, then
/// down into the moment layer; with radius 0, straight into the layer.
/// `spot`: the depth is a spot's perspective depth (linearised first).
void makeMoments(TechniqueHost& host, MapBlock& block, const MapArray& g, int layer, int radius, bool spot);

} // namespace shadowlab::map
