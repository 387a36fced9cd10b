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
#if MAP_FILTER == SL_MAP_FILTER_PCSS
float cubeDepthAt(vec3 direction) { return unpackDepth(texture(mapCubePacked, vec4(direction, map.params.x))); }
#endif
#else
layout(binding = SL_UNIT_SHADOW_FIRST) uniform samplerCubeArrayShadow mapCube;
float cubeTap(vec3 direction, float ref) { return texture(mapCube, vec4(direction, map.params.x), ref); }
#if MAP_FILTER == SL_MAP_FILTER_PCSS
// The stored depths for PCSS's blocker search: a sampler without comparison.
layout(binding = SL_UNIT_SHADOW_FIRST + 1) uniform samplerCubeArray mapCubeRaw;
float cubeDepthAt(vec3 direction) { return texture(mapCubeRaw, vec4(direction, map.params.x)).r; }
#endif
#endif
// Translucent casters (alphaMode blend): the cube's transmittance and the
// nearest translucent depth (shadow_map_cube_transmit.frag).
layout(binding = SL_UNIT_SHADOW_FIRST + 2) uniform samplerCubeArray mapCubeTransmitColour;
layout(binding = SL_UNIT_SHADOW_FIRST + 3) uniform samplerCubeArray mapCubeTransmitDepth;
vec3 mapTransmit = vec3(1.0);
vec3 cubeTransmittanceAt(vec3 direction, float ref) {
    if (map.transmit.x < 0.5) return vec3(1.0);
    float nearest = texture(mapCubeTransmitDepth, vec4(direction, map.params.x)).r;
    return ref > nearest ? texture(mapCubeTransmitColour, vec4(direction, map.params.x)).rgb : vec3(1.0);
}
#else
// The array layer the taps read: the light's map, or the cascade's.
float mapLayer = 0.0;
#if MAP_MOMENTS > 0
layout(binding = SL_UNIT_SHADOW_FIRST) uniform sampler2DArray mapMoments;
#elif MAP_RGBA8
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

#if !MAP_CUBE && (MAP_FILTER == SL_MAP_FILTER_PCSS || MAP_MOMENTS > 0)
#if MAP_FILTER == SL_MAP_FILTER_PCSS
// PCSS reads stored depths in its blocker search: the same array through a
// sampler without comparison (rgba8: unpacked).
#if MAP_RGBA8
float mapDepthAt(vec2 uv) { return unpackDepth(texture(mapPacked, vec3(uv, mapLayer))); }
#else
layout(binding = SL_UNIT_SHADOW_FIRST + 1) uniform sampler2DArray mapRaw;
float mapDepthAt(vec2 uv) { return texture(mapRaw, vec3(uv, mapLayer)).r; }
#endif
#endif
// The map being read: its texel's world size (perspective: per unit of
// distance), its camera's near and far planes, and the receiver's
// texture-space point (uv, depth) per screen pixel in x and y, taken where
// every fragment of a quad runs (the receiver-plane bias of the taps).
float mapTexelWorld = 0.0;
vec2 mapPlanes = vec2(0.0, 1.0);
vec3 mapDx = vec3(0.0), mapDy = vec3(0.0);
// A stored depth as distance along the light (perspective: linearised).
float mapDistance(float depth) {
    float n = mapPlanes.x, f = mapPlanes.y;
    if (map.params.w > 0.5) {
        float z = 2.0 * depth - 1.0;
        return 2.0 * n * f / (f + n - z * (f - n));
    }
    return n + depth * (f - n);
}
#endif

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
#elif MAP_FILTER == SL_MAP_FILTER_PCSS
    float reachWorld = 0.0;  // each tap compares against the receiver's plane itself
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
    mapTransmit = cubeTransmittanceAt(v, ref);
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
#elif MAP_FILTER == SL_MAP_FILTER_PCSS
    // Percentage-closer soft shadows on a disk across the ray (Fernando
    // 2005, for a sphere light of radius `size`). Each tap compares against
    // the receiver's plane where its direction meets it, not the centre's depth.
    float size = map.pcss.x;
    float dr = length(v);
    vec3 axis = v / dr;
    vec3 t = normalize(abs(axis.y) < 0.99 ? cross(axis, vec3(0.0, 1.0, 0.0)) : cross(axis, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(axis, t);
    float nv = dot(n, v);
    float rotation = 6.2831853 * mapNoise(gl_FragCoord.xy);
    // 1. Blockers within three radii of the ray at the receiver (those at
    // least a quarter of the way from the light).
    int blockerTaps = int(map.pcss.w);
    float blockers = 0.0, blockerSum = 0.0;
    for (int k = 0; k < blockerTaps; ++k) {
        float r = sqrt((float(k) + 0.5) / float(blockerTaps)) * 3.0 * size;
        float a = float(k) * 2.3999632 + rotation;
        vec3 w = v + r * (cos(a) * t + sin(a) * b);
        float nw = dot(n, w);
        float tapRef = nv < 0.0 && nw < 0.0 ? length(w) * nv / nw / map.cube.x - map.bias.x : ref;
        float d = cubeDepthAt(w);
        if (d < tapRef) {
            blockers += 1.0;
            blockerSum += d * map.cube.x;
        }
    }
    if (blockers == 0.0) return 1.0;
    float db = blockerSum / blockers;
    // 2. The penumbra's half width at the receiver, by similar triangles.
    float penumbra = size * (dr - db) / max(db, 1e-6);
    // 3. Percentage-closer filtering over it.
    int taps = int(map.taps.z);
    float sum = 0.0;
    for (int k = 0; k < taps; ++k) {
        float r = sqrt((float(k) + 0.5) / float(taps)) * penumbra;
        float a = float(k) * 2.3999632 + rotation;
        vec3 w = v + r * (cos(a) * t + sin(a) * b);
        float nw = dot(n, w);
        sum += cubeTap(w, nv < 0.0 && nw < 0.0 ? length(w) * nv / nw / map.cube.x - map.bias.x : ref);
    }
    return sum / float(taps);
#else
#error this MAP_FILTER is for 2D maps
#endif
}
#else
// The filtered test at map point `uv` for reference depth `ref`, in layer mapLayer.
float mapFilter(vec2 uv, float ref);

// Translucent casters (alphaMode blend): the layer's transmittance and the
// nearest translucent depth (shadow_map_transmit.frag); a receiver behind
// that depth gets the light through them, coloured.
layout(binding = SL_UNIT_SHADOW_FIRST + 2) uniform sampler2DArray mapTransmitColour;
layout(binding = SL_UNIT_SHADOW_FIRST + 3) uniform sampler2DArray mapTransmitDepth;
vec3 mapTransmit = vec3(1.0);  // of the last mapTest (the cascade in use)
vec3 transmittanceAt(vec2 uv, float ref) {
    if (map.transmit.x < 0.5) return vec3(1.0);
    float nearest = texture(mapTransmitDepth, vec3(uv, mapLayer)).r;
    return ref > nearest ? texture(mapTransmitColour, vec3(uv, mapLayer)).rgb : vec3(1.0);
}

// The test in a map, at texture-space point s (before the divide).
float mapTest(vec4 s, float NdotL) {
    if (s.w <= 0.0) return 1.0;
    s.xyz /= s.w;
    // Outside the map or beyond its far plane: lit, never falsely shadowed (004).
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0))) || s.z > 1.0) return 1.0;
    float ref = s.z - map.bias.x - max(map.bias.y * (1.0 - NdotL), map.bias.z);
    mapTransmit = transmittanceAt(s.xy, ref);
    return mapFilter(s.xy, ref);
}

#if MAP_CASCADES > 1
// Cascade c's test: the offsets of shadow_map_vertex.glsl, here per
// fragment with the cascade's own texel size.
float cascadeTest(int c, vec3 worldPosition, vec3 n, float NdotL, float tanTheta, vec3 worldDx, vec3 worldDy) {
    float texel = map.cascadeTexel[c >> 2][c & 3];
    vec3 p = worldPosition + n * (map.bias.w * texel * (1.0 - NdotL)) + map.light.xyz * (map.params.y * texel * tanTheta);
    mapLayer = map.params.x + float(c);
#if MAP_FILTER == SL_MAP_FILTER_PCSS
    mapTexelWorld = texel;
    mapPlanes = map.cascadeRange[c].xy;
    mat3 affine = mat3(map.cascadeShadowFromWorld[c]);  // orthographic: the point's change is linear
    mapDx = affine * worldDx;
    mapDy = affine * worldDy;
#endif
    return mapTest(map.cascadeShadowFromWorld[c] * vec4(p, 1.0), NdotL);
}

// The shadow test's visibility, 0 (shadowed) to 1 (lit): the slice's
// cascade, fading into the next one over the far `blend` share of the slice.
float mapVisibility(vec3 worldPosition, vec3 worldNormal) {
    vec3 n = worldNormal;
    float NdotL = clamp(dot(n, map.light.xyz), 0.0, 1.0);
    float tanTheta = min(length(cross(n, map.light.xyz)) / max(NdotL, 1e-4), 10.0);
    vec3 worldDx = dFdx(worldPosition), worldDy = dFdy(worldPosition);
    float depth = cascadeDepth(worldPosition);
    int c = cascadeOf(depth);
    float v = cascadeTest(c, worldPosition, n, NdotL, tanTheta, worldDx, worldDy);
    if (c < MAP_CASCADES - 1) {
        float far = cascadeFarOf(c);
        float band = map.cascade.w * (far - (c > 0 ? cascadeFarOf(c - 1) : 0.0));
        float t = band > 0.0 ? (depth - (far - band)) / band : 0.0;
        if (t > 0.0) v = mix(v, cascadeTest(c + 1, worldPosition, n, NdotL, tanTheta, worldDx, worldDy), min(t, 1.0));
    }
    return v;
}
#else
in vec4 vShadowCoord;   // from shadow_map_vertex.glsl: the offset point in texture space
in float vShadowNdotL;

// The shadow test's visibility, 0 (shadowed) to 1 (lit).
float mapVisibility(vec3 worldPosition, vec3 worldNormal) {
    mapLayer = map.params.x;
#if MAP_MOMENTS > 0
    mapPlanes = map.pcss.yz;
#endif
#if MAP_FILTER == SL_MAP_FILTER_PCSS
    mapTexelWorld = map.params.z;
    mapPlanes = map.pcss.yz;
    vec3 q = vShadowCoord.xyz / vShadowCoord.w;
    mapDx = dFdx(q);
    mapDy = dFdy(q);
#endif
    return mapTest(vShadowCoord, vShadowNdotL);
}
#endif

#if MAP_MOMENTS > 0
// Chebyshev's upper bound on the share of the filtered region at least as
// far as t, from its mean and mean square (VSM, each EVSM warp).
float chebyshev(vec2 m, float t, float minVariance) {
    if (t <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    return variance / (variance + d * d);
}

#if MAP_MOMENTS == SL_MAP_MOMENTS_MSM
// Hamburger 4-moment shadow intensity (Peters and Klein 2015, algorithm 3):
// the least upper bound on the occluded share given four moments, from the
// biased moments' Cholesky factorisation and a quadratic's two roots.
float msmShadow(vec4 b, float z) {
    b = mix(b, vec4(0.5), MAP_MOMENT_BIAS);
    float l32d22 = -b.x * b.y + b.z;
    float d22 = -b.x * b.x + b.y;
    float squaredDepthVariance = -b.y * b.y + b.w;
    float d33d22 = dot(vec2(squaredDepthVariance, -l32d22), vec2(d22, l32d22));
    float invD22 = 1.0 / d22;
    float l32 = l32d22 * invD22;
    vec3 c = vec3(1.0, z, z * z);
    c.y -= b.x;
    c.z -= b.y + l32 * c.y;
    c.y *= invD22;
    c.z *= d22 / d33d22;
    c.y -= l32 * c.z;
    c.x -= dot(c.yz, b.xy);
    float p = c.y / c.z, q = c.x / c.z;
    float r = sqrt(max(p * p * 0.25 - q, 0.0));
    float z1 = -p * 0.5 - r, z2 = -p * 0.5 + r;
    vec4 select = z2 < z ? vec4(z1, z, 1.0, 1.0) : (z1 < z ? vec4(z, z1, 0.0, 1.0) : vec4(0.0));
    float quotient = (select.x * z2 - b.x * (select.x + z2) + b.y) / ((z2 - select.y) * (z - z1));
    return clamp(select.z + select.w * quotient, 0.0, 1.0);
}
#endif

// A moment map's visibility at uv for the receiver's depth `ref`: the
// filtered moments (bilinear, mipmapped when asked, blurred by the shadow
// pass) bound the share of occluders nearer than the receiver from above;
// values under bleedReduction are cut (less light bleeding, darker
// penumbrae).
float momentVisibility(vec2 uv, float ref) {
    float z = map.params.w > 0.5 ? (mapDistance(ref) - mapPlanes.x) / (mapPlanes.y - mapPlanes.x) : ref;
    vec4 m = texture(mapMoments, vec3(uv, mapLayer));
#if MAP_MOMENTS == SL_MAP_MOMENTS_VSM
    float v = chebyshev(m.xy, z, MAP_MIN_VARIANCE);
#elif MAP_MOMENTS == SL_MAP_MOMENTS_MSM
    float v = 1.0 - msmShadow(m, z);
#else
    // EVSM: each warp's bound, the floor of the variance scaled by the warp's slope.
    float w = 2.0 * z - 1.0;
    float positive = exp(MAP_EVSM_POSITIVE * w);
    float slope = 1e-4 * MAP_EVSM_POSITIVE * positive;
    float v = chebyshev(m.xy, positive, slope * slope);
#if MAP_MOMENTS == SL_MAP_MOMENTS_EVSM4
    float negative = -exp(-MAP_EVSM_NEGATIVE * w);
    float slopeN = 1e-4 * MAP_EVSM_NEGATIVE * negative;
    v = min(v, chebyshev(m.zw, negative, slopeN * slopeN));
#endif
#endif
    return clamp((v - map.moments.x) / (1.0 - map.moments.x), 0.0, 1.0);
}
#endif

float mapFilter(vec2 uv, float ref) {
#if MAP_MOMENTS > 0
    return momentVisibility(uv, ref);
#else
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
#elif MAP_FILTER == SL_MAP_FILTER_PCSS
    // Percentage-closer soft shadows (Fernando 2005). Every tap compares
    // against the receiver's plane at its own place (the depth change per
    // uv from the screen derivatives), not the centre's depth.
    float det = mapDx.x * mapDy.y - mapDx.y * mapDy.x;
    vec2 dzduv = abs(det) > 1e-20 ? vec2(mapDy.y * mapDx.z - mapDx.y * mapDy.z, mapDx.x * mapDy.z - mapDy.x * mapDx.z) / det : vec2(0.0);
    dzduv = clamp(dzduv, vec2(-1e4), vec2(1e4));
    bool perspective = map.params.w > 0.5;
    float dr = mapDistance(ref);
    float texel = perspective ? mapTexelWorld * dr : mapTexelWorld;
    float size = map.pcss.x;
    float rotation = 6.2831853 * mapNoise(gl_FragCoord.xy);
    // 1. Blockers: stored depths nearer the light than the receiver's plane
    // within the region a blocker can shade it from: directional, the light's
    // angular radius over the depth up to the light camera's near plane;
    // spot, three radii at the receiver (blockers at least a quarter of the
    // way from the light). At most an eighth of the map.
    float limit = 0.125 / du;
    float search = clamp((perspective ? 3.0 * size : (dr - mapPlanes.x) * size) / texel, 1.0, limit);
    int blockerTaps = int(map.pcss.w);
    float blockers = 0.0, blockerSum = 0.0;
    for (int k = 0; k < blockerTaps; ++k) {
        float r = sqrt((float(k) + 0.5) / float(blockerTaps)) * search;
        float a = float(k) * 2.3999632 + rotation;
        vec2 o = du * r * vec2(cos(a), sin(a));
        float d = mapDepthAt(uv + o);
        if (d < ref + dot(dzduv, o)) {
            blockers += 1.0;
            blockerSum += mapDistance(d);
        }
    }
    if (blockers == 0.0) return 1.0;
    float db = blockerSum / blockers;
    // 2. The penumbra's half width at the receiver, by similar triangles.
    float radius = min((perspective ? size * (dr - db) / max(db, 1e-6) : (dr - db) * size) / texel, limit);
    // 3. Percentage-closer filtering over it.
    int taps = int(map.taps.z);
    float sum = 0.0;
    for (int k = 0; k < taps; ++k) {
        float r = sqrt((float(k) + 0.5) / float(taps)) * radius;
        float a = float(k) * 2.3999632 + rotation;
        vec2 o = du * r * vec2(cos(a), sin(a));
        sum += mapTap(uv + o, ref + dot(dzduv, o));
    }
    return sum / float(taps);
#else
#error unknown MAP_FILTER
#endif
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
    return v * mapTransmit;  // coloured by the translucent casters in the way
}
