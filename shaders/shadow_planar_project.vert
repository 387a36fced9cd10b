// Technique "planar": a caster flattened onto a receiver plane. Variant
// PLANAR_GEOMETRY: the world position only, the geometry shader projects
// (onto every plane of the draw). Otherwise the first plane, here, with
// two clip distances: the projected w (a vertex beyond the light would
// land on the far side: an anti-shadow) and the vertex's side of the plane
// (a vertex behind the receiver casts nothing on it).
#include "shadow_planar_shared.h"

layout(location = 0) in vec3 inPosition;
#if PLANAR_GEOMETRY
out vec3 vPlanarWorld;
#endif

void main() {
    vec4 world = draw.worldFromObject * vec4(inPosition, 1.0);
#if PLANAR_GEOMETRY
    vPlanarWorld = world.xyz;
    gl_Position = world;
#else
    vec4 projected = planar.shadowFromWorld[0] * world;
    gl_Position = frame.clipFromWorld * projected;
    gl_ClipDistance[0] = projected.w;
    gl_ClipDistance[1] = dot(planar.plane[0], world);
#endif
}
