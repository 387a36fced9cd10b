// Technique "disc": a point is shadowed when the segment from it to the
// light (to infinity along a directional light) crosses one of the discs:
// the ray meets the disc's plane at t, and there the point's coordinates
// along the disc's semi-axes a and b lie in the unit circle. Exact, per
// fragment, no shadow pass (Ganovelli et al. exercise 8.6.2-1).
#include "shadow_disc_shared.h"

vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    vec3 toLight = disc.light.w > 0.5 ? disc.light.xyz - worldPosition : disc.light.xyz;
    float reach = disc.light.w > 0.5 ? 1.0 : 1e30;  // the ray's end, in units of toLight
    // Start just off the surface along its normal (a disc never shadows itself).
    vec3 n = dot(worldNormal, toLight) < 0.0 ? -worldNormal : worldNormal;
    vec3 p = worldPosition + n * disc.params.y;
    // Every disc is tested and the hits are or-ed, with no early return or
    // continue: a rasteriser that runs both sides of a branch (llvmpipe)
    // pays for their masks in every round of the loop.
    // DISC_COUNT (the variant): the light's discs as a constant, so that
    // the loop unrolls and each disc's uniforms are read at a constant index.
    const int count = DISC_COUNT;
    bool hit = false;
    for (int k = 0; k < count; ++k) {
        vec3 c = disc.centre[k].xyz, a = disc.axisA[k].xyz, b = disc.axisB[k].xyz;
        vec3 normal = cross(a, b);
        float facing = dot(normal, toLight);
        bool crosses = abs(facing) >= 1e-12;  // not a ray in the disc's plane
        float t = dot(normal, c - p) / (crosses ? facing : 1.0);
        vec3 q = p + t * toLight - c;
        float s = dot(q, a) / dot(a, a), u = dot(q, b) / dot(b, b);
        hit = hit || (crosses && t > 0.0 && t < reach && s * s + u * u <= 1.0);
    }
    return vec3(hit ? 0.0 : 1.0);
}
