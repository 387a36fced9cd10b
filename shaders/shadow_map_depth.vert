// Technique "map", shadow pass: the casters from the light camera.
#include "shadow_map_shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
out vec2 vUv;

// A caster drawn from a coarser level of its mesh (map/passes/CasterDraw.h): its
// vertices moved this far away from the light, world units; 0 for a mesh's
// own triangles.
layout(location = 4) uniform float casterPush = 0.0;

void main() {
    vUv = inUv;
    if (casterPush > 0.0) {
        vec4 world = draw.worldFromObject * vec4(inPosition, 1.0);
        // Away from the light: against a directional light's direction, else
        // along the rays from the light's position (a spot; a cube's floor, MapFloors).
        world.xyz += casterPush * (dot(map.towardsLight, map.towardsLight) > 0.0 ? -map.towardsLight : normalize(world.xyz - map.lightPosition));
        gl_Position = map.lightClipFromWorld * world;
    } else {
        gl_Position = map.lightClipFromWorld * draw.worldFromObject * vec4(inPosition, 1.0);
    }
}
