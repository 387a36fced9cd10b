// Technique "map", the light pass for 2D maps (directional and spot lights,
// one map or cascades; shadow_map.glsl includes it unless MAP_CUBE). The
// vertex goes to the light's texture space through one matrix (the bias
// matrix times the light's projection and view; shadow_map_vertex.glsl,
// which also applies the normal offset and the filter's receiver-plane
// bias), and the fragment, after the perspective divide, is compared with
// the map by the filter's kernel (shadow_map_filter_*.glsl): in hardware
// through a sampler2DArrayShadow, or unpacked from RGBA8 and compared here
// (MAP_RGBA8), or bounded from moments (shadow_map_moments.glsl).
// Cascades (MAP_CASCADES > 1, directional lights): the fragment's view
// depth picks a cascade, each a layer of the array: its point scaled and
// offset from the first cascade's, taken per vertex with its offsets
// (MAP_CASCADE_AXES), or, warped or fitted on the GPU, its own matrix with
// the offsets per fragment; the far cascadeBlend share of each slice fades
// into the next.

#if MAP_MIPMAPS && MAP_MOMENTS == 0
// A mipmapped depth map: the level is read through this gradient, the
// shorter of the map point's changes per pixel (mapLevelGradient), which
// mapVisibility sets before its taps.
vec2 mapTapGradient = vec2(0.0);
#define MAP_TAP_GRAD , mapTapGradient, mapTapGradient
#define MAP_TEXTURE textureGrad
#else
#define MAP_TAP_GRAD
#define MAP_TEXTURE texture
#endif

#if MAP_MOMENTS > 0
// The moments, or the depth they are taken from (MAP_MOMENTS_FROM_DEPTH).
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2DArray mapMoments;
#elif MAP_RGBA8
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2DArray mapPacked;
// 1 where the receiver at depth `ref` is nearer than the map's occluder.
float mapTap(float layer, vec2 uv, float ref) {
    return ref <= unpackDepth(MAP_TEXTURE(mapPacked, vec3(uv, layer) MAP_TAP_GRAD)) ? 1.0 : 0.0;
}
#elif MAP_PLAIN_FETCH
// A software rasteriser: the nearest depth at level 0, compared here
// (LightPassVariant::plainFetch; the comparison sampler's LEQUAL, its border).
// One 2D map (MAP_LAYER_VIEW): a 2D view of its layer, which llvmpipe
// addresses faster than the array's layer (MapSettings: layerView).
#if MAP_LAYER_VIEW
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2D mapDepthPlain;
float mapTap(float layer, vec2 uv, float ref) { return ref <= textureLod(mapDepthPlain, uv, 0.0).r ? 1.0 : 0.0; }
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2DArray mapDepthPlain;
float mapTap(float layer, vec2 uv, float ref) { return ref <= textureLod(mapDepthPlain, vec3(uv, layer), 0.0).r ? 1.0 : 0.0; }
#endif
#elif MAP_LAYER_VIEW
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2DShadow mapDepth;
float mapTap(float layer, vec2 uv, float ref) { return MAP_TEXTURE(mapDepth, vec3(uv, ref) MAP_TAP_GRAD); }
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2DArrayShadow mapDepth;
float mapTap(float layer, vec2 uv, float ref) { return MAP_TEXTURE(mapDepth, vec4(uv, layer, ref) MAP_TAP_GRAD); }
#endif

// The map a test reads: its array layer, its camera's near and far
// planes, its texel's world size (perspective: per unit of distance), and
// the receiver's texture-space point (uv, depth) per screen pixel in x and
// y, taken where every fragment of a quad runs (PCSS's receiver-plane bias
// of the taps); whether the point is inside the map, and whether every
// fragment of the quad runs this test (MAP_QUAD_SHARED: the search shared
// by the quad).
struct MapLookup {
    float layer;
    vec2 planes;
    float texelWorld;
    vec3 dx, dy;
    bool inside;
    bool quad;
};
MapLookup mapLookup(float layer) { return MapLookup(layer, vec2(0.0, 1.0), 0.0, vec3(0.0), vec3(0.0), true, true); }

// A stored depth as distance along the light (perspective: linearised).
float mapDistance(float depth, vec2 planes) {
    float n = planes.x, f = planes.y;
    if (map.perspective > 0.5) return perspectiveDistance(depth, n, f);
    return n + depth * (f - n);
}

// Translucent casters (alphaMode blend): the layer's transmittance and the
// nearest translucent depth (shadow_map_transmit.frag); a receiver behind
// that depth gets the light through them, coloured.
SL_BINDING(SL_UNIT_SHADOW_FIRST + 2) uniform sampler2DArray mapTransmitColour;
SL_BINDING(SL_UNIT_SHADOW_FIRST + 3) uniform sampler2DArray mapTransmitDepth;
vec3 transmittanceAt(float layer, vec2 uv, float ref) {
#if MAP_TRANSMIT
    float nearest = texture(mapTransmitDepth, vec3(uv, layer)).r;
    return ref > nearest ? texture(mapTransmitColour, vec3(uv, layer)).rgb : vec3(1.0);
#else
    return vec3(1.0);  // no translucent casters this frame (LightPassVariant::transmittance)
#endif
}

// The filtered test at map point `uv` for reference depth `ref` (the filter's kernel file).
float mapFilter(MapLookup m, vec2 uv, float ref);

// The test in a map, at texture-space point s (before the divide);
// `transmit` becomes the translucent casters' transmittance there (left as
// it was outside the map). Outside the map, behind a perspective light or
// beyond its far plane: lit, never falsely shadowed (Navarro Rosales). The filter runs
// there too and its answer is dropped, with no early return: a rasteriser
// that runs both sides of a branch (llvmpipe) paid for the return's masks
// (0.1-0.2 ms of an 800x600 frame), and PCSS's quad-shared search needs
// every fragment of the quad to run it anyway (m.inside: no share).
float mapTest(MapLookup m, vec4 s, float NdotL, inout vec3 transmit) {
    m.inside = s.w > 0.0;
    s.xyz /= m.inside ? s.w : 1.0;
#if MAP_OUTSIDE_REPEAT
    // outside "repeat" (LearnOpenGL's over-sampling): the map tiled, and a
    // point past its far plane compared as it is, deeper than any depth
    // stored, so shadowed.
    s.xy = fract(s.xy);
#else
    m.inside = m.inside && all(greaterThanEqual(s.xy, vec2(0.0))) && all(lessThanEqual(s.xy, vec2(1.0))) && s.z <= 1.0;
#endif
    float ref = s.z - map.constantBias;
#if MAP_PRESET_BIAS
    // LearnOpenGL's own bias, slope-scaled, in place of the offsets (the preset).
    ref -= max(map.slopeDepthBias * (1.0 - NdotL), map.minDepthBias);
#endif
    if (m.inside) transmit = transmittanceAt(m.layer, s.xy, ref);
    float v = mapFilter(m, s.xy, ref);
    return m.inside ? v : 1.0;
}

#if MAP_CASCADES > 1
// Cascade c's test: the offsets of shadow_map_vertex.glsl, here per
// fragment with the cascade's own texel size; or, where the cascades share
// one light view (MAP_CASCADE_AXES), the point and its offsets per texel
// taken per vertex in the first cascade's texture space
// (shadow_map_vertex.glsl), scaled and offset to cascade c's
// (MapBlock: cascadeScale, cascadeOffset, whose w is c's texel).
// `quad`: every fragment of the quad runs this test (the slice's own, not
// the fade into the next). `dx`, `dy`: the point's change per pixel, in
// the world (MAP_CASCADE_AXES: in the first cascade's texture space).
#if MAP_CASCADE_AXES
in vec3 vCascadePoint;
in vec3 vCascadeOffset;
in vec2 vCascadeAxes;
#endif
float cascadeTest(int c, bool quad, vec3 worldPosition, vec3 n, float NdotL, float tanTheta, vec3 dx, vec3 dy, inout vec3 transmit) {
#if MAP_CASCADE_AXES
    vec4 scale = map.cascadeScale[c], offset = map.cascadeOffset[c];
    MapLookup m = mapLookup(map.layer + float(c));
    m.quad = quad;
    m.texelWorld = max(offset.w, scale.w);
    m.planes = map.cascadeRange[c].xy;
    m.dx = scale.xyz * dx;
    m.dy = scale.xyz * dy;
    float texel = dot(vec2(offset.w, scale.w), vCascadeAxes);  // the x and y texels, weighed by the normal
#if MAP_MIPMAPS
    texel *= mapLevelScale(scale.xy * dx.xy, scale.xy * dy.xy);
    mapTapGradient = mapLevelGradient(scale.xy * dx.xy, scale.xy * dy.xy);
#endif
    return mapTest(m, vec4(scale.xyz * (vCascadePoint + texel * vCascadeOffset) + offset.xyz, 1.0), NdotL, transmit);
#else
    float texel = mapAxesTexel(map.cascadeShadowFromWorld[c], n);  // its x and y texels weighed by the normal
#if MAP_WARP
    if (map.warpU > 0.0) texel = mapWarpedTexel(map.cascadeWarpPlane[c], map.cascadeWarp[c].xy, worldPosition, n);  // warped cascades
#endif
#if MAP_MIPMAPS
    mat3 toUv = mat3(map.cascadeShadowFromWorld[c]);
    texel *= mapLevelScale((toUv * dx).xy, (toUv * dy).xy);
    mapTapGradient = mapLevelGradient((toUv * dx).xy, (toUv * dy).xy);
#endif
    vec3 p = mapReceiverPlaneOffset(mapNormalOffset(worldPosition, n, NdotL, texel), map.towardsLight, texel, tanTheta);
    MapLookup m = mapLookup(map.layer + float(c));
    m.quad = quad;
    m.texelWorld = texel;
    m.planes = map.cascadeRange[c].xy;
    mat3 affine = mat3(map.cascadeShadowFromWorld[c]);  // orthographic: the point's change is linear
    m.dx = affine * dx;
    m.dy = affine * dy;
    return mapTest(m, map.cascadeShadowFromWorld[c] * vec4(p, 1.0), NdotL, transmit);
#endif
}

// The shadow test's visibility, 0 (shadowed) to 1 (lit): the slice's
// cascade, fading into the next one over the far `blend` share of the
// slice; `transmit`, the translucent casters' transmittance (the last
// cascade tested).
float mapVisibility(vec3 worldPosition, vec3 worldNormal, inout vec3 transmit) {
    vec3 n = worldNormal;
    float NdotL = clamp(dot(n, map.towardsLight), 0.0, 1.0);
    float tanTheta = mapTanTheta(n, map.towardsLight, NdotL);
#if MAP_CASCADE_AXES
    vec3 dx = dFdx(vCascadePoint), dy = dFdy(vCascadePoint);
#else
    vec3 dx = dFdx(worldPosition), dy = dFdy(worldPosition);
#endif
    float depth = cascadeDepth(worldPosition);
    int c = cascadeOf(depth);
    float t = c < MAP_CASCADES - 1 ? cascadeBlend(depth, c) : 0.0;
    // The slice's test, then the next cascade's where the slice fades into
    // it: rounds of a loop whose count (2) comes from the block, so that the
    // compiler keeps it and a rasteriser that runs both sides of a branch
    // (llvmpipe) skips the second round for a group of pixels none of which
    // fades, as it could not skip an if's.
    float v = 1.0, next = 1.0;
    int rounds = int(map.cascadeRounds);
    for (int r = 0; r < rounds; ++r) {
        float tested = cascadeTest(min(c + r, MAP_CASCADES - 1), r == 0, worldPosition, n, NdotL, tanTheta, dx, dy, transmit);
        if (r == 0) v = tested;
        else next = tested;
        if (t <= 0.0) break;
    }
    return t > 0.0 ? mix(v, next, min(t, 1.0)) : v;
}
#else
in vec4 vShadowCoord;   // from shadow_map_vertex.glsl: the offset point in texture space
#if MAP_MIPMAPS
in vec4 vShadowOffset;  // and the offsets in it, at level 0's texel
#endif
#if MAP_PRESET_BIAS
in float vShadowNdotL;  // N.L at the vertex, for the preset's slope-scaled bias
#endif
#if MAP_RAY_DEPTH_OFFSET
in float vShadowDepthOffset;  // the receiver-plane offset as a change of vShadowCoord.z
#endif

// The shadow test's visibility, 0 (shadowed) to 1 (lit); `transmit`, the
// translucent casters' transmittance.
float mapVisibility(vec3 worldPosition, vec3 worldNormal, inout vec3 transmit) {
    MapLookup m = mapLookup(map.layer);
    vec4 shadowCoord = vShadowCoord;
#if MAP_RAY_DEPTH_OFFSET
    // A perspective map: the receiver-plane offset as a change of the
    // depth along the fragment's own ray (shadow_map_vertex.glsl).
    shadowCoord.z += vShadowDepthOffset;
#endif
    m.texelWorld = map.texelWorld;
    m.planes = vec2(map.nearPlane, map.farPlane);
    vec3 q = shadowCoord.xyz / shadowCoord.w;
    m.dx = dFdx(q);
    m.dy = dFdy(q);
    vec4 coord = shadowCoord;
#if MAP_MIPMAPS
    // The offsets reach the texel of the level read (shadow_map_bias.glsl).
    vec2 uv = shadowCoord.xy / shadowCoord.w;
    float levelScale = mapLevelScale(dFdx(uv), dFdy(uv)) - 1.0;
    mapTapGradient = mapLevelGradient(dFdx(uv), dFdy(uv));
    coord += levelScale * vShadowOffset;
#if MAP_RAY_DEPTH_OFFSET
    coord.z += levelScale * vShadowDepthOffset;
#endif
#endif
#if MAP_PRESET_BIAS
    return mapTest(m, coord, vShadowNdotL, transmit);
#else
    return mapTest(m, coord, 1.0, transmit);
#endif
}
#endif
