// Technique "map", filters "none" and "hardware": one tap, through a
// nearest or a bilinear (2x2, hardware-compared) sampler (MapBindings.cpp
// picks it).
#if MAP_MOMENTS == 0 && (MAP_FILTER == SL_MAP_FILTER_NONE || MAP_FILTER == SL_MAP_FILTER_HARDWARE)
#if MAP_CUBE
// Bilinear: the 2x2 footprint (seamless across faces).
float cubeReach(float texel, float radius) { return MAP_FILTER == SL_MAP_FILTER_HARDWARE ? texel : 0.0; }
float cubeFilter(vec3 v, float ref, vec3 n, float radius) { return cubeTap(v, ref); }
#else
float mapFilter(MapLookup m, vec2 uv, float ref) { return mapTap(m.layer, uv, ref); }
#endif
#endif
