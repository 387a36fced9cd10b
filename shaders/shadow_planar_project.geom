// Technique "planar", variant PLANAR_GEOMETRY: each triangle of the caster
// emitted once per receiver plane of the draw, flattened onto it (lecture
// Wolberg's geometry-shader duplication), with the vertex shader's clip distances.
#include "shadow_planar_shared.h"

layout(triangles) in;
layout(triangle_strip, max_vertices = 48) out;  // 3 x SL_PLANAR_MAX_PLANES

in vec3 vPlanarWorld[];
// The plane of the caster itself, if it is one of this draw's receivers (-1: none): not projected onto itself.
layout(location = 2) uniform int skipPlane;

void main() {
    int planes = int(planar.params.x);
    for (int p = 0; p < planes; ++p) {
        if (p == skipPlane) continue;
        for (int k = 0; k < 3; ++k) {
            vec4 world = vec4(vPlanarWorld[k], 1.0);
            vec4 projected = planar.shadowFromWorld[p] * world;
            gl_Position = frame.clipFromWorld * projected;
            gl_ClipDistance[0] = projected.w;
            gl_ClipDistance[1] = dot(planar.plane[p], world);
            EmitVertex();
        }
        EndPrimitive();
    }
}
