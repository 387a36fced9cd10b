// The shadow atlas's lookup (technique map with `atlas`): a light's map is
// a tile of one depth texture, a point light's cube six tiles, one per
// face (src/techniques/map/atlas/Atlas.cpp places and draws them). Shared by
// the light list's lookup (shadow_atlas_list.glsl, which fills lighting.frag's
// "@list_shadow" slot) and the map technique's own pass for one such light
// (shadow_map_atlas.glsl).
#ifndef SHADOW_ATLAS_GLSL
#define SHADOW_ATLAS_GLSL

#include "shadow_atlas_shared.h"

layout(std430) SL_BINDING(SL_STORAGE_ATLAS_TILES) readonly buffer AtlasTiles { AtlasTile atlasTiles[]; };
SL_BINDING(SL_UNIT_ATLAS) uniform sampler2D atlasDepth;
SL_BINDING(SL_UNIT_ATLAS_COMPARE) uniform sampler2DShadow atlasCompare;

// The cube face direction d falls in, as a cube map picks it: the axis of
// its largest component, + or - (0..5: +X, -X, +Y, -Y, +Z, -Z).
uint atlasFace(vec3 d) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x > 0.0 ? 0u : 1u;
    if (a.y >= a.z) return d.y > 0.0 ? 2u : 3u;
    return d.z > 0.0 ? 4u : 5u;
}

// Visibility (1 lit, 0 shadowed) of point p with normal n for a light at
// `lightPosition` in the unit direction L from p, whose N.L there is NdotL, with `shadow` as
// ListedLight.shadow. The point is moved along its normal by the normal
// offset (shadow.z texels of the tile, their world size where p is, times
// 1 - N.L) and towards the light by SL_ATLAS_CONSTANT_TEXELS texels: the
// position interpolated over a large receiver (a 50 m floor in two
// triangles) is a millimetre or so off on llvmpipe, more than a polygon
// offset's depth steps cover where the surface faces the light (the
// light's own maps interpolate light-space coordinates per vertex
// instead, exact on a flat triangle; a pass over many lights cannot). The
// tile's polygon offset adds its slope term when it is drawn. Lookups stay
// inside the tile (its outermost texels' centres); outside the rectangle
// its casters may cover (AtlasTile.casters) the point is lit (the texels
// there were neither cleared nor drawn this frame). Past the count, every
// step runs and the answer is dropped where the point is lit, with no early
// return: a rasteriser that runs both sides of a branch (llvmpipe) pays for
// a return's masks, here once per listed light and pixel.
float atlasVisibility(vec4 shadow, vec3 lightPosition, vec3 p, vec3 n, vec3 L, float NdotL) {
    uint count = uint(shadow.y);
    if (count == 0u) return 1.0;  // no tile this frame: none to read
    uint t = uint(shadow.x);
    if (count == 6u) t += atlasFace(p - lightPosition);
    mat4 m = atlasTiles[t].atlasFromWorld;
    float texel = atlasTiles[t].params.x * max((m * vec4(p, 1.0)).w, 0.0);
    vec3 q = p + n * (shadow.z * texel * (1.0 - NdotL)) + L * (SL_ATLAS_CONSTANT_TEXELS * texel);
    vec4 c = m * vec4(q, 1.0);
    // Lit: no caster in this tile, or behind a spot's camera (outside its cone).
    bool lit = atlasTiles[t].params.y == 0.0 || !(c.w > 0.0);
    vec3 s = c.xyz / (lit ? 1.0 : c.w);
    vec4 box = atlasTiles[t].uvClamp;
    vec2 uv = clamp(s.xy, box.xy, box.zw);
    // Only the texels casters may cover were cleared and drawn: lit elsewhere.
    vec4 drawn = atlasTiles[t].casters;
    lit = lit || any(lessThan(uv, drawn.xy)) || any(greaterThan(uv, drawn.zw));
    float v = shadow.w > 0.5 ? texture(atlasCompare, vec3(uv, s.z))
                             : (s.z <= texelFetch(atlasDepth, ivec2(uv * vec2(textureSize(atlasDepth, 0))), 0).r ? 1.0 : 0.0);
    return lit ? 1.0 : v;
}

#endif
