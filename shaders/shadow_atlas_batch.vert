// Technique "map", the shadow atlas's pass for the opaque casters in one
// batch (src/techniques/map/passes/CasterBatch.cpp): positions already in
// world space, so one call draws every caster a tile culls; clipped to the
// tile's sides as shadow_atlas_depth.vert says.
layout(location = 0) in vec3 inWorldPosition;
layout(location = 0) uniform mat4 tileClipFromWorld;

void main() {
    gl_Position = tileClipFromWorld * vec4(inWorldPosition, 1.0);
    gl_ClipDistance[0] = gl_Position.w + gl_Position.x;
    gl_ClipDistance[1] = gl_Position.w - gl_Position.x;
    gl_ClipDistance[2] = gl_Position.w + gl_Position.y;
    gl_ClipDistance[3] = gl_Position.w - gl_Position.y;
}
