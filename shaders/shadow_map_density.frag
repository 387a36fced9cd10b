// Technique "map", debug view and metric: the texel footprint, how many
// screen pixels one shadow-map texel covers at each visible point (Lloyd's
// aliasing measure: about 1 is no aliasing, above 10 heavy). With t the
// point's map coordinates in texels and J = (dt/dx, dt/dy) their change per
// screen pixel, a texel step along the map's u (v) axis is the screen step
// J^-1 (1, 0) (J^-1 (0, 1)); the footprint is the longer of the two, in
// pixels. Written as a float (location 1: compare's texelFootprint
// percentiles; -1 where nothing is measured: the background, surfaces that
// receive no shadow, points outside the map) and as a colour (location 0):
// green about one pixel a texel; towards red, a texel over many pixels
// (blocky edges, 16 at full red); towards blue, many texels in one pixel
// (resolution spent for nothing, 1/16 at full blue); grey: outside the map
// (lit) or not a receiver. With cascades (MAP_CASCADES > 1) the point's own
// cascade; a point light's cube (MAP_CUBE): the face its direction samples.
#include "shadow_map_shared.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;
layout(location = 0) out vec4 outColor;
layout(location = 1) out float outFootprint;

// The larger screen extent of a texel step along either map axis, for map
// coordinates (in texels) changing by tx per pixel in x and ty in y.
float texelFootprint(vec2 tx, vec2 ty) {
    float det = abs(tx.x * ty.y - ty.x * tx.y);
    if (det <= 0.0) return 1e9;  // the map's plane seen edge-on: one texel spread without bound
    return max(length(vec2(ty.y, tx.y)), length(vec2(ty.x, tx.x))) / det;
}

void main() {
    bool inside;
    float footprint;
#if MAP_CUBE
    // The face the direction from the light samples (its largest
    // component), and the direction's change per pixel projected on that
    // face (the quotient rule), so that every fragment of a quad uses its
    // own face.
    vec3 v = vWorldPosition - map.lightPosition;
    vec3 vx = dFdx(v), vy = dFdy(v);
    vec3 a = abs(v);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    int i = axis == 0 ? 1 : 0, j = axis == 2 ? 1 : 2;
    float m = v[axis];
    // Face coordinates c = (v_i, v_j) / m in -1..1 span the face's size in
    // texels: size / 2 = 1 / cubeTexelPerDistance texels per unit of c.
    vec2 c = vec2(v[i], v[j]) / m;
    vec2 cx = (vec2(vx[i], vx[j]) - c * vx[axis]) / m, cy = (vec2(vy[i], vy[j]) - c * vy[axis]) / m;
    footprint = texelFootprint(cx / map.cubeTexelPerDistance, cy / map.cubeTexelPerDistance);
    inside = length(v) > 0.0 && length(v) <= map.cubeFar;
#else
#if MAP_CASCADES > 1
    vec4 s = map.cascadeShadowFromWorld[cascadeOf(cascadeDepth(vWorldPosition))] * vec4(vWorldPosition, 1.0);
#else
    vec4 s = map.shadowFromWorld * vec4(vWorldPosition, 1.0);
#endif
    vec2 t = s.xy / s.w / map.texelUv;
    footprint = texelFootprint(dFdx(t), dFdy(t));
    vec2 uv = s.xy / s.w;
    inside = s.w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
#endif
    // draw.baseColor.w: the node receives shadows.
    bool measured = inside && draw.baseColor.w > 0.5;
    float l = clamp(log2(max(footprint, 1e-6)) / 4.0, -1.0, 1.0);
    vec3 colour = l > 0.0 ? mix(vec3(0.1, 0.8, 0.2), vec3(0.9, 0.1, 0.1), l) : mix(vec3(0.1, 0.8, 0.2), vec3(0.1, 0.2, 0.9), -l);
    outColor = vec4(measured ? colour : vec3(0.35), 1.0);
    outFootprint = measured ? footprint : -1.0;
}
