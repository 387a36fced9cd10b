// Technique "map", filter "none": one tap through a nearest sampler.
#if MAP_CUBE
float cubeReach(float texel, float radius) { return 0.0; }
float cubeFilter(vec3 v, float ref, vec3 n, float radius) { return cubeTap(v, ref); }
#else
float mapFilter(MapLookup m, vec2 uv, float ref) { return mapTap(m.layer, uv, ref); }
#endif
