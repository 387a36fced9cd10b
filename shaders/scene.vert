// Transforms scene geometry to clip space and passes world-space position,
// normal and texture coordinates on. Shared by every pass that draws meshes.
#include "shadowlab_shared.h"
// A technique's per-vertex part (its light-space coordinates, say): a file
// that defines SHADOW_VERTEX_HOOK and void shadowVertex(vec3 worldPosition,
// vec3 worldNormal), writing its own outputs. Empty for most variants.
#include "@shadow_vertex?"

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
#ifdef SHADOW_VERTEX_HOOK
    shadowVertex(world.xyz, normalize(vWorldNormal));
#endif
}
