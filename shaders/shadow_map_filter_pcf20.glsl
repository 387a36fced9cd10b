// Technique "map", filter "pcf20": the lecture's 20 offset directions
// (Lawonn) times the radius, far apart, none along the ray. Cube maps only.
#if !MAP_CUBE
#error filter pcf20 is for point lights' cube maps
#endif
const vec3 kPcf20[20] = vec3[](
    vec3(1, 1, 1), vec3(1, -1, 1), vec3(-1, -1, 1), vec3(-1, 1, 1),
    vec3(1, 1, -1), vec3(1, -1, -1), vec3(-1, -1, -1), vec3(-1, 1, -1),
    vec3(1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0), vec3(-1, 1, 0),
    vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
    vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, -1, -1), vec3(0, 1, -1));

float cubeReach(float texel, float radius) { return radius * 1.7320508; }  // |(1, 1, 1)| x radius

#if MAP_EARLY_OUT
// The same 20 directions in rounds of four: the cube's eight corners
// (first two rounds), then its twelve edge midpoints, which are taken only
// where the corners disagree. The corners span the others: a shadow edge
// running straight across the kernel leaves corners on both sides of it
// (MapOptions::earlyOut). The rounds' count comes from the block
// (map.kernelRounds: 5) so that the compiler keeps the loop, whose rounds
// a rasteriser can skip only as a whole.
// Tap j of round r.
vec3 pcf20Direction(int r, int j) {
    vec2 s = vec2((j & 1) != 0 ? -1.0 : 1.0, (j & 2) != 0 ? -1.0 : 1.0);
    if (r < 2) return vec3(s, r == 0 ? 1.0 : -1.0);  // the corners
    return r == 2 ? vec3(s, 0.0) : r == 3 ? vec3(s.x, 0.0, s.y) : vec3(0.0, s);
}

float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    float sum = 0.0, taken = 0.0;
    int rounds = int(map.kernelRounds);
    for (int r = 0; r < rounds; ++r) {
        for (int j = 0; j < 4; ++j) sum += cubeTap(v + pcf20Direction(r, j) * radius, ref);
        taken += 4.0;
        if (r == 1 && (sum == 0.0 || sum == taken)) break;  // the eight corners agree
    }
    return sum / taken;
}
#else
float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    float sum = 0.0;
    for (int k = 0; k < 20; ++k) sum += cubeTap(v + kPcf20[k] * radius, ref);
    return sum / 20.0;
}
#endif
