#pragma once
// Technique "map": what the technique's passes share for every light of a
// frame: the texture arrays, the uniform block, the samplers, the floors.
#include "techniques/map/MapArrays.h"
#include "techniques/map/MapBindings.h"
#include "techniques/map/MapBlock.h"
#include "techniques/map/MapFloors.h"

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

/// A directional or spot light's shadow pass: its map (or each cascade)
/// cleared and drawn, blurred (moments), the translucent layers, mipmaps.
void renderMapPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, MapLight& p);
/// A point light's cube: its faces cleared where they hold or will hold
/// casters, then the casters drawn once through the geometry shader (each
/// triangle to the faces it touches) or once per face they touch.
void renderCubePass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, MapLight& p);
/// Attaches the light's layer to its framebuffers when the array or the
/// layer changed (a new array gets a new framebuffer: the old one may still
/// name the deleted texture).
void attachTargets(MapLight& p, const MapArray& g);

} // namespace shadowlab::map
