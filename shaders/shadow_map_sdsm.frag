// Technique "map", fit "sdsm": the depth pre-pass of the camera's view
// (MapSdsm) for alpha-tested (mask) materials, whose holes it cuts as the
// camera cuts them; every other surface is drawn without a fragment shader
// (depth only, the rasteriser's fastest path).
#include "shadowlab_shared.h"
#include "alpha_test.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;

void main() {
    if (alphaCutOut(vUv)) discard;
}
