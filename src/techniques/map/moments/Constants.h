#pragma once
// Technique "map": moment maps' constants (VSM, EVSM, MSM; shaders
// shadow_map_shared.h momentsOf, shadow_map.glsl momentVisibility), which
// the programs that write or read moments get as defines (Variants.h).
#include <shadowlab/MapOptions.h>

namespace shadowlab::map {

/// The exponents of EVSM's warps (32-bit floats: 40 and 40, under the
/// about 42 that e^(2c) allows; a negative 5, as MJP's sample, left 0.054 %
/// false lit on cascades-field against 0.040 %; 16-bit: 5.54 each, the
/// most e^(2c) allows under 65504) and
/// MSM's and VSM's floors; every program that writes or reads moments gets
/// them as defines (Variants.h), the clear colour is made from them.
struct MomentConstants {
    double evsmPositive = 40.0;  ///< MAP_EVSM_POSITIVE
    double evsmNegative = 40.0;  ///< MAP_EVSM_NEGATIVE
    double momentBias = 3e-6;    ///< MAP_MOMENT_BIAS: MSM's pull towards the middle (32-bit: 3e-5 leaked 0.67 % at casters' feet on cascades-field; 1e-6 and less turn two-depth regions noisy)
    double minVariance = 1e-6;   ///< MAP_MIN_VARIANCE: VSM's floor
    static MomentConstants of(MapMomentFormat format);
};

} // namespace shadowlab::map
