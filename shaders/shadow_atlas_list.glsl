// Technique "map": the light list's shadow lookup (lighting.frag's
// "@list_shadow" slot, Technique::listShadowFile): the shadow atlas's, for
// listed lights with `atlas`.
#include "shadow_atlas.glsl"

// Visibility (1 lit, 0 shadowed) of point p with normal n for a listed light
// at `lightPosition`, in the unit direction L from p, N.L there NdotL, its
// ListedLight.shadow `shadow` (shadow_atlas_shared.h says what it holds).
float listedVisibility(vec4 shadow, vec3 lightPosition, vec3 p, vec3 n, vec3 L, float NdotL) {
    return atlasVisibility(shadow, lightPosition, p, n, L, NdotL);
}
