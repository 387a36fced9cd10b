#pragma once
// Technique "map": what the technique's passes share for every light of a
// frame: the texture arrays, the uniform block, the samplers, the floors
// (the passes themselves: passes/Pass2D.h, passes/CubePass.h; their
// framebuffers: passes/Targets.h).
#include "techniques/map/floors/Floors.h"
#include "techniques/map/lookup/Bindings.h"
#include "techniques/map/lookup/Block.h"
#include "techniques/map/passes/Arrays.h"

namespace shadowlab::map {

struct MapResources {
    MapArrays arrays;
    MapBlock block;
    MapSamplers samplers;
    MapFloors floors;
    bool translucent = false;  ///< the frame has translucent casters: the arrays have transmittance layers
    bool holes = false;        ///< the frame has casters with holes (alphaMode mask): the depth passes draw them through the alpha test
    bool software = false;     ///< a software rasteriser (MapSettings: bilinearGrid)
};

} // namespace shadowlab::map
