// Technique "map", filter "grid": the lecture's percentage-closer filter,
// MAP_KERNEL x MAP_KERNEL comparisons one texel apart (2D maps), or the
// lecture's 3-D grid of MAP_KERNEL^3 offsets around the ray (cube maps, Lawonn's lecture).
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
#elif MAP_EARLY_OUT
// The same MAP_KERNEL x MAP_KERNEL nearest taps, the kernel's corners
// first (after an odd kernel's centre), and the rest, four at a time, only
// where those disagree: a shadow edge that runs straight across the kernel
// leaves the corners on both sides of it, so agreeing corners (and centre)
// put every tap between them on their side (MapOptions::earlyOut). Rounds
// of four so that a round is one stretch of code; their count comes from
// the block (map.kernelRounds) so that the compiler keeps the loop, whose
// rounds a rasteriser can skip only as a whole (MapSettings: kernelRounds).

// Cell k (column, row) of the kernel in that order: the four corners, then
// the others row by row, leaving out the corners and an odd kernel's
// centre (taken first, outside this order).
ivec2 gridCell(int k) {
    const int n = MAP_KERNEL;
    if (k < 4) return ivec2(k & 1, k >> 1) * (n - 1);
    int q = k - 3;                            // past cell 0, a corner
    q += q >= n - 1 ? 1 : 0;                  // past the corner ending row 0
    if (n % 2 == 1) q += q >= (n * n - 1) / 2 ? 1 : 0;  // past the centre
    q += q >= n * n - n ? 1 : 0;              // past the corner starting the last row
    return ivec2(q % n, q / n);
}

float mapFilter(MapLookup m, vec2 uv, float ref) {
    float du = map.texelUv;
    float start = -0.5 * float(MAP_KERNEL - 1);
    float sum = 0.0, taken = 0.0;
#if MAP_KERNEL % 2 == 1
    sum = mapTap(m.layer, uv + du * vec2(start + float(MAP_KERNEL / 2)), ref);
    taken = 1.0;
#endif
    int rounds = int(map.kernelRounds);
    for (int r = 0; r < rounds; ++r) {
        for (int j = 0; j < 4; ++j) {
#if MAP_KERNEL == 3
            // The default kernel (and LearnOpenGL's): gridCell's cells as
            // offsets written out (its integer arithmetic cost llvmpipe
            // about what the skipped taps saved), corners then edges.
            vec2 o = r == 0 ? vec2((j & 1) != 0 ? 1.0 : -1.0, (j & 2) != 0 ? 1.0 : -1.0)
                            : vec2(j == 0 ? 1.0 : j == 1 ? -1.0 : 0.0, j == 2 ? 1.0 : j == 3 ? -1.0 : 0.0);
            sum += mapTap(m.layer, uv + du * o, ref);
#else
            ivec2 c = gridCell(4 * r + j);
            sum += mapTap(m.layer, uv + du * vec2(start + float(c.x), start + float(c.y)), ref);
#endif
        }
        taken += 4.0;
        if (r == 0 && (sum == 0.0 || sum == taken)) break;  // the corners (and centre) agree
    }
    return sum / taken;
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
