// Technique "volume", extrusion "cpu": the volume's vertices as the CPU
// built them (object space, and whether each is the extruded copy at
// infinity), placed with the very functions the geometry shader uses.
#include "shadow_volume_shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in float inExtruded;

void main() {
    vec3 world = (draw.worldFromObject * vec4(inPosition, 1.0)).xyz;
    gl_Position = inExtruded > 0.5 ? atInfinity(world) : here(world);
}
