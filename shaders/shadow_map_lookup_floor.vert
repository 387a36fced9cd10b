// Technique "map", the floor of its lookups (bench: MapFloors::drawLookup):
// the frame's opaque items from the camera, each point also in the light's
// clip space (the depth pass's camera) or, for a cube (LOOKUP_CUBE), as
// the direction from the light, and nothing else.
#include "shadow_map_shared.h"

layout(location = 0) in vec3 inPosition;
#if LOOKUP_CUBE
layout(location = 0) uniform vec3 lightPosition;
out vec3 vFromLight;
#else
out vec4 vLightClip;
#endif

void main() {
    vec4 world = draw.worldFromObject * vec4(inPosition, 1.0);
    gl_Position = frame.clipFromWorld * world;
#if LOOKUP_CUBE
    vFromLight = world.xyz - lightPosition;
#else
    vLightClip = map.lightClipFromWorld * world;
#endif
}
