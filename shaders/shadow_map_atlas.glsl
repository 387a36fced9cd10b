// Technique "map", the light pass of one light whose map is in the shadow
// atlas (MAP_ATLAS; it fills shadow_map.glsl's "@map_filter" slot): the
// same lookup as the light list's (shadow_atlas.glsl), with the light's
// first tile, tile count and bias from the map block.
#include "shadow_atlas.glsl"

float mapVisibility(vec3 worldPosition, vec3 worldNormal, inout vec3 transmit) {
    vec3 L = normalize(map.lightPosition - worldPosition);
    vec4 shadow = vec4(map.layer, map.atlasTiles, map.normalBiasTexels, map.atlasBilinear);
    return atlasVisibility(shadow, map.lightPosition, worldPosition, worldNormal, L, clamp(dot(worldNormal, L), 0.0, 1.0));
}
