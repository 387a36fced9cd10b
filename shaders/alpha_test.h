// Alpha-tested materials (AlphaMode mask): whether the surface is a hole at
// uv; translucent ones (blend): the light they let through. The alpha is the
// material's factor times the base-colour texture's alpha, read at level 0
// (the ray-traced reference reads the same texels, src/reference), so the
// camera, every shadow map and the truth cut the same holes. Needs the draw
// block and the base-colour texture bound at SL_UNIT_BASE_COLOR when
// draw.alpha.w says there is one.
#ifndef SHADOWLAB_ALPHA_TEST_H
#define SHADOWLAB_ALPHA_TEST_H
#include "shadowlab_shared.h"

SL_BINDING(SL_UNIT_BASE_COLOR) uniform sampler2D alphaTexture;

bool alphaCutOut(vec2 uv) {
    if (draw.alpha.z < 0.5 || draw.alpha.z > 1.5) return false;
    float a = draw.alpha.x * (draw.alpha.w > 0.5 ? textureLod(alphaTexture, uv, 0.0).a : 1.0);
    return a < draw.alpha.y;
}

// Whether the surface is translucent (blend): it casts no depth, only colour.
bool translucentSurface() { return draw.alpha.z > 1.5; }

// A translucent surface's transmittance at uv: white through its clear
// parts, its colour (base colour times texture) where it is opaque.
vec3 surfaceTransmittance(vec2 uv) {
    vec4 c = vec4(draw.baseColor.rgb, draw.alpha.x);
    if (draw.alpha.w > 0.5) c *= textureLod(alphaTexture, uv, 0.0);
    return mix(vec3(1.0), c.rgb, c.a);
}
#endif
