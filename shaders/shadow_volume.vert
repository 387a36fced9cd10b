// Technique "volume": world positions for the extruding geometry shader.
#include "shadow_volume_shared.h"

layout(location = 0) in vec3 inPosition;
out vec3 vVolumeWorld;
out vec3 vVolumeObject;

void main() {
    vVolumeWorld = (draw.worldFromObject * vec4(inPosition, 1.0)).xyz;
    vVolumeObject = inPosition;
    gl_Position = vec4(vVolumeWorld, 1.0);
}
