// Technique "map": a shadow map per light (Wolberg's lecture, Ganovelli et al. §8.2-8.4), a
// cube map per point light (Lawonn); the light pass's visibility hook. The
// variant (src/techniques/map/Variants.h: LightPassVariant) picks the
// path and the kernel: MAP_CUBE (a point light's cube map) or a 2D map
// with MAP_CASCADES maps; MAP_FILTER (SL_MAP_FILTER_*, one kernel file
// each), MAP_KERNEL (grid side), MAP_GRID_BILINEAR (the grid's
// comparisons from bilinear fetches), MAP_RGBA8/MAP_R8 (depth packed into
// colour), MAP_MOMENTS (SL_MAP_MOMENTS_*, a filterable moment map),
// MAP_ATLAS (a spot's or point light's tiles of the shadow atlas).
// Numbers are uniforms (shadow_map_shared.h's block).
#include "shadow_map_shared.h"
#include "shadow_map_sampling.glsl"
#include "shadow_map_bias.glsl"

#if MAP_QUAD_SHARED
// PCSS's blocker search is shared by each 2x2 quad through derivatives
// (shadow_map_sampling.glsl): the light pass runs the test where every
// fragment of the quad does (lighting.frag).
#define SHADOW_QUAD_UNIFORM 1
#endif

#if MAP_ATLAS
// A tile of the shadow atlas: the "@map_filter" slot is shadow_map_atlas.glsl.
#elif MAP_CUBE
#include "shadow_map_cube_lookup.glsl"
#else
#include "shadow_map_2d.glsl"
#endif

// The filter's kernel (shadow_map_filter_<name>.glsl, for both kinds of
// map) or a moment map's bound (shadow_map_moments.glsl): the variant
// fills the slot (LightPassVariant::kernelFile).
#include "@map_filter"

vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    vec3 transmit = vec3(1.0);  // coloured by the translucent casters in the way
    float v = mapVisibility(worldPosition, worldNormal, transmit);
#if !OUTPUT_VISIBILITY
    // The look of Ganovelli et al. listing 8.4 (color *= 0.6 in shadow) when
    // shadowedLight > 0; compare reads the test itself (OUTPUT_VISIBILITY).
    v = mix(map.shadowedLight, 1.0, v);
#endif
    return v * transmit;
}
