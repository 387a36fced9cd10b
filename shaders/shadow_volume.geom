// Technique "volume": one triangle with its edge neighbours
// (GL_TRIANGLES_ADJACENCY: 0, 2, 4 the triangle; 1, 3, 5 the vertices
// across edges 0-2, 2-4, 4-0) becomes its part of the shadow volume:
// - `mode` 0 (open meshes, "facing") and 2 (closed meshes): a
//   light-facing triangle emits a side quad for each silhouette edge (the
//   neighbour faces away from the light, or there is none: an open edge,
//   whose "neighbour" is the triangle's own opposite vertex,
//   core/Adjacency.h), extruded to infinity (w = 0) along the light's rays;
// - the caps (CAPS): a triangle wound towards the light as the front cap
//   and its copy at infinity, reversed, as the back cap. Mode 0 caps with
//   the light-facing triangles. Mode 2 caps with the triangles that face
//   away: a ray from a point outside a closed mesh to the light crosses as
//   many of either, but from a light inside the mesh (a lamp in a shade, a
//   room built as a box) it crosses one more facing away, and none may
//   face it at all;
// - `mode` 1: every triangle is its own closed volume (its three edges,
//   both caps), wound so that its faces point out of it.
// The counts only need every volume's faces wound consistently: a point
// inside k volumes gets a count of k (or -k), never 0.
#include "shadow_volume_shared.h"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

layout(location = 0) uniform int mode;  // 0 open (facing), 1 per triangle, 2 closed
// The light in the item's object space: the facing test runs there, in
// double precision, on the mesh's own coordinates, so that the CPU path
// (Volume.cpp) takes the very same decisions for faces seen edge-on.
layout(location = 1) uniform dvec4 lightInObject;
in vec3 vVolumeWorld[];
in vec3 vVolumeObject[];

// Lexicographic order of positions.
bool before(vec3 p, vec3 q) { return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z))); }

// A triangle's facing, computed from its lexicographically smallest corner
// on (a cyclic turn, which keeps the orientation): the triangle itself and
// its neighbour across an edge then round the very same expression, so two
// nearly coplanar faces can never disagree about their shared edge (Ganovelli et al.
// §8.5's "hole" in the volume).
bool facesLight(int i, int j, int k) {
    if (before(vVolumeObject[j], vVolumeObject[i]) && !before(vVolumeObject[k], vVolumeObject[j])) { int t = i; i = j; j = k; k = t; }
    else if (before(vVolumeObject[k], vVolumeObject[i]) && before(vVolumeObject[k], vVolumeObject[j])) { int t = k; k = j; j = i; i = t; }
    precise dvec3 a = dvec3(vVolumeObject[i]), b = dvec3(vVolumeObject[j]), c = dvec3(vVolumeObject[k]);
    precise dvec3 towards = lightInObject.w > 0.5 ? lightInObject.xyz - a : lightInObject.xyz;
    precise dvec3 n = cross(b - a, c - a);
    precise double d = n.x * towards.x + n.y * towards.y + n.z * towards.z;
    return d > 0.0;
}

void sideQuad(vec3 a, vec3 b) {
    gl_Position = here(a); EmitVertex();
    gl_Position = atInfinity(a); EmitVertex();
    gl_Position = here(b); EmitVertex();
    gl_Position = atInfinity(b); EmitVertex();
    EndPrimitive();
}

void main() {
    vec3 v[6];
    for (int i = 0; i < 6; ++i) v[i] = vVolumeWorld[i];
    bool lit = facesLight(0, 2, 4);
    if (mode == 0 && !lit) return;
    // Wind the triangle towards the light (a back-facing one is turned).
    vec3 a = v[0], b = lit ? v[2] : v[4], c = lit ? v[4] : v[2];
    if (mode == 1) {
        sideQuad(a, b);
        sideQuad(b, c);
        sideQuad(c, a);
    } else if (lit) {
        for (int e = 0; e < 3; ++e) {
            vec3 p = v[2 * e], q = v[(2 * e + 2) % 6];
            bool open = all(equal(vVolumeObject[2 * e + 1], vVolumeObject[(2 * e + 4) % 6]));
            if (open || !facesLight(2 * e, 2 * e + 1, (2 * e + 2) % 6)) sideQuad(p, q);
        }
    }
#if CAPS
    if (mode == 2 && lit) return;
    gl_Position = here(a); EmitVertex();
    gl_Position = here(b); EmitVertex();
    gl_Position = here(c); EmitVertex();
    EndPrimitive();
    gl_Position = atInfinity(a); EmitVertex();
    gl_Position = atInfinity(c); EmitVertex();
    gl_Position = atInfinity(b); EmitVertex();
    EndPrimitive();
#endif
}
