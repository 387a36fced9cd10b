// Technique "map", the shadow atlas: its units, its tiles' buffer and a
// tile's layout, shared by its C++ (src/techniques/map/atlas/) and its
// GLSL (shadow_atlas.glsl).
#ifndef SHADOWLAB_SHADOW_ATLAS_SHARED_H
#define SHADOWLAB_SHADOW_ATLAS_SHARED_H

#include "shadowlab_shared.h"

#define SL_UNIT_ATLAS SL_UNIT_SHADOW_FIRST               // the shadow atlas's depth, nearest
#define SL_UNIT_ATLAS_COMPARE (SL_UNIT_SHADOW_FIRST + 1) // the same, through a bilinear comparison sampler
#define SL_STORAGE_ATLAS_TILES SL_STORAGE_LIST_SHADOW    // AtlasTile[]: the atlas's tiles

// A listed light's ListedLight.shadow, in the atlas: x its first
// AtlasTile, y its tiles (0: no shadow, 1: a spot's map, 6: a point
// light's faces), z normal offset in texels, w 1: a bilinear compare
// (filter hardware), 0: the nearest texel.

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadowlab::shared {
#endif

// The shadow atlas's constant bias: receivers are moved this many of the
// tile's texels towards the light (shadow_atlas.glsl says why).
#define SL_ATLAS_CONSTANT_TEXELS 0.5

// One tile of the shadow atlas (std430): a spot's map or one face of a
// point light's cube (+X, -X, +Y, -Y, +Z, -Z in that order).
struct AtlasTile {
    SL_MAT4 atlasFromWorld; // the tile's camera, then into its place: atlas uv in xy, window depth (0..1) in z, after /w; w the distance along the camera's axis
    SL_VEC4 uvClamp;        // the centres of the tile's outermost texels, atlas uv: min in xy, max in zw
    SL_VEC4 casters;        // where casters may have been drawn, atlas uv (min xy, max zw), a texel inside what was cleared: lit outside
    SL_VEC4 params;         // x a texel's world size per unit of w, y 1 when casters were drawn into it (0: lit everywhere), zw unused
};

#ifdef __cplusplus
} // namespace shadowlab::shared
#endif
#endif
