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
in vec3 vVolumeWorld[];

vec3 towardsLight(vec3 p) { return volume.light.w > 0.5 ? volume.light.xyz - p : volume.light.xyz; }
bool facesLight(vec3 a, vec3 b, vec3 c) { return dot(cross(b - a, c - a), towardsLight(a)) > 0.0; }
#if BOOK
// Lecture 002 §8.5: the silhouette swept to a finite distance, beyond the scene's box.
vec4 atInfinity(vec3 p) { return frame.clipFromWorld * vec4(p - normalize(towardsLight(p)) * volume.params.x, 1.0); }
#else
vec4 atInfinity(vec3 p) { return frame.clipFromWorld * vec4(-towardsLight(p), 0.0); }
#endif
vec4 here(vec3 p) { return frame.clipFromWorld * vec4(p, 1.0); }

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
    bool lit = facesLight(v[0], v[2], v[4]);
    if (perTriangle == 0 && !lit) return;
    // Wind the triangle towards the light (a back-facing one, perTriangle only, is turned).
    vec3 a = v[0], b = lit ? v[2] : v[4], c = lit ? v[4] : v[2];
    if (perTriangle != 0) {
        sideQuad(a, b);
        sideQuad(b, c);
        sideQuad(c, a);
    } else {
        for (int e = 0; e < 3; ++e) {
            vec3 p = v[2 * e], q = v[(2 * e + 2) % 6], n = v[2 * e + 1];
            bool open = all(equal(n, v[(2 * e + 4) % 6]));
            if (open || !facesLight(p, n, q)) sideQuad(p, q);
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
