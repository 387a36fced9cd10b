// Technique "disc": its options table and catalog row (no OpenGL; the
// technique itself is techniques/Disc.cpp).
#include "techniques/Kinds.h"

#include <shadowlab/DiscOptions.h>

namespace shadowlab {

const OptionTable& discOptionTable() {
    static const OptionTable table =
        OptionTableFor<DiscOptions>("disc")
            .nodeNames(&DiscOptions::casters, "casters",
                       "the disc casters (disc shapes); empty: every casting node whose shape is a disc")
            .build();
    return table;
}

TechniqueKind discKind() {
    return {"disc", "exact shadows of flat discs in the light pass, no shadow pass or map (Ganovelli et al. exercise 8.6.2-1)", &discOptionTable()};
}

} // namespace shadowlab
