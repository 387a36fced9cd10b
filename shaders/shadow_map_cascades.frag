// Technique "map", debug view of cascaded maps (MAP_CASCADES > 1): each
// visible point in its cascade's colour (red, green, blue, yellow, magenta,
// cyan, orange, violet from near to far), mixed with the next cascade's
// colour in the blend band where the two fade into each other, and
// shaded by the light a little so the scene stays readable.
#include "shadow_map_shared.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;
layout(location = 0) out vec4 outColor;

const vec3 kCascadeColour[8] = vec3[](vec3(0.9, 0.2, 0.2), vec3(0.2, 0.8, 0.25), vec3(0.25, 0.4, 0.95), vec3(0.95, 0.85, 0.2),
                                      vec3(0.85, 0.3, 0.85), vec3(0.2, 0.85, 0.85), vec3(0.95, 0.55, 0.15), vec3(0.55, 0.35, 0.9));

void main() {
    float depth = cascadeDepth(vWorldPosition);
    int c = cascadeOf(depth);
    vec3 colour = kCascadeColour[c];
    if (c < MAP_CASCADES - 1) {
        float t = cascadeBlend(depth, c);
        if (t > 0.0) colour = mix(colour, kCascadeColour[c + 1], min(t, 1.0));
    }
    float lit = 0.55 + 0.45 * clamp(dot(normalize(vWorldNormal), map.towardsLight), 0.0, 1.0);
    outColor = vec4(colour * lit, 1.0);
}
