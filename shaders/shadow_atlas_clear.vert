// Technique "map", the shadow atlas: a tile cleared to the far plane by a
// triangle over its viewport at depth 1 (depth test ALWAYS), drawn in the
// pipeline like the casters after it. glClearTexSubImage on a region
// waits for the rasteriser to finish what came before (llvmpipe), once
// per tile.
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}
