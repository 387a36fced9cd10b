// Every pass that shades scene geometry: the base pass (ambient, and one
// light merged in when its technique allows) and the additive pass of each
// further light. Blinn-Phong as in the lecture (Wolberg, "passTwo"):
//   colour = globalAmbient*ambient*base
//          + visibility * light * (diffuse*base*max(N.L,0) + specular*max(N.H,0)^shininess)
// Variants (ShaderVariant): AMBIENT, LIGHT (0/1: the ambient term, one
// light's term), LIGHT_LIST (the clustered list's lights), LIGHT_LIST_SHADOWS
// (some of them with shadows: their technique's lookup fills the
// "@list_shadow" slot), LIGHT_TYPE (SL_LIGHT_*), HAS_BASE_COLOR_TEXTURE,
// ALPHA_TEST (alphaMode mask: discard under the cutoff),
// WRITE_SURFACES (world position and geometric normal for the reference),
// SCREEN_VISIBILITY (visibility from a per-pixel texture: the ray-traced
// reference), OUTPUT_VISIBILITY (write the visibility term itself, for
// compare), BLENDED (write the material's alpha: translucent surfaces, drawn
// last over the frame). The technique's GLSL fills the "@shadow" slot with
// vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal); where it
// defines SHADOW_QUAD_UNIFORM (it shares work across a 2x2 quad through
// derivatives) the test runs first, before any discard or branch.
#include "shadowlab_shared.h"
#include "light_reach.h"
#include "alpha_test.h"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;

#if HAS_BASE_COLOR_TEXTURE
SL_BINDING(SL_UNIT_BASE_COLOR) uniform sampler2D baseColorTexture;
#endif
#if HAS_PROJECTOR
SL_BINDING(SL_UNIT_PROJECTOR) uniform sampler2D projectorImage;
#endif

layout(location = SL_TARGET_COLOR) out vec4 outColor;
#if WRITE_SURFACES
layout(location = SL_TARGET_POSITION) out vec4 outPosition;
layout(location = SL_TARGET_NORMAL) out vec4 outNormal;
#endif

#if LIGHT
#if SCREEN_VISIBILITY
SL_BINDING(SL_UNIT_SCREEN_VISIBILITY) uniform sampler2D screenVisibility;
vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    return vec3(texelFetch(screenVisibility, ivec2(gl_FragCoord.xy), 0).r);
}
#else
#include "@shadow"
#endif
// Where `receivesShadows` applies (and in the light list's loop below): a node that does not receive
// shadows is lit whatever the technique (or the reference) says.
vec3 lightVisibility(vec3 worldPosition, vec3 worldNormal) {
    return draw.baseColor.w > 0.5 ? shadowVisibility(worldPosition, worldNormal) : vec3(1.0);
}
#endif

#if LIGHT || LIGHT_LIST
// A light's diffuse and specular at this fragment, before visibility, for
// a light of `type` (SL_LIGHT_*) at `position` travelling along
// `direction`, with `params` as LightUniforms.params and `radiance` its
// colour; `reached` false outside the light's reach or facing away; L the
// unit direction towards the light (the light list's shadow lookups take it).
vec3 lightTermOf(int type, vec3 position, vec3 direction, vec4 params, vec3 radiance, vec3 N, vec3 V, vec3 base, out bool reached, out vec3 L) {
    float attenuation = 1.0;
    if (type == SL_LIGHT_DIRECTIONAL) {
        L = -direction;
    } else {
        L = normalize(position - vWorldPosition);
        if (!slLightReaches(type, position, direction, params.x, params.z, vWorldPosition))
            attenuation = 0.0;
        // Smooth falloff between the inner and outer cone (cosines in params.yz).
        if (type == SL_LIGHT_SPOT) attenuation *= smoothstep(params.z, params.y, dot(-L, direction));
    }
    float NdotL = max(dot(N, L), 0.0);
    reached = NdotL > 0.0 && attenuation > 0.0;
    if (!reached) return vec3(0.0);
    vec3 H = normalize(L + V);
    vec3 diffuse = draw.diffuse.rgb * base * NdotL;
    vec3 specular = draw.specular.rgb * pow(max(dot(N, H), 0.0), draw.specular.w);
    return attenuation * radiance * (diffuse + specular);
}
#endif

#if LIGHT
// The one light of this pass (LIGHT_TYPE a constant, so the branches above
// fold away).
vec3 lightTerm(vec3 N, vec3 V, vec3 base, out bool reached) {
    vec3 radiance = light.radiance.rgb;
#if HAS_PROJECTOR
    // The slide projector (Wolberg's lecture): projective texture coordinates from
    // the spot's camera; black outside the image. Image rows run top to
    // bottom, so v is flipped.
    vec4 c = light.projectorFromWorld * vec4(vWorldPosition, 1.0);
    vec2 uv = c.xy / c.w * 0.5 + 0.5;
    bool onSlide = c.w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    radiance *= onSlide ? texture(projectorImage, vec2(uv.x, 1.0 - uv.y)).rgb : vec3(0.0);
#endif
    vec3 L;
    return lightTermOf(LIGHT_TYPE, light.position.xyz, light.direction.xyz, light.params, radiance, N, V, base, reached, L);
}
#endif

#if LIGHT_LIST
// The lights beyond the base pass's that have no shadow pass after it
// (none, or a map in the shadow atlas), in one pass: the lights whose
// reach overlaps this pixel's cluster, its tile and the slice of the view
// its depth lies in (geometry/LightTiles.h; src/render/LightList.cpp bins them
// on the CPU each frame).
#if LIGHT_LIST_SHADOWS
#include "@list_shadow"
#endif
layout(std430) SL_BINDING(SL_STORAGE_LIGHT_LIST) readonly buffer LightList { ListedLight listed[]; };
layout(std430) SL_BINDING(SL_STORAGE_LIGHT_TILES) readonly buffer LightTiles {
    uvec4 tiling;  // tile size in pixels, tiles across, tiles down, depth slices
    vec4 slicing;  // x: the view depth the slices are counted from, y: slices per unit of log(depth / x)
    uint cells[];  // per cluster (first, count) into cells itself, then the light indices
};

vec3 listedLightsTerm(vec3 N, vec3 V, vec3 base, out bool reached) {
    uvec2 tile = min(uvec2(gl_FragCoord.xy) / tiling.x, tiling.yz - 1u);
    // The pixel's slice from its view depth (clip w = 1 / gl_FragCoord.w), as LightTiles::sliceOf.
    float slice = floor(log(1.0 / (gl_FragCoord.w * slicing.x)) * slicing.y);
    uint s = uint(clamp(slice, 0.0, float(tiling.w - 1u)));
    uint t = (s * tiling.z + tile.y) * tiling.y + tile.x;
    uint first = cells[2u * t], count = cells[2u * t + 1u];
    vec3 sum = vec3(0.0);
    reached = false;
    for (uint k = 0u; k < count; ++k) {
        ListedLight l = listed[cells[first + k]];
        bool one;
        vec3 L;
        vec3 term = lightTermOf(int(l.params.w), l.position.xyz, l.direction.xyz, l.params, l.radiance.rgb, N, V, base, one, L);
#if LIGHT_LIST_SHADOWS
        if (one && l.shadow.y > 0.0 && draw.baseColor.w > 0.5) {  // receivesShadows (the atlas: spot and point lights)
            term *= listedVisibility(l.shadow, l.position.xyz, vWorldPosition, N, L, clamp(dot(N, L), 0.0, 1.0));
        }
#endif
        if (one) sum += term;
        reached = reached || one;
    }
    return sum;
}
#endif

void main() {
    vec3 N = normalize(vWorldNormal);
    // Two-sided lighting: a back face seen by the camera is lit as its front.
    if (!gl_FrontFacing) N = -N;
#if LIGHT && SHADOW_QUAD_UNIFORM
    // Where every fragment of the quad runs (the technique's derivatives).
    vec3 visibility = lightVisibility(vWorldPosition, N);
#define SL_VISIBILITY visibility
#elif LIGHT
#define SL_VISIBILITY lightVisibility(vWorldPosition, N)
#endif
#if ALPHA_TEST
    if (alphaCutOut(vUv)) discard;  // a hole in an alpha-tested surface: nothing drawn, no surface for the reference
#endif
#if OUTPUT_VISIBILITY && LIGHT
    // The shadow term alone, for every pixel: compare classifies it.
    outColor = vec4(SL_VISIBILITY, 1.0);
    return;
#endif

    vec3 base = draw.baseColor.rgb;
    float alpha = draw.alpha.x;
#if HAS_BASE_COLOR_TEXTURE
    vec4 texel = texture(baseColorTexture, vUv);
    base *= texel.rgb;
    alpha *= texel.a;
#endif
    vec3 color = vec3(0.0);
#if AMBIENT
    color += frame.ambient.rgb * draw.ambient.rgb * base;
#endif
#if LIGHT
    vec3 V = normalize(frame.cameraPosition.xyz - vWorldPosition);
    bool reached;
    vec3 term = lightTerm(N, V, base, reached);
#if !AMBIENT
    if (!reached) discard;  // an additive pass adds nothing here
#endif
    if (reached) color += SL_VISIBILITY * term;
#endif
#if LIGHT_LIST
    vec3 V = normalize(frame.cameraPosition.xyz - vWorldPosition);
    bool reached;
    color += listedLightsTerm(N, V, base, reached);
    if (!reached) discard;  // an additive pass adds nothing here
#endif
    // A translucent surface's alpha weighs it over what is behind (BLENDED);
    // opaque passes store 1.
    outColor = vec4(color, BLENDED != 0 ? alpha : 1.0);

#if WRITE_SURFACES
    // Geometric (flat) normal from screen-space derivatives of the position,
    // turned towards the camera: the normal of the visible triangle itself.
    vec3 geometric = normalize(cross(dFdx(vWorldPosition), dFdy(vWorldPosition)));
    if (dot(geometric, frame.cameraPosition.xyz - vWorldPosition) < 0.0) geometric = -geometric;
    outPosition = vec4(vWorldPosition, 1.0);
    outNormal = vec4(geometric, draw.baseColor.w);
#endif
}
