// Base pass: writes depth, the ambient term (lit or not, every surface gets
// globalAmbient * ambient * base), and the surface data later passes and the
// ray-traced reference read: world position and geometric normal.
#include "shadowlab_shared.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;

#if HAS_BASE_COLOR_TEXTURE
layout(binding = SL_UNIT_BASE_COLOR) uniform sampler2D baseColorTexture;
#endif

layout(location = SL_TARGET_COLOR) out vec4 outColor;
layout(location = SL_TARGET_POSITION) out vec4 outPosition;
layout(location = SL_TARGET_NORMAL) out vec4 outNormal;

void main() {
    vec3 base = draw.baseColor.rgb;
#if HAS_BASE_COLOR_TEXTURE
    base *= texture(baseColorTexture, vUv).rgb;
#endif
    outColor = vec4(frame.ambient.rgb * draw.ambient.rgb * base, 1.0);
    // Geometric (flat) normal from screen-space derivatives of the position,
    // turned towards the camera: the normal of the visible triangle itself.
    vec3 geometric = normalize(cross(dFdx(vWorldPosition), dFdy(vWorldPosition)));
    if (dot(geometric, frame.cameraPosition.xyz - vWorldPosition) < 0.0) geometric = -geometric;
    outPosition = vec4(vWorldPosition, 1.0);
    outNormal = vec4(geometric, draw.baseColor.w);
}
