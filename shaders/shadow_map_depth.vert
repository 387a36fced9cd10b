// Technique "map", shadow pass: the casters from the light camera.
#include "shadow_map_shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
out vec2 vUv;

void main() {
    vUv = inUv;
    gl_Position = map.lightClipFromWorld * draw.worldFromObject * vec4(inPosition, 1.0);
}
