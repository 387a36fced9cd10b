// Technique "map", per vertex (scene.vert's "@shadow_vertex?" slot): the
// receiver's offset point in the light's texture space, so the fragment
// only divides, compares and filters (Ganovelli et al. Listing 8.3 computes
// vShadowPosition in the vertex shader too). Under a directional light the
// offsets are linear in the position over a flat triangle, so
// interpolating them is exact there; a perspective map's receiver-plane
// offset, along the ray to the light, is not, and goes on as a change of
// depth alone (MAP_RAY_DEPTH_OFFSET).
#include "shadow_map_shared.h"
#include "shadow_map_bias.glsl"
#define SHADOW_VERTEX_HOOK 1

#if MAP_CASCADE_AXES
// Cascades that share one light view (LightPassVariant::cascadeAxes): the
// point in the first cascade's texture space, and its offsets there per
// world unit of a texel; the fragment's depth picks the cascade, whose
// coordinates are a scale and an offset of these (shadow_map_2d.glsl).
out vec3 vCascadePoint;
out vec3 vCascadeOffset;
out vec2 vCascadeAxes;  // how much of the offsets' texel is the light view's x texel, and how much its y's

void shadowVertex(vec3 worldPosition, vec3 worldNormal) {
    vec3 n = worldNormal;  // as modelled (see below)
    float NdotL = clamp(dot(n, map.towardsLight), 0.0, 1.0);
    vec3 perTexel = mapReceiverPlaneOffset(mapNormalOffset(vec3(0.0), n, NdotL, 1.0), map.towardsLight, 1.0, mapTanTheta(n, map.towardsLight, NdotL));
    vCascadePoint = (map.shadowFromWorld * vec4(worldPosition, 1.0)).xyz;
    vCascadeOffset = mat3(map.shadowFromWorld) * perTexel;
    // A texel's depth change runs along the normal's direction across the
    // light: its size that way weighs the two axes' texels (a ground under a
    // low sun: the y texel, which a stabilised cascade may have finer).
    mat3 toMap = transpose(mat3(map.shadowFromWorld));  // columns: the map's x, y and depth axes in the world
    vec2 g = abs(vec2(dot(normalize(toMap[0]), n), dot(normalize(toMap[1]), n)));
    vCascadeAxes = g.x + g.y > 1e-4 ? g / (g.x + g.y) : vec2(0.5);
}
#elif MAP_CUBE || MAP_CASCADES > 1 || MAP_ATLAS
// Cube maps work per fragment (shadow_map.glsl): a point light's texel size
// and N.L change too much across a wall-sized triangle to interpolate.
// Warped cascades too, and those fitted on the GPU: the fragment's depth
// picks the cascade. The atlas's tiles: shadow_atlas.glsl, per fragment.
void shadowVertex(vec3 worldPosition, vec3 worldNormal) {}
#else

out vec4 vShadowCoord;  // map.shadowFromWorld times the offset point
#if MAP_RAY_DEPTH_OFFSET
out float vShadowDepthOffset; // a perspective map: the receiver-plane offset as a change of vShadowCoord.z
#endif
#if MAP_MIPMAPS
out vec4 vShadowOffset; // the offsets in texture space (the fragment scales them to its level)
#endif
#if MAP_PRESET_BIAS
out float vShadowNdotL; // N.L at the vertex, for the learnopengl preset's bias
#endif

void shadowVertex(vec3 worldPosition, vec3 worldNormal) {
    vec3 toLight = map.perspective > 0.5 ? normalize(map.lightPosition - worldPosition) : map.towardsLight;
    // The normal as modelled: turning it per vertex (towards the camera or
    // the light) would flip it on some vertices of a silhouette triangle and
    // not on others. A two-sided surface lit from its back gets no offset
    // there (N.L is 0), only the depth and receiver-plane biases.
    vec3 n = worldNormal;
    float NdotL = clamp(dot(n, toLight), 0.0, 1.0);
    // World size of one map texel here.
    float texel = map.texelWorld;
    // Perspective: texels grow with the depth along the light camera's axis,
    // which is affine in the position, so it interpolates exactly across
    // even a wall-sized triangle.
    if (map.perspective > 0.5) texel *= max(dot(worldPosition - map.lightPosition, map.lightAxis), 0.0);
    // A warped map (lispsm): its texel's size here (shadow_map_bias.glsl).
#if MAP_WARP
    if (map.warpU > 0.0) texel = mapWarpedTexel(map.warpPlane, vec2(map.warpU, map.warpV), worldPosition, n);
#endif
    // The normal offset, then the receiver-plane bias for the filter's reach (shadow_map_bias.glsl).
#if MAP_RAY_DEPTH_OFFSET
    // A perspective map: the receiver-plane offset moves the point towards
    // the light along its own ray, which keeps its uv and brings its depth
    // nearer, t of the way: in texture space a mix with the light's point
    // (w 0). Moved along the vertex's ray and interpolated across a large
    // triangle (a floor of two), the uv moved along it (the panel's shadow
    // on glass-panel's floor, grazed by the spot, shifted a few pixels at
    // 512^2). So the point keeps the normal offset alone, and the
    // receiver-plane offset goes as a change of the depth, which the
    // fragment adds to its own.
    vec3 p = mapNormalOffset(worldPosition, n, NdotL, texel);
    vShadowCoord = map.shadowFromWorld * vec4(p, 1.0);
    // mix(s, light, t) has the depth (s.z + t / (1 - t) light.z) / s.w: a
    // change of s.z alone, which interpolates as s does (no divide here,
    // where a vertex behind the light has w <= 0).
    float t = min(map.reachTexels * texel * mapTanTheta(n, toLight, NdotL) / max(length(map.lightPosition - p), 1e-30), 0.5);
    vShadowDepthOffset = t / (1.0 - t) * map.lightTexture.z;
#else
    vec3 p = mapReceiverPlaneOffset(mapNormalOffset(worldPosition, n, NdotL, texel), toLight, texel, mapTanTheta(n, toLight, NdotL));
    vShadowCoord = map.shadowFromWorld * vec4(p, 1.0);
#endif
#if MAP_MIPMAPS
    vShadowOffset = map.shadowFromWorld * vec4(p - worldPosition, 0.0);
#endif
#if MAP_PRESET_BIAS
    vShadowNdotL = NdotL;
#endif
}
#endif
