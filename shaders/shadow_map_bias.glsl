// Technique "map": the receiver's offsets against acne, shared by the
// vertex hook (2D maps), the cascades and the cube maps.
#ifndef SHADOW_MAP_BIAS_GLSL
#define SHADOW_MAP_BIAS_GLSL

// tan of the angle between the normal n and the direction L to the light
// (at most 10): sin from the cross product stays accurate at small angles,
// where 1 - (N.L)^2 rounds to 0.
float mapTanTheta(vec3 n, vec3 L, float NdotL) { return min(length(cross(n, L)) / max(NdotL, 1e-4), 10.0); }

// Normal offset: the point moved along its normal by `normalBias` texels
// (map.normalBiasTexels) of world size `texel`, times 1 - N.L.
vec3 mapNormalOffset(vec3 p, vec3 n, float NdotL, float texel) { return p + n * (map.normalBiasTexels * texel * (1.0 - NdotL)); }

// Receiver-plane bias for filters: a filter compares the centre's depth
// with occluders up to `reach` texels away (map.reachTexels), where the
// surface tilted by theta is tan(theta) x that distance nearer the light;
// the point moved towards the light (L) by as much.
vec3 mapReceiverPlaneOffset(vec3 p, vec3 L, float texel, float tanTheta) { return p + L * (map.reachTexels * texel * tanTheta); }

// A warped map's texel (warp lispsm, LightCamera): its world size at point
// p grows with t = dot(plane.xyz, p) + plane.w, the distance from the warp's
// centre along the view, as uv.x t across the view and uv.y t^2 along it, so
// it is long and narrow far away. The offsets are against the surface's
// depth change over a texel, which runs along the normal n's direction
// across the light (the map's x: map.warpAcross, y: plane.xyz): the
// texel's extent that way.
float mapWarpedTexel(vec4 plane, vec2 uv, vec3 p, vec3 n) {
    float t = max(dot(plane.xyz, p) + plane.w, 0.0);
    vec2 extent = vec2(uv.x * t, uv.y * t * t);
    vec2 g = abs(vec2(dot(map.warpAcross.xyz, n), dot(plane.xyz, n)));
    float lg = g.x + g.y;
    return lg > 1e-4 ? dot(extent, g) / lg : max(extent.x, extent.y);
}

// An orthographic map's texel for the offsets at a point of normal n:
// its texels along the light view's x and y (1 / (size |row|) for the
// texture-space matrix's first two rows), weighed by how much the normal
// tilts along each across the light, where a texel's depth changes.
// Stabilised cascades may have them differ (core/LightCamera: fitCascade).
float mapAxesTexel(mat4 shadowFromWorld, vec3 n) {
    vec3 r0 = vec3(shadowFromWorld[0][0], shadowFromWorld[1][0], shadowFromWorld[2][0]);
    vec3 r1 = vec3(shadowFromWorld[0][1], shadowFromWorld[1][1], shadowFromWorld[2][1]);
    vec2 lengths = vec2(length(r0), length(r1));
    vec2 g = abs(vec2(dot(r0, n), dot(r1, n))) / lengths;
    vec2 texels = map.texelUv / lengths;
    float s = g.x + g.y;
    return s > 1e-4 ? dot(g, texels) / s : max(texels.x, texels.y);
}

// A mipmapped map (MAP_MIPMAPS): the map point's change per pixel the
// level is chosen by: the shorter of its changes in x and y (duvdx,
// duvdy), over sqrt 2. Where the view grazes a surface the longer one
// spans many texels, and a level that coarse would blur the map across
// several pixels in the other direction too (a caster's edge blended with
// the depth behind it, its shadow shrunk). A nearest-level sampler rounds
// log2 of the footprint; over sqrt 2 it rounds down instead: the finest
// level whose texel is no wider than the pixel's shorter footprint, so a
// blended edge stays within a pixel (the taps pass it as both gradients).
vec2 mapLevelGradient(vec2 duvdx, vec2 duvdy) { return 0.70710678 * (dot(duvdx, duvdx) <= dot(duvdy, duvdy) ? duvdx : duvdy); }

// How many level-0 texels a texel of that level spans, 2^level (level 0
// where a texel covers a pixel or more). Averaged depths are the depth at
// the coarse texel's centre, so the offsets against acne must reach that
// texel's size, not level 0's.
float mapLevelScale(vec2 duvdx, vec2 duvdy) {
    float rho = length(mapLevelGradient(duvdx, duvdy)) / map.texelUv;
    return exp2(max(floor(log2(max(rho, 1e-8)) + 0.5), 0.0));
}

#endif
