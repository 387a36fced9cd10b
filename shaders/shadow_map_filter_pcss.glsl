// Technique "map", filter "pcss": percentage-closer soft shadows (Fernando
// 2005) for a light of size map.lightSize: a blocker search of map.blockerTaps
// taps, the penumbra's width by similar triangles, then map.filterTaps taps
// of percentage-closer filtering over it, each tap compared against the
// receiver's plane at its own place, not the centre's depth. The taps are
// bilinear compares, or with MAP_PCSS_NEAREST (a software rasteriser:
// LightPassVariant::pcssNearest) nearest depths compared here. The blocker
// search is shared by the 2x2 pixels of a quad (MAP_QUAD_SHARED,
// shadow_map_sampling.glsl): the quad's disk of map.blockerTaps taps, each
// pixel fetching every fourth about its own point and testing them against
// its own receiver plane, the blockers found and their depths summed over
// the quad; the filter's taps stay each pixel's own.

// How far from the receiver's ray the blocker search reaches, in light
// radii, for a receiver `dr` from the light (a spot: along its axis): a
// blocker db from the light shades it from within (dr - db) / db radii of
// its ray there, and none is nearer than map.blockerNear (the nearest
// caster drawn into the map); at most three radii (blockers at least a
// quarter of the way from the light), as where that is unknown (0).
float blockerReach(float dr) {
    float nearest = map.blockerNear;
    return nearest > 0.0 ? clamp((dr - nearest) / nearest, 0.0, 3.0) : 3.0;
}

#if MAP_CUBE
#if MAP_CUBE_WINDOW
#error MAP_CUBE_WINDOW is for the one-tap filters (MapSettings: cubeWindowDepth)
#endif
// The stored depths for the blocker search (distance / far): the cube
// through a sampler without comparison (rgba8: unpacked).
#if MAP_RGBA8
float cubeDepthAt(vec3 direction) { return unpackDepth(texture(mapCubePacked, vec4(direction, map.layer))); }
#elif MAP_LAYER_VIEW
SL_BINDING(SL_UNIT_SHADOW_FIRST + 1) uniform samplerCube mapCubeRaw;
float cubeDepthAt(vec3 direction) { return texture(mapCubeRaw, direction).r; }
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST + 1) uniform samplerCubeArray mapCubeRaw;
float cubeDepthAt(vec3 direction) { return texture(mapCubeRaw, vec4(direction, map.layer)).r; }
#endif

float cubeReach(float texel, float radius) { return 0.0; }  // each tap compares against the receiver's plane itself

// The reference depth of the receiver's plane (normal n, nv = n.v at the
// centre) where the tap's direction w meets it; the centre's `ref` when
// the plane does not face the light there.
float cubePlaneRef(vec3 w, vec3 n, float nv, float ref) {
    float nw = dot(n, w);
    return nv < 0.0 && nw < 0.0 ? length(w) * nv / nw / map.cubeFar - map.constantBias : ref;
}

// On a disk across the ray, for a sphere light of radius `size`.
float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    float size = map.lightSize;
    float dr = length(v);
    vec3 axis = v / dr;
    vec3 t = normalize(abs(axis.y) < 0.99 ? cross(axis, vec3(0.0, 1.0, 0.0)) : cross(axis, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(axis, t);
    float nv = dot(n, v);
    float rotation = mapRotation();
    // 1. Blockers within blockerReach radii of the ray at the receiver:
    // this pixel's share of the quad's search (found: blockers, the sum of
    // their distances, taps taken), none where it is lit without a test
    // (beyond the far plane or at the light: shadow_map_cube_lookup.glsl).
    float search = blockerReach(dr) * size;
    int blockerTaps = int(map.blockerTaps);
    vec3 found = vec3(0.0);
    int first = quadLane();
    vec2 d = vogelFirst(quadRotation() + float(first) * SL_MAP_GOLDEN_ANGLE);
    vec2 turn = vogelStep(4);
    for (int k = first; k < blockerTaps; k += 4, d = vogelTurnBy(d, turn)) {
        vec3 w = v + vogelOffset3D(k, blockerTaps, search, d, t, b);
        float depth = cubeDepthAt(w);
        if (depth < cubePlaneRef(w, n, nv, ref)) found.xy += vec2(1.0, depth * map.cubeFar);
        found.z += 1.0;
    }
    found = quadSum(dr > 0.0 && dr <= map.cubeFar ? found : vec3(0.0));
    float blockers = found.x;
    if (blockers == 0.0) return 1.0;
    float db = found.y / blockers;
    // 2. The penumbra's half width at the receiver, by similar triangles.
    float penumbra = size * (dr - db) / max(db, 1e-6);
#if MAP_EARLY_OUT
    // Umbra: every blocker tap blocked and the filter's disk inside their
    // hull (MapSettings: vogelHullInradius): every filter tap is too.
    if (blockers == found.z && penumbra <= map.blockerHull * search) return 0.0;
#endif
    // 3. Percentage-closer filtering over it.
    int taps = int(map.filterTaps);
    float sum = 0.0;
    d = vogelFirst(rotation);
    for (int k = 0; k < taps; ++k, d = vogelTurn(d)) {
        vec3 w = v + vogelOffset3D(k, taps, penumbra, d, t, b);
#if MAP_PCSS_NEAREST
        sum += cubePlaneRef(w, n, nv, ref) <= cubeDepthAt(w) ? 1.0 : 0.0;
#else
        sum += cubeTap(w, cubePlaneRef(w, n, nv, ref));
#endif
    }
    return sum / float(taps);
}
#else
// The stored depths for the blocker search: the same array through a
// sampler without comparison (rgba8: unpacked).
#if MAP_RGBA8
float mapDepthAt(float layer, vec2 uv) { return unpackDepth(texture(mapPacked, vec3(uv, layer))); }
#elif MAP_LAYER_VIEW
SL_BINDING(SL_UNIT_SHADOW_FIRST + 1) uniform sampler2D mapRaw;  // the layer's view
float mapDepthAt(float layer, vec2 uv) { return texture(mapRaw, uv).r; }
#else
SL_BINDING(SL_UNIT_SHADOW_FIRST + 1) uniform sampler2DArray mapRaw;
float mapDepthAt(float layer, vec2 uv) { return texture(mapRaw, vec3(uv, layer)).r; }
#endif

// The receiver plane's depth change per uv, from the screen derivatives of
// its texture-space point (m.dx, m.dy), clamped.
vec2 receiverDepthSlope(MapLookup m) {
    float det = m.dx.x * m.dy.y - m.dx.y * m.dy.x;
    vec2 dzduv = abs(det) > 1e-20 ? vec2(m.dy.y * m.dx.z - m.dx.y * m.dy.z, m.dx.x * m.dy.z - m.dy.x * m.dx.z) / det : vec2(0.0);
    return clamp(dzduv, vec2(-1e4), vec2(1e4));
}

float mapFilter(MapLookup m, vec2 uv, float ref) {
    float du = map.texelUv;
    vec2 dzduv = receiverDepthSlope(m);
    bool perspective = map.perspective > 0.5;
    float dr = mapDistance(ref, m.planes);
    float texel = perspective ? m.texelWorld * dr : m.texelWorld;
    float size = map.lightSize;
    float rotation = mapRotation();
    // 1. Blockers: stored depths nearer the light than the receiver's plane
    // within the region a blocker can shade it from: directional, the light's
    // angular radius over the depth up to the light camera's near plane;
    // spot, three radii at the receiver (blockers at least a quarter of the
    // way from the light; nearer where the nearest caster is known:
    // blockerReach). At most an eighth of the map.
    float limit = 0.125 / du;
    float search = clamp((perspective ? blockerReach(dr) * size : (dr - m.planes.x) * size) / texel, 1.0, limit);
    // This pixel's share of the quad's search (found: blockers, the sum of
    // their distances, taps taken), none outside the map (lit:
    // shadow_map_2d.glsl); all of it where it searches alone (a cascade's
    // fade into the next, where not every pixel of the quad runs: m.quad).
    int blockerTaps = int(map.blockerTaps);
    vec3 found = vec3(0.0);
    int first = m.quad ? quadLane() : 0, stride = m.quad ? 4 : 1;
    vec2 d = vogelFirst((m.quad ? quadRotation() : rotation) + float(first) * SL_MAP_GOLDEN_ANGLE);
    vec2 turn = vogelStep(stride);
    for (int k = first; k < blockerTaps; k += stride, d = vogelTurnBy(d, turn)) {
        vec2 o = vogelOffset2D(k, blockerTaps, search, d, du);
        float depth = mapDepthAt(m.layer, uv + o);
        if (depth < ref + dot(dzduv, o)) found.xy += vec2(1.0, mapDistance(depth, m.planes));
        found.z += 1.0;
    }
    vec3 quad = quadSum(m.inside ? found : vec3(0.0));
    if (m.quad) found = quad;
    float blockers = found.x;
    if (blockers == 0.0) return 1.0;
    float db = found.y / blockers;
    // 2. The penumbra's half width at the receiver, by similar triangles.
    float radius = min((perspective ? size * (dr - db) / max(db, 1e-6) : (dr - db) * size) / texel, limit);
#if MAP_EARLY_OUT
    // Umbra: every blocker tap blocked and the filter's disk inside their
    // hull (MapSettings: vogelHullInradius): every filter tap is too.
    if (blockers == found.z && radius <= map.blockerHull * search) return 0.0;
#endif
    // 3. Percentage-closer filtering over it.
    int taps = int(map.filterTaps);
    float sum = 0.0;
    d = vogelFirst(rotation);
    for (int k = 0; k < taps; ++k, d = vogelTurn(d)) {
        vec2 o = vogelOffset2D(k, taps, radius, d, du);
#if MAP_PCSS_NEAREST
        sum += ref + dot(dzduv, o) <= mapDepthAt(m.layer, uv + o) ? 1.0 : 0.0;
#else
        sum += mapTap(m.layer, uv + o, ref + dot(dzduv, o));
#endif
    }
    return sum / float(taps);
}
#endif
