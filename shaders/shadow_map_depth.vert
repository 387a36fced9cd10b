// Technique "map", shadow pass: the casters from the light camera.
#include "shadow_map_shared.h"

layout(location = 0) in vec3 inPosition;
out vec2 vLightNdc;

void main() {
    gl_Position = map.lightClipFromWorld * draw.worldFromObject * vec4(inPosition, 1.0);
    vLightNdc = gl_Position.xy / gl_Position.w;
}
