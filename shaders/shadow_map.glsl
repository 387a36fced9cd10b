// Technique "map": a shadow map per light (lecture 000, 002 §8.2-8.4), a
// cube map per point light (001).
// 2D maps: the vertex goes to the light's texture space through one matrix
// (the bias matrix times the light's projection and view;
// shadow_map_vertex.glsl, which also applies the normal offset and the
// filter's receiver-plane bias), and the fragment, after the perspective
// divide, is compared with the map: in hardware through a
// sampler2DArrayShadow, or unpacked from RGBA8 and compared here
// (MAP_RGBA8). Cube maps (MAP_CUBE): the fragment's vector from the light
// looks the map up, its distance over the far plane is the reference (all
// per fragment). Cascades (MAP_CASCADES > 1, directional lights): the
// fragment's view depth picks a cascade, each a layer of the array with its
// own matrix, offsets applied per fragment; the far share cascade.w of each
// slice fades into the next. Variants: MAP_CUBE, MAP_CASCADES, MAP_FILTER (SL_MAP_FILTER_*),
// MAP_KERNEL (grid side), MAP_GRID_BILINEAR (the grid's comparisons from
// bilinear fetches), MAP_RGBA8. Numbers are uniforms.
#include "shadow_map_shared.h"

#if MAP_CUBE
#if MAP_RGBA8
layout(binding = SL_UNIT_SHADOW_FIRST) uniform samplerCubeArray mapCubePacked;
float cubeTap(vec3 direction, float ref) {
    return ref <= unpackDepth(texture(mapCubePacked, vec4(direction, map.params.x))) ? 1.0 : 0.0;
}
#else
layout(binding = SL_UNIT_SHADOW_FIRST) uniform samplerCubeArrayShadow mapCube;
float cubeTap(vec3 direction, float ref) { return texture(mapCube, vec4(direction, map.params.x), ref); }
#endif
#else
// The array layer the taps read: the light's map, or the cascade's.
float mapLayer = 0.0;
#if MAP_RGBA8
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2DArray mapPacked;
// 1 where the receiver at depth `ref` is nearer than the map's occluder.
float mapTap(vec2 uv, float ref) {
    return ref <= unpackDepth(texture(mapPacked, vec3(uv, mapLayer))) ? 1.0 : 0.0;
}
#else
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2DArrayShadow mapDepth;
float mapTap(vec2 uv, float ref) { return texture(mapDepth, vec4(uv, mapLayer, ref)); }
#endif
#endif

// Interleaved gradient noise (Jimenez 2014): a per-pixel rotation for the disk.
float mapNoise(vec2 pixel) { return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715)))); }

#if MAP_CUBE
// The lecture's 20 offset directions (001): far apart, none along the ray.
const vec3 kPcf20[20] = vec3[](
    vec3(1, 1, 1), vec3(1, -1, 1), vec3(-1, -1, 1), vec3(-1, 1, 1),
    vec3(1, 1, -1), vec3(1, -1, -1), vec3(-1, -1, -1), vec3(-1, 1, -1),
    vec3(1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0), vec3(-1, 1, 0),
    vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
    vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, -1, -1), vec3(0, 1, -1));

// The shadow test's visibility, 0 (shadowed) to 1 (lit).
float mapVisibility(vec3 worldPosition, vec3 worldNormal) {
    vec3 toLight = map.light.xyz - worldPosition;
    float d = length(toLight);
    if (d <= 0.0) return 1.0;
    vec3 L = toLight / d;
    vec3 n = worldNormal;
    float NdotL = clamp(dot(n, L), 0.0, 1.0);
    // World size of one texel at this distance (largest at a face's centre).
    float texel = d * map.cube.z;
    // Filter radius at the fragment, growing with the viewer's distance (001).
    float radius = map.cube.w * (1.0 + map.cubeMore.x * length(frame.cameraPosition.xyz - worldPosition) / map.cube.x);
#if MAP_FILTER == SL_MAP_FILTER_NONE
    float reachWorld = 0.0;
#elif MAP_FILTER == SL_MAP_FILTER_HARDWARE
    float reachWorld = texel;
#elif MAP_FILTER == SL_MAP_FILTER_GRID
    float reachWorld = radius * 1.7320508;  // the grid's corners
#elif MAP_FILTER == SL_MAP_FILTER_PCF20
    float reachWorld = radius * 1.7320508;  // |(1, 1, 1)| x radius
#else
    float reachWorld = radius;
#endif
    vec3 p = worldPosition;
    float ref;
    if (map.cubeMore.z > 0.5) {
        // The presets: their constant bias only (in stored-depth units).
        ref = length(p - map.light.xyz) / map.cube.x - map.bias.x;
    } else {
        // Normal offset: `normalBias` texels times 1 - N.L, along the normal;
        // then the receiver-plane bias for the filter's reach (as for 2D maps).
        p += n * (map.bias.w * texel * (1.0 - NdotL));
        float tanTheta = min(length(cross(n, L)) / max(NdotL, 1e-4), 10.0);
        ref = (length(p - map.light.xyz) - reachWorld * tanTheta) / map.cube.x - map.bias.x;
    }
    vec3 v = p - map.light.xyz;
    // Beyond the far plane: lit (004).
    if (length(v) > map.cube.x) return 1.0;
#if MAP_FILTER == SL_MAP_FILTER_NONE || MAP_FILTER == SL_MAP_FILTER_HARDWARE
    return cubeTap(v, ref);  // the sampler is nearest or bilinear (seamless)
#elif MAP_FILTER == SL_MAP_FILTER_GRID
    // The lecture's 3-D grid (001): MAP_KERNEL^3 offsets evenly from -radius
    // to +radius on each axis (64 for kernel 4).
    float sum = 0.0;
    float step = MAP_KERNEL > 1 ? 2.0 * radius / float(MAP_KERNEL - 1) : 0.0;
    for (int z = 0; z < MAP_KERNEL; ++z)
        for (int y = 0; y < MAP_KERNEL; ++y)
            for (int x = 0; x < MAP_KERNEL; ++x)
                sum += cubeTap(v + (vec3(x, y, z) * step - vec3(MAP_KERNEL > 1 ? radius : 0.0)), ref);
    return sum / float(MAP_KERNEL * MAP_KERNEL * MAP_KERNEL);
#elif MAP_FILTER == SL_MAP_FILTER_PCF20
    float sum = 0.0;
    for (int k = 0; k < 20; ++k) sum += cubeTap(v + kPcf20[k] * radius, ref);
    return sum / 20.0;
#elif MAP_FILTER == SL_MAP_FILTER_POISSON
    // A Vogel disk across the ray (no taps wasted along it), rotated per pixel.
    vec3 axis = normalize(v);
    vec3 t = normalize(abs(axis.y) < 0.99 ? cross(axis, vec3(0.0, 1.0, 0.0)) : cross(axis, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(axis, t);
    int taps = int(map.taps.z);
    float rotation = 6.2831853 * mapNoise(gl_FragCoord.xy);
    float sum = 0.0;
    for (int k = 0; k < taps; ++k) {
        float r = sqrt((float(k) + 0.5) / float(taps)) * radius;
        float a = float(k) * 2.3999632 + rotation;
        sum += cubeTap(v + r * (cos(a) * t + sin(a) * b), ref);
    }
    return sum / float(taps);
#else
#error this MAP_FILTER is for 2D maps
#endif
}
#else
// The filtered test at map point `uv` for reference depth `ref`, in layer mapLayer.
float mapFilter(vec2 uv, float ref);

// The test in a map, at texture-space point s (before the divide).
float mapTest(vec4 s, float NdotL) {
    if (s.w <= 0.0) return 1.0;
    s.xyz /= s.w;
    // Outside the map or beyond its far plane: lit, never falsely shadowed (004).
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0))) || s.z > 1.0) return 1.0;
    return mapFilter(s.xy, s.z - map.bias.x - max(map.bias.y * (1.0 - NdotL), map.bias.z));
}

#if MAP_CASCADES > 1
// Cascade c's test: the offsets of shadow_map_vertex.glsl, here per
// fragment with the cascade's own texel size.
float cascadeTest(int c, vec3 worldPosition, vec3 n, float NdotL, float tanTheta) {
    float texel = map.cascadeTexel[c >> 2][c & 3];
    vec3 p = worldPosition + n * (map.bias.w * texel * (1.0 - NdotL)) + map.light.xyz * (map.params.y * texel * tanTheta);
    mapLayer = map.params.x + float(c);
    return mapTest(map.cascadeShadowFromWorld[c] * vec4(p, 1.0), NdotL);
}

// The shadow test's visibility, 0 (shadowed) to 1 (lit): the slice's
// cascade, fading into the next one over the far `blend` share of the slice.
float mapVisibility(vec3 worldPosition, vec3 worldNormal) {
    vec3 n = worldNormal;
    float NdotL = clamp(dot(n, map.light.xyz), 0.0, 1.0);
    float tanTheta = min(length(cross(n, map.light.xyz)) / max(NdotL, 1e-4), 10.0);
    float depth = cascadeDepth(worldPosition);
    int c = cascadeOf(depth);
    float v = cascadeTest(c, worldPosition, n, NdotL, tanTheta);
    if (c < MAP_CASCADES - 1) {
        float far = cascadeFarOf(c);
        float band = map.cascade.w * (far - (c > 0 ? cascadeFarOf(c - 1) : 0.0));
        float t = band > 0.0 ? (depth - (far - band)) / band : 0.0;
        if (t > 0.0) v = mix(v, cascadeTest(c + 1, worldPosition, n, NdotL, tanTheta), min(t, 1.0));
    }
    return v;
}
#else
in vec4 vShadowCoord;   // from shadow_map_vertex.glsl: the offset point in texture space
in float vShadowNdotL;

// The shadow test's visibility, 0 (shadowed) to 1 (lit).
float mapVisibility(vec3 worldPosition, vec3 worldNormal) {
    mapLayer = map.params.x;
    return mapTest(vShadowCoord, vShadowNdotL);
}
#endif

float mapFilter(vec2 uv, float ref) {
    float du = map.taps.x;
#if MAP_FILTER == SL_MAP_FILTER_NONE || MAP_FILTER == SL_MAP_FILTER_HARDWARE
    return mapTap(uv, ref);  // the sampler is nearest or bilinear
#elif MAP_FILTER == SL_MAP_FILTER_GRID && !MAP_GRID_BILINEAR
    // MAP_KERNEL x MAP_KERNEL nearest taps one texel apart, centred on the point.
    float sum = 0.0;
    float start = -0.5 * float(MAP_KERNEL - 1);
    for (int j = 0; j < MAP_KERNEL; ++j)
        for (int i = 0; i < MAP_KERNEL; ++i)
            sum += mapTap(uv + du * vec2(start + float(i), start + float(j)), ref);
    return sum / float(MAP_KERNEL * MAP_KERNEL);
#elif MAP_FILTER == SL_MAP_FILTER_GRID
    // The same MAP_KERNEL x MAP_KERNEL nearest taps, from as few bilinear
    // hardware compares as the kernel allows: the nearest taps read the N
    // consecutive texels from k0 = floor(t - (N - 1) / 2) on each axis (t:
    // the point in texel units). A bilinear compare at the corner between two
    // texels averages exactly those two, one at a texel's centre reads that
    // texel alone; so pairs of texels take one tap of weight 2, an odd last
    // texel one tap of weight 1: ceil(N / 2)^2 taps (4 for 3x3, 16 for 8x8)
    // give the box average of the N^2 comparisons.
    vec2 t = uv / du;
    vec2 k0 = floor(t - 0.5 * float(MAP_KERNEL - 1));
    const int taps = (MAP_KERNEL + 1) / 2;
    float sum = 0.0;
    for (int j = 0; j < taps; ++j) {
        bool pairY = 2 * j + 1 < MAP_KERNEL;
        float wy = pairY ? 2.0 : 1.0;
        float y = k0.y + float(2 * j) + (pairY ? 1.0 : 0.5);
        for (int i = 0; i < taps; ++i) {
            bool pairX = 2 * i + 1 < MAP_KERNEL;
            float wx = pairX ? 2.0 : 1.0;
            float x = k0.x + float(2 * i) + (pairX ? 1.0 : 0.5);
            sum += wx * wy * mapTap(vec2(x, y) * du, ref);
        }
    }
    return sum / float(MAP_KERNEL * MAP_KERNEL);
#elif MAP_FILTER == SL_MAP_FILTER_DITHER4
    // The lecture's 4-sample dithered PCF (000): one of four patterns from
    // gl_FragCoord mod 2, taps `spread` texels apart.
    float w = map.taps.w * du;
    vec2 o = mod(floor(gl_FragCoord.xy), 2.0) * w;
    float sum = mapTap(uv + vec2(-1.5 * w + o.x, 1.5 * w - o.y), ref) + mapTap(uv + vec2(-1.5 * w + o.x, -0.5 * w - o.y), ref) +
                mapTap(uv + vec2(0.5 * w + o.x, 1.5 * w - o.y), ref) + mapTap(uv + vec2(0.5 * w + o.x, -0.5 * w - o.y), ref);
    return 0.25 * sum;
#elif MAP_FILTER == SL_MAP_FILTER_POISSON
    // A Vogel disk (golden-angle spiral, uniform by area) rotated per pixel.
    int taps = int(map.taps.z);
    float rotation = 6.2831853 * mapNoise(gl_FragCoord.xy);
    float sum = 0.0;
    for (int k = 0; k < taps; ++k) {
        float r = sqrt((float(k) + 0.5) / float(taps)) * map.taps.y;
        float a = float(k) * 2.3999632 + rotation;
        sum += mapTap(uv + du * r * vec2(cos(a), sin(a)), ref);
    }
    return sum / float(taps);
#else
#error unknown MAP_FILTER
#endif
}
#endif

vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    float v = mapVisibility(worldPosition, worldNormal);
#if !OUTPUT_VISIBILITY
    // The look of lecture 002 listing 8.4 (color *= 0.6 in shadow) when
    // shadowedLight > 0; compare reads the test itself (OUTPUT_VISIBILITY).
    v = mix(map.light.w, 1.0, v);
#endif
    return vec3(v);
}
