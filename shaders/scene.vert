// Transforms scene geometry to clip space and passes world-space position,
// normal and texture coordinates on. Shared by every pass that draws meshes.
#include "shadowlab_shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec2 vUv;
// Light passes test depth EQUAL against the base pass: same transform, same bits.
invariant gl_Position;

void main() {
    vec4 world = draw.worldFromObject * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = mat3(draw.normalFromObject) * inNormal;
    vUv = inUv;
    gl_Position = frame.clipFromWorld * world;
}
