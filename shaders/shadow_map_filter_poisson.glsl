// Technique "map", filter "poisson": a Vogel disk (golden-angle spiral,
// uniform by area) of map.filterTaps taps rotated per pixel, within
// map.poissonRadius texels (2D maps) or across the ray within the radius (cube
// maps: no taps wasted along the ray).
#if MAP_CUBE
float cubeReach(float texel, float radius) { return radius; }

float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    vec3 axis = normalize(v);
    vec3 t = normalize(abs(axis.y) < 0.99 ? cross(axis, vec3(0.0, 1.0, 0.0)) : cross(axis, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(axis, t);
    int taps = int(map.filterTaps);
    vec2 d = vogelFirst(mapRotation());
    float sum = 0.0;
    for (int k = 0; k < taps; ++k, d = vogelTurn(d)) sum += cubeTap(v + vogelOffset3D(k, taps, radius, d, t, b), ref);
    return sum / float(taps);
}
#else
float mapFilter(MapLookup m, vec2 uv, float ref) {
    int taps = int(map.filterTaps);
    vec2 d = vogelFirst(mapRotation());
    float sum = 0.0;
    for (int k = 0; k < taps; ++k, d = vogelTurn(d)) sum += mapTap(m.layer, uv + vogelOffset2D(k, taps, map.poissonRadius, d, map.texelUv), ref);
    return sum / float(taps);
}
#endif
