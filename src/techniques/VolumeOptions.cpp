// Technique "volume": its options table and catalog row (no OpenGL; the
// technique itself is techniques/Volume.cpp).
#include "techniques/Kinds.h"

#include <shadowlab/VolumeOptions.h>

namespace shadowlab {

const OptionTable& volumeOptionTable() {
    static const OptionTable table =
        OptionTableFor<VolumeOptions>("volume")
            .choice(&VolumeOptions::method, "method", {"depth-fail", "depth-pass", "book"},
                    "count the volume faces behind the visible surface (right with the camera in a shadow), or in front of it (no caps; wrong then), or Ganovelli et al. §8.5's finite extrusion counted in two culled passes")
            .choice(&VolumeOptions::extrusion, "extrusion", {"gpu", "cpu"},
                    "silhouettes found and extruded by a geometry shader, or on the CPU each frame (the same volumes; bench reports the CPU's triangles per second)")
            .choice(&VolumeOptions::openMeshes, "openMeshes", {"facing", "triangles"},
                    "a caster that is not a closed mesh: its light-facing triangles with their open edges extruded, or every triangle its own volume")
            .build();
    return table;
}

TechniqueKind volumeKind() {
    return {"volume", "stencil shadow volumes: silhouettes extruded to infinity and capped, counted depth-fail (or depth-pass)", &volumeOptionTable()};
}

} // namespace shadowlab
