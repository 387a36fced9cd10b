// Technique "map", a point light's cube map in one pass: each triangle goes
// to the faces whose frustum it may touch (of those the item's bounds touch,
// `faceMask`), as layer 6 x (the light's cube) + face of the cube-map array.
// Variant MAP_CUBE_CULL 0: every triangle to every face in the mask (the
// option faceCulling false, as LearnOpenGL's demo does).
#include "shadow_map_shared.h"

layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

layout(location = 0) uniform uint faceMask;
in vec3 vCubeWorld[];
in vec2 vCubeUv[];
out vec3 gCubeWorld;
out vec2 gCubeUv;

void main() {
    int first = 6 * int(map.layer);
    for (int f = 0; f < 6; ++f) {
        if ((faceMask & (1u << uint(f))) == 0u) continue;
        vec4 c[3];
        for (int k = 0; k < 3; ++k) c[k] = map.faceClipFromWorld[f] * vec4(vCubeWorld[k], 1.0);
        // Outside the face's frustum when all three corners are beyond one plane.
        bool outside = false;
#if MAP_CUBE_CULL
        for (int axis = 0; axis < 3 && !outside; ++axis) {
            outside = (c[0][axis] > c[0].w && c[1][axis] > c[1].w && c[2][axis] > c[2].w) ||
                      (c[0][axis] < -c[0].w && c[1][axis] < -c[1].w && c[2][axis] < -c[2].w);
        }
#endif
        if (outside) continue;
        for (int k = 0; k < 3; ++k) {
            gl_Layer = first + f;
            gl_Position = c[k];
#if MAP_CUBE_WINDOW
            gl_Position.z = cubeWindowClipZ(c[k].w);
#endif
            gCubeWorld = vCubeWorld[k];
            gCubeUv = vCubeUv[k];
            EmitVertex();
        }
        EndPrimitive();
    }
}
