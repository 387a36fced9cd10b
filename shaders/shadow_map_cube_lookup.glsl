// Technique "map", the light pass for a point light's cube map (Lawonn's
// lecture; shadow_map.glsl includes it when MAP_CUBE): the fragment's vector
// from the light looks the map up, its distance over the far plane is the
// reference (all per fragment: a point light's texel size and N.L change
// too much across a wall-sized triangle to interpolate), and the filter's
// kernel (shadow_map_filter_*.glsl) compares around it.

#if MAP_RGBA8
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform samplerCubeArray mapCubePacked;
float cubeTap(vec3 direction, float ref) {
    return ref <= unpackDepth(texture(mapCubePacked, vec4(direction, map.layer))) ? 1.0 : 0.0;
}
#else
#if MAP_CUBE_WINDOW
// The stored depth is the face's window depth, reversed (MapSettings:
// cubeWindowDepth): with n, f the cube's near and far planes and z the
// point's distance along the face's axis (the direction's largest
// component), n (f - z) / ((f - n) z). The kernels keep working in
// distance / far: a reference turns into that depth for its direction.
// Lit where the receiver's window depth is the greater. The shadow pass's
// constant offset (map.cubeOffset) is taken off here. Only the one-tap
// filters take this measure; PCSS's blocker search reads distance / far.
float cubeStored(vec3 direction, float ref) {
    vec3 a = abs(direction);
    float axis = (ref - map.cubeOffset) * map.cubeFar * max(a.x, max(a.y, a.z)) * inversesqrt(dot(direction, direction));
    float n = map.nearPlane, f = map.farPlane;
    return n * (f - axis) / ((f - n) * axis);
}
#define SL_CUBE_REF(direction, ref) cubeStored(direction, ref)
#else
#define SL_CUBE_REF(direction, ref) (ref)
#endif
#if MAP_PLAIN_FETCH
// A software rasteriser: the nearest depth at level 0, compared here
// (LightPassVariant::plainFetch; the comparison sampler's LEQUAL, or
// GEQUAL for a reversed window depth).
// The light's six layers as a cube of their own (MAP_LAYER_VIEW:
// MapSettings layerView) or the array with the light's layer.
#if MAP_LAYER_VIEW
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform samplerCube mapCubePlain;
float cubeStoredAt(vec3 direction) { return textureLod(mapCubePlain, direction, 0.0).r; }
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform samplerCubeArray mapCubePlain;
float cubeStoredAt(vec3 direction) { return textureLod(mapCubePlain, vec4(direction, map.layer), 0.0).r; }
#endif
#if MAP_CUBE_WINDOW
// cubeStored(direction, ref) >= stored without its root and division, per
// tap: with k = n f / ((f - n) (ref - offset) far) (the same for a
// kernel's taps of one reference) and m the direction's largest
// component, k |direction| / m - n / (f - n) >= stored, squared.
float cubeTap(vec3 direction, float ref) {
    float stored = cubeStoredAt(direction);
    float n = map.nearPlane, f = map.farPlane;
    float k = n * f / ((f - n) * (ref - map.cubeOffset) * map.cubeFar);
    vec3 a = abs(direction);
    float rhs = (stored + n / (f - n)) * max(a.x, max(a.y, a.z));
    return k <= 0.0 || k * k * dot(direction, direction) >= rhs * rhs ? 1.0 : 0.0;
}
#else
float cubeTap(vec3 direction, float ref) { return ref <= cubeStoredAt(direction) ? 1.0 : 0.0; }
#endif
#elif MAP_LAYER_VIEW
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform samplerCubeShadow mapCube;
float cubeTap(vec3 direction, float ref) { return texture(mapCube, vec4(direction, SL_CUBE_REF(direction, ref))); }
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform samplerCubeArrayShadow mapCube;
float cubeTap(vec3 direction, float ref) { return texture(mapCube, vec4(direction, map.layer), SL_CUBE_REF(direction, ref)); }
#endif
#endif

// Translucent casters (alphaMode blend): the cube's transmittance and the
// nearest translucent depth (shadow_map_cube_transmit.frag).
SL_BINDING(SL_UNIT_SHADOW_FIRST + 2) uniform samplerCubeArray mapCubeTransmitColour;
SL_BINDING(SL_UNIT_SHADOW_FIRST + 3) uniform samplerCubeArray mapCubeTransmitDepth;
vec3 cubeTransmittanceAt(vec3 direction, float ref) {
#if MAP_TRANSMIT
    float nearest = texture(mapCubeTransmitDepth, vec4(direction, map.layer)).r;
    return ref > nearest ? texture(mapCubeTransmitColour, vec4(direction, map.layer)).rgb : vec3(1.0);
#else
    return vec3(1.0);  // no translucent casters this frame (LightPassVariant::transmittance)
#endif
}

// The filter's kernel (shadow_map_filter_*.glsl): its reach from the
// centre in world units for a texel of world size `texel` and the radius
// at the fragment, and the filtered test around the vector v from the
// light for reference depth `ref` (n: the receiver's normal).
float cubeReach(float texel, float radius);
float cubeFilter(vec3 v, float ref, vec3 n, float radius);

// The shadow test's visibility, 0 (shadowed) to 1 (lit); `transmit`, the
// translucent casters' transmittance. At the light or beyond the far
// plane: lit (Navarro Rosales). The filter runs there too and its answer is dropped,
// with no early return (a rasteriser that runs both sides of a branch paid
// for the return's masks; PCSS's quad-shared search needs every fragment
// of the quad to run it: it sees from its vector that such a fragment
// takes no share).
float mapVisibility(vec3 worldPosition, vec3 worldNormal, inout vec3 transmit) {
    vec3 toLight = map.lightPosition - worldPosition;
    float d = length(toLight);
    bool lit = d <= 0.0;
    d = lit ? 1.0 : d;
    vec3 L = toLight / d;
    vec3 n = worldNormal;
    float NdotL = clamp(dot(n, L), 0.0, 1.0);
    // World size of one texel at this distance (largest at a face's centre).
    float texel = d * map.cubeTexelPerDistance;
    // Filter radius at the fragment, growing with the viewer's distance (Lawonn).
    float radius = map.diskRadius * (1.0 + map.diskGrowth * length(frame.cameraPosition.xyz - worldPosition) / map.cubeFar);
    float reachWorld = cubeReach(texel, radius);
    vec3 p = worldPosition;
#if MAP_PRESET_BIAS
    // The presets: their constant bias only (in stored-depth units).
    float ref = length(p - map.lightPosition) / map.cubeFar - map.constantBias;
#else
    // The normal offset, then the receiver-plane bias for the filter's
    // reach (as for 2D maps, along the ray: shadow_map_bias.glsl).
    p = mapNormalOffset(p, n, NdotL, texel);
    float tanTheta = mapTanTheta(n, L, NdotL);
    float ref = (length(p - map.lightPosition) - reachWorld * tanTheta) / map.cubeFar - map.constantBias;
#endif
    vec3 v = p - map.lightPosition;
    lit = lit || length(v) > map.cubeFar;
    if (!lit) transmit = cubeTransmittanceAt(v, ref);
    float visibility = cubeFilter(v, ref, n, radius);
    return lit ? 1.0 : visibility;
}
