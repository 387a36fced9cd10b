// Technique "map": moment maps' constants (moments/Constants.h).
#include "techniques/map/moments/Constants.h"

namespace shadowlab::map {

MomentConstants MomentConstants::of(MapMomentFormat format) {
    if (format == MapMomentFormat::Rgba16f) return {5.54, 5.54, 1e-3, 1e-4};
    return {};
}

} // namespace shadowlab::map
