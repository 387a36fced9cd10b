// Alpha-tested materials (AlphaMode mask, and blend until coloured
// transmittance): whether the surface is a hole at uv. The alpha is the
// material's factor times the base-colour texture's alpha, read at level 0
// (the ray-traced reference reads the same texels, src/reference), so the
// camera, every shadow map and the truth cut the same holes. Needs the draw
// block and the base-colour texture bound at SL_UNIT_BASE_COLOR when
// draw.alpha.w says there is one.
#ifndef SHADOWLAB_ALPHA_TEST_H
#define SHADOWLAB_ALPHA_TEST_H
#include "shadowlab_shared.h"

layout(binding = SL_UNIT_BASE_COLOR) uniform sampler2D alphaTexture;

bool alphaCutOut(vec2 uv) {
    if (draw.alpha.z < 0.5) return false;
    float a = draw.alpha.x * (draw.alpha.w > 0.5 ? textureLod(alphaTexture, uv, 0.0).a : 1.0);
    return a < draw.alpha.y;
}
#endif
