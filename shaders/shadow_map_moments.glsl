// Technique "map", filterable moment maps (representation vsm, evsm2,
// evsm4, msm; shadow_map_shared.h momentsOf writes them): the filtered
// moments bound the share of occluders nearer than the receiver.
#if MAP_CUBE
#error moment maps are for 2D maps
#endif
// Chebyshev's upper bound on the share of the filtered region at least as
// far as t, from its mean and mean square (VSM, each EVSM warp).
float chebyshev(vec2 m, float t, float minVariance) {
    if (t <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    return variance / (variance + d * d);
}

#if MAP_MOMENTS == SL_MAP_MOMENTS_MSM
// Hamburger 4-moment shadow intensity (Peters and Klein 2015, algorithm 3):
// the least upper bound on the occluded share given four moments, from the
// biased moments' Cholesky factorisation and a quadratic's two roots.
float msmShadow(vec4 b, float z) {
    b = mix(b, vec4(0.5), MAP_MOMENT_BIAS);
    float l32d22 = -b.x * b.y + b.z;
    float d22 = -b.x * b.x + b.y;
    float squaredDepthVariance = -b.y * b.y + b.w;
    float d33d22 = dot(vec2(squaredDepthVariance, -l32d22), vec2(d22, l32d22));
    float invD22 = 1.0 / d22;
    float l32 = l32d22 * invD22;
    vec3 c = vec3(1.0, z, z * z);
    c.y -= b.x;
    c.z -= b.y + l32 * c.y;
    c.y *= invD22;
    c.z *= d22 / d33d22;
    c.y -= l32 * c.z;
    c.x -= dot(c.yz, b.xy);
    float p = c.y / c.z, q = c.x / c.z;
    float r = sqrt(max(p * p * 0.25 - q, 0.0));
    float z1 = -p * 0.5 - r, z2 = -p * 0.5 + r;
    vec4 select = z2 < z ? vec4(z1, z, 1.0, 1.0) : (z1 < z ? vec4(z, z1, 0.0, 1.0) : vec4(0.0));
    float quotient = (select.x * z2 - b.x * (select.x + z2) + b.y) / ((z2 - select.y) * (z - z1));
    return clamp(select.z + select.w * quotient, 0.0, 1.0);
}
#endif

// The filtered moments at uv of layer `layer` (planes: a spot's near and
// far, which linearise its depth as shadow_map_blur.frag does).
#if MAP_MOMENTS_FROM_DEPTH
// Taken from the depth itself (map/passes/Arrays.h: momentsFromDepth): the four
// depth texels a bilinear lookup reads, gathered, their moments blended
// with the bilinear weights, which is what a bilinear lookup of moments
// made per texel returns (with no blur, no mipmaps, 32-bit moments).
vec4 momentsOfDepth(float z, vec2 planes) {
    z = clamp(z, 0.0, 1.0);
    if (map.perspective > 0.5) z = (perspectiveDistance(z, planes.x, planes.y) - planes.x) / (planes.y - planes.x);
    return momentsOf(z);
}
vec4 filteredMoments(vec2 uv, float layer, vec2 planes) {
    vec2 f = fract(uv * vec2(textureSize(mapMoments, 0).xy) - 0.5);
    vec4 d = textureGather(mapMoments, vec3(uv, layer));  // (i0, j1), (i1, j1), (i1, j0), (i0, j0)
    vec4 below = mix(momentsOfDepth(d.w, planes), momentsOfDepth(d.z, planes), f.x);
    vec4 above = mix(momentsOfDepth(d.x, planes), momentsOfDepth(d.y, planes), f.x);
    return mix(below, above, f.y);
}
#else
vec4 filteredMoments(vec2 uv, float layer, vec2 planes) { return texture(mapMoments, vec3(uv, layer)); }
#endif

// A moment map's visibility at uv for the receiver's depth `ref`: the
// filtered moments (bilinear, mipmapped when asked, blurred by the shadow
// pass) bound the share of occluders nearer than the receiver from above;
// values under bleedReduction are cut (less light bleeding, darker
// penumbrae).
float mapFilter(MapLookup m, vec2 uv, float ref) {
    float z = map.perspective > 0.5 ? (mapDistance(ref, m.planes) - m.planes.x) / (m.planes.y - m.planes.x) : ref;
    vec4 moments = filteredMoments(uv, m.layer, m.planes);
#if MAP_MOMENTS == SL_MAP_MOMENTS_VSM
    float v = chebyshev(moments.xy, z, MAP_MIN_VARIANCE);
#elif MAP_MOMENTS == SL_MAP_MOMENTS_MSM
    float v = 1.0 - msmShadow(moments, z);
#else
    // EVSM: each warp's bound, the floor of the variance scaled by the warp's slope.
    float w = 2.0 * z - 1.0;
    float positive = exp(MAP_EVSM_POSITIVE * w);
    float slope = 1e-4 * MAP_EVSM_POSITIVE * positive;
    float v = chebyshev(moments.xy, positive, slope * slope);
#if MAP_MOMENTS == SL_MAP_MOMENTS_EVSM4
    float negative = -exp(-MAP_EVSM_NEGATIVE * w);
    float slopeN = 1e-4 * MAP_EVSM_NEGATIVE * negative;
    v = min(v, chebyshev(moments.zw, negative, slopeN * slopeN));
#endif
#endif
    return clamp((v - map.bleedReduction) / (1.0 - map.bleedReduction), 0.0, 1.0);
}
