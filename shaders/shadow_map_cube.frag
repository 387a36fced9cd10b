// Technique "map", a point light's cube-map pass. MAP_CUBE_WINDOW
// (depth32f): the stored depth is the face camera's window depth as
// rasterised, reversed (near 1, far 0), with the polygon offset for bias;
// nothing is written here. Otherwise it is the distance from the light
// over the far plane (Lawonn's lecture), written to gl_FragDepth, plus the slope
// bias (the distance's largest change to a neighbouring texel times
// `slopeBias`, what glPolygonOffset's factor does for window depth, which a
// written depth bypasses) and the constant offset. Variant MAP_RGBA8 packs
// it into colour (Ganovelli et al. §8.3.1).
#include "shadow_map_shared.h"
#include "alpha_test.h"

in vec3 gCubeWorld;
in vec2 gCubeUv;
#if MAP_RGBA8
layout(location = 0) out vec4 outPacked;
#endif

void main() {
#if MAP_HOLES
    if (alphaCutOut(gCubeUv) || translucentSurface()) discard;  // holes (CubePassVariant::holes); translucent casters cast no depth
#endif
#if !MAP_CUBE_WINDOW
    float distance = length(gCubeWorld - map.lightPosition);
    float slope = max(abs(dFdx(distance)), abs(dFdy(distance)));
    float depth = (distance + map.cubeSlopeBias * slope) / map.cubeFar + map.cubeOffset;
    gl_FragDepth = clamp(depth, 0.0, 1.0);
#if MAP_RGBA8
    outPacked = packDepth(gl_FragDepth);
#endif
#endif
}
