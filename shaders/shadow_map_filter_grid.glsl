// Technique "map", filter "grid": the lecture's percentage-closer filter,
// MAP_KERNEL x MAP_KERNEL comparisons one texel apart (2D maps), or the
// lecture's 3-D grid of MAP_KERNEL^3 offsets around the ray (cube maps, 001).
#if MAP_CUBE
float cubeReach(float texel, float radius) { return radius * 1.7320508; }  // the grid's corners

// Offsets evenly from -radius to +radius on each axis (64 for kernel 4).
float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    float sum = 0.0;
    float step = MAP_KERNEL > 1 ? 2.0 * radius / float(MAP_KERNEL - 1) : 0.0;
    for (int z = 0; z < MAP_KERNEL; ++z)
        for (int y = 0; y < MAP_KERNEL; ++y)
            for (int x = 0; x < MAP_KERNEL; ++x)
                sum += cubeTap(v + (vec3(x, y, z) * step - vec3(MAP_KERNEL > 1 ? radius : 0.0)), ref);
    return sum / float(MAP_KERNEL * MAP_KERNEL * MAP_KERNEL);
}
#elif !MAP_GRID_BILINEAR
// MAP_KERNEL x MAP_KERNEL nearest taps one texel apart, centred on the point.
float mapFilter(MapLookup m, vec2 uv, float ref) {
    float du = map.texelUv;
    float sum = 0.0;
    float start = -0.5 * float(MAP_KERNEL - 1);
    for (int j = 0; j < MAP_KERNEL; ++j)
        for (int i = 0; i < MAP_KERNEL; ++i)
            sum += mapTap(m.layer, uv + du * vec2(start + float(i), start + float(j)), ref);
    return sum / float(MAP_KERNEL * MAP_KERNEL);
}
#else
// The same MAP_KERNEL x MAP_KERNEL nearest taps, from as few bilinear
// hardware compares as the kernel allows: the nearest taps read the N
// consecutive texels from k0 = floor(t - (N - 1) / 2) on each axis (t:
// the point in texel units). A bilinear compare at the corner between two
// texels averages exactly those two, one at a texel's centre reads that
// texel alone; so pairs of texels take one tap of weight 2, an odd last
// texel one tap of weight 1: ceil(N / 2)^2 taps (4 for 3x3, 16 for 8x8)
// give the box average of the N^2 comparisons.
float mapFilter(MapLookup m, vec2 uv, float ref) {
    float du = map.texelUv;
    vec2 t = uv / du;
    vec2 k0 = floor(t - 0.5 * float(MAP_KERNEL - 1));
    const int taps = (MAP_KERNEL + 1) / 2;
    float sum = 0.0;
    for (int j = 0; j < taps; ++j) {
        bool pairY = 2 * j + 1 < MAP_KERNEL;
        float wy = pairY ? 2.0 : 1.0;
        float y = k0.y + float(2 * j) + (pairY ? 1.0 : 0.5);
        for (int i = 0; i < taps; ++i) {
            bool pairX = 2 * i + 1 < MAP_KERNEL;
            float wx = pairX ? 2.0 : 1.0;
            float x = k0.x + float(2 * i) + (pairX ? 1.0 : 0.5);
            sum += wx * wy * mapTap(m.layer, vec2(x, y) * du, ref);
        }
    }
    return sum / float(MAP_KERNEL * MAP_KERNEL);
}
#endif
