// Technique "map", the floor of its lookups (bench: MapFloors::drawLookup):
// the frame's opaque items from the camera, each point also in the light's
// clip space (the depth pass's camera), and nothing else.
#include "shadow_map_shared.h"

layout(location = 0) in vec3 inPosition;
out vec4 vLightClip;

void main() {
    vec4 world = draw.worldFromObject * vec4(inPosition, 1.0);
    gl_Position = frame.clipFromWorld * world;
    vLightClip = map.lightClipFromWorld * world;
}
