#pragma once
// Options of technique "volume": stencil shadow volumes (Ganovelli et al. §8.5),
// under lights[i].shadow.volume in a scene file.
#include <shadowlab/Export.h>
#include <shadowlab/Options.h>

namespace shadowlab {

enum class VolumeMethod {
    DepthFail, ///< "depth-fail": count the volume faces behind the visible surface (right with the camera inside a volume; default)
    DepthPass, ///< "depth-pass": count the faces in front of it (no caps needed; wrong when the camera is inside a volume)
    Book,      ///< "book": Ganovelli et al. §8.5's construction: extruded to a finite distance beyond the scene's box, depth-fail in two passes with face culling
};

enum class VolumeOpenMeshes {
    Facing,    ///< "facing": the light-facing triangles cast, their open edges extruded like silhouettes (default)
    Triangles, ///< "triangles": every triangle its own closed volume (exact for any triangle soup; far more fill)
};

enum class VolumeExtrusion {
    Gpu, ///< "gpu": a geometry shader over GL_TRIANGLES_ADJACENCY finds the silhouettes and extrudes them (default)
    Cpu, ///< "cpu": the same, on the CPU every frame, into a vertex buffer
};

/// Technique "volume"'s options. What each one does and its default are
/// documented once, in the options table (`shadowlab techniques`,
/// docs/techniques/volume.md); a field's comment here gives its unit and
/// default only.
struct VolumeOptions {
    static constexpr const char* kTechnique = "volume";
    VolumeMethod method = VolumeMethod::DepthFail;
    VolumeOpenMeshes openMeshes = VolumeOpenMeshes::Facing;
    VolumeExtrusion extrusion = VolumeExtrusion::Gpu;
};

/// The options table of "volume".
SHADOWLAB_API const OptionTable& volumeOptionTable();

} // namespace shadowlab
