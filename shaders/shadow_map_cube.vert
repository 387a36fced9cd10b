// Technique "map", a point light's cube-map pass (Lawonn's lecture): the casters'
// world positions for the geometry shader (MAP_CUBE_ONE_PASS), or one face's
// clip position for the six-pass path (that face in `face`).
#include "shadow_map_shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
#if MAP_CUBE_ONE_PASS
out vec3 vCubeWorld;
out vec2 vCubeUv;
#else
layout(location = 1) uniform int face;
out vec3 gCubeWorld;
out vec2 gCubeUv;
#endif
// A caster drawn from a coarser level of its mesh (map/passes/CasterDraw.h): its
// vertices moved this far away from the light, world units; 0 for a mesh's
// own triangles.
layout(location = 4) uniform float casterPush = 0.0;

void main() {
#if MAP_CUBE_ONE_PASS
    vCubeUv = inUv;
#else
    gCubeUv = inUv;
#endif
    vec4 world = draw.worldFromObject * vec4(inPosition, 1.0);
    if (casterPush > 0.0) world.xyz += casterPush * normalize(world.xyz - map.lightPosition);
#if MAP_CUBE_ONE_PASS
    vCubeWorld = world.xyz;
    gl_Position = world;
#else
    gCubeWorld = world.xyz;
    gl_Position = map.faceClipFromWorld[face] * world;
#if MAP_CUBE_WINDOW
    gl_Position.z = cubeWindowClipZ(gl_Position.w);
#endif
#endif
}
