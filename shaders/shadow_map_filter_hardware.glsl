// Technique "map", filter "hardware": one tap through a bilinear sampler,
// the 2x2 texels around it compared in hardware and weighted (seamless
// across a cube's faces).
#if MAP_CUBE
float cubeReach(float texel, float radius) { return texel; }  // the 2x2 footprint
float cubeFilter(vec3 v, float ref, vec3 n, float radius) { return cubeTap(v, ref); }
#else
float mapFilter(MapLookup m, vec2 uv, float ref) { return mapTap(m.layer, uv, ref); }
#endif
