// Technique "volume": one triangle with its edge neighbours
// (GL_TRIANGLES_ADJACENCY: 0, 2, 4 the triangle; 1, 3, 5 the vertices
// across edges 0-2, 2-4, 4-0) becomes its part of the shadow volume:
// - closed meshes (`perTriangle` 0): a light-facing triangle emits a side
//   quad for each silhouette edge (the neighbour faces away from the light,
//   or there is none: an open edge, whose "neighbour" is the triangle's own
//   opposite vertex, core/Adjacency.h), extruded to infinity (w = 0) along
//   the light's rays, and (CAPS) itself as the front cap and its copy at
//   infinity, reversed, as the back cap;
// - `perTriangle` 1: every triangle is its own closed volume (its three
//   edges, both caps), wound so that its faces point out of it.
// The counts only need every volume's faces wound consistently: a point
// inside k volumes gets a count of k (or -k), never 0.
#include "shadow_volume_shared.h"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;

layout(location = 0) uniform int perTriangle;
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
// nearly coplanar faces can never disagree about their shared edge (002
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
    if (perTriangle == 0 && !lit) return;
    // Wind the triangle towards the light (a back-facing one, perTriangle only, is turned).
    vec3 a = v[0], b = lit ? v[2] : v[4], c = lit ? v[4] : v[2];
    if (perTriangle != 0) {
        sideQuad(a, b);
        sideQuad(b, c);
        sideQuad(c, a);
    } else {
        for (int e = 0; e < 3; ++e) {
            vec3 p = v[2 * e], q = v[(2 * e + 2) % 6];
            bool open = all(equal(vVolumeObject[2 * e + 1], vVolumeObject[(2 * e + 4) % 6]));
            if (open || !facesLight(2 * e, 2 * e + 1, (2 * e + 2) % 6)) sideQuad(p, q);
        }
    }
#if CAPS
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
