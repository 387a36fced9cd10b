// Light pass: one light's Blinn-Phong diffuse and specular (lecture 000,
// "passTwo"), scaled by the light's visibility, added onto the base pass.
// Variants: LIGHT_TYPE (SL_LIGHT_*), SHADOW_TECHNIQUE (SL_SHADOW_*),
// HAS_BASE_COLOR_TEXTURE (0/1), SCREEN_VISIBILITY (0/1: visibility from a
// per-pixel texture, the ray-traced reference, instead of the technique),
// OUTPUT_VISIBILITY (0/1: write the visibility term itself, for compare).
#include "shadowlab_shared.h"
#include "light_reach.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;

#if HAS_BASE_COLOR_TEXTURE
layout(binding = SL_UNIT_BASE_COLOR) uniform sampler2D baseColorTexture;
#endif

#if SCREEN_VISIBILITY
layout(binding = SL_UNIT_SCREEN_VISIBILITY) uniform sampler2D screenVisibility;
#endif

layout(location = SL_TARGET_COLOR) out vec4 outColor;

// The hook every shadow technique plugs into: 1 = lit, 0 = shadowed.
float shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
#if SCREEN_VISIBILITY
    return texelFetch(screenVisibility, ivec2(gl_FragCoord.xy), 0).r;
#elif SHADOW_TECHNIQUE == SL_SHADOW_NONE
    return 1.0;
#else
#error unknown SHADOW_TECHNIQUE
#endif
}

void main() {
    vec3 N = normalize(vWorldNormal);
    vec3 V = normalize(frame.cameraPosition.xyz - vWorldPosition);
    // Two-sided lighting: a back face seen by the camera is lit as its front.
    if (!gl_FrontFacing) N = -N;
#if OUTPUT_VISIBILITY
    // The shadow term alone, for every pixel: compare classifies it.
    outColor = vec4(shadowVisibility(vWorldPosition, N), 0.0, 0.0, 1.0);
    return;
#endif

    vec3 L;
    float attenuation = 1.0;
#if LIGHT_TYPE == SL_LIGHT_DIRECTIONAL
    L = -light.direction.xyz;
#else
    vec3 toLight = light.position.xyz - vWorldPosition;
    L = normalize(toLight);
    if (!slLightReaches(LIGHT_TYPE, light.position.xyz, light.direction.xyz, light.params.x, light.params.z, vWorldPosition))
        discard;
#if LIGHT_TYPE == SL_LIGHT_SPOT
    // Smooth falloff between the inner and outer cone (cosines in params.yz).
    float cosAngle = dot(-L, light.direction.xyz);
    attenuation *= smoothstep(light.params.z, light.params.y, cosAngle);
#endif
#endif
    float NdotL = max(dot(N, L), 0.0);
    if (NdotL <= 0.0 || attenuation <= 0.0) discard;

    vec3 base = draw.baseColor.rgb;
#if HAS_BASE_COLOR_TEXTURE
    base *= texture(baseColorTexture, vUv).rgb;
#endif
    vec3 H = normalize(L + V);
    vec3 diffuse = draw.diffuse.rgb * base * NdotL;
    vec3 specular = draw.specular.rgb * pow(max(dot(N, H), 0.0), draw.specular.w);
    float visibility = shadowVisibility(vWorldPosition, N);
    outColor = vec4(visibility * attenuation * light.radiance.rgb * (diffuse + specular), 1.0);
}
