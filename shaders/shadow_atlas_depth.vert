// Technique "map", the shadow atlas's pass (src/techniques/map/atlas/Atlas.cpp):
// the casters from one tile's camera (a spot's, or a cube face's), drawn
// into the tile's square of the atlas (the viewport); shadow_map_depth.frag
// after it.
#include "shadowlab_shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 0) uniform mat4 tileClipFromWorld;
out vec2 vUv;

void main() {
    vUv = inUv;
    gl_Position = tileClipFromWorld * draw.worldFromObject * vec4(inPosition, 1.0);
    // Clipped to the tile's sides for real (RenderState::clipDistances 4):
    // a rasteriser with a guard band (llvmpipe) draws a large triangle
    // unclipped, and a floor's plane equation taken from corners tens of
    // tiles away leaves its depths noisy by more than any bias.
    gl_ClipDistance[0] = gl_Position.w + gl_Position.x;
    gl_ClipDistance[1] = gl_Position.w - gl_Position.x;
    gl_ClipDistance[2] = gl_Position.w + gl_Position.y;
    gl_ClipDistance[3] = gl_Position.w - gl_Position.y;
}
