#pragma once
// Technique "map": shadow maps for directional (orthographic) and spot
// (perspective) lights, cube maps for point lights; options in
// include/shadowlab/MapOptions.h. The module's files (src/techniques/map/):
//   Map.cpp            the Technique: per frame, which light gets which
//                      array layer and cameras; each pass handed on
//   MapOptionTable.cpp the options table and the combinations refused
//   MapSettings        a light's options with its preset, and what follows
//   MapFilters         the filters as data: names, samplers, reach, kernel files
//   MapVariants        its programs as typed values, and their #defines
//   MapArrays          the texture arrays lights share, and the memory budget
//   MapLight.h         what is kept per light
//   MapCameras         the lights' cameras and the casters each one draws
//   MapSdsm            fit "sdsm": the view's depth pre-pass and its reduction
//   MapTargets.cpp     the framebuffers on each light's layers
//   MapPass2D.cpp      the shadow pass of a directional or spot light
//   MapCubePass.cpp    the shadow pass of a point light's cube
//   MapAtlas           the shadow atlas (option atlas): tiles sized from
//                      the screen, placed, kept or drawn, described for lookups
//   MapAtlasImages.cpp the atlas and each light's tiles as debug images
//   MapCasterBatch     the opaque casters in world space, one draw per tile
//   MapMoments         filterable moment maps: constants, clear, blur
//   MapTranslucent     translucent casters' transmittance layers
//   MapBlock           the uniform block (shaders/shadow_map_shared.h)
//   MapBindings        the light pass's textures and samplers
//   MapFloors          each pass's floor (a bare depth draw), for bench
//   MapRegion          where on the screen a light's shadows can fall
//   MapDebugImages     the maps, cube crosses, texel density, cascades as images
#include "techniques/Technique.h"

namespace shadowlab {

/// The registry row of "map".
TechniqueEntry mapTechnique();

} // namespace shadowlab
