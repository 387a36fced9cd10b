// Technique "map": the sampling patterns its filter kernels share.
#ifndef SHADOW_MAP_SAMPLING_GLSL
#define SHADOW_MAP_SAMPLING_GLSL

// Interleaved gradient noise (Jimenez 2014): a per-pixel rotation for the disk.
float mapNoise(vec2 pixel) { return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715)))); }
// This pixel's rotation of the disk, radians.
float mapRotation() { return 6.2831853 * mapNoise(gl_FragCoord.xy); }

// A Vogel disk (the golden-angle spiral, uniform by area): tap k of n at
// radius vogelRadius(k, n) (of a unit disk) and angle k x the golden angle
// + the pixel's rotation. The angle's direction is walked, not evaluated:
// vogelFirst(rotation) is tap 0's, vogelTurn the next tap's from the one
// before (a turn by the golden angle: a cosine and a sine per pixel, not
// per tap; on llvmpipe they were a fifth of PCSS's lookup).
float vogelRadius(int k, int n) { return sqrt((float(k) + 0.5) / float(n)); }
vec2 vogelFirst(float rotation) { return vec2(cos(rotation), sin(rotation)); }
// The turn by `stride` golden angles (the next tap of a pixel that takes
// every stride-th tap of a disk: 1, or 4 in a quad's share below), and
// direction d turned by it.
vec2 vogelStep(int stride) {
    const vec2 g1 = vec2(cos(SL_MAP_GOLDEN_ANGLE), sin(SL_MAP_GOLDEN_ANGLE));
    const vec2 g4 = vec2(cos(4.0 * SL_MAP_GOLDEN_ANGLE), sin(4.0 * SL_MAP_GOLDEN_ANGLE));
    return stride == 4 ? g4 : g1;
}
vec2 vogelTurnBy(vec2 d, vec2 g) { return vec2(d.x * g.x - d.y * g.y, d.x * g.y + d.y * g.x); }
vec2 vogelTurn(vec2 d) { return vogelTurnBy(d, vogelStep(1)); }

// One disk shared by the 2x2 pixels of a quad (MAP_QUAD_SHARED: pcss's
// blocker search): turned by the quad's rotation, each pixel takes every
// fourth of its taps from tap quadLane(), and quadSum adds a value over the
// quad's four pixels through the fine derivatives (the partner across is
// the value plus or minus dFdxFine, then the pair's partner down the same
// with dFdyFine). Only where every pixel of the quad runs: the light pass
// tests these variants before any branch or discard (lighting.frag,
// SHADOW_QUAD_UNIFORM).
int quadLane() {
    ivec2 q = ivec2(gl_FragCoord.xy) & 1;
    return q.x + 2 * q.y;
}
float quadRotation() { return 6.2831853 * mapNoise(floor(0.5 * gl_FragCoord.xy)); }
vec3 quadSum(vec3 v) {
    ivec2 q = ivec2(gl_FragCoord.xy) & 1;
    vec3 dx = dFdxFine(v);
    vec3 row = v + (q.x == 0 ? v + dx : v - dx);
    vec3 dy = dFdyFine(row);
    return row + (q.y == 0 ? row + dy : row - dy);
}

// Tap k of n, in direction `d`, on a disk of `radius` texels, in uv (`du`: one texel).
vec2 vogelOffset2D(int k, int n, float radius, vec2 d, float du) { return du * vogelRadius(k, n) * radius * d; }
// Tap k of n, in direction `d`, on a disk of `radius` across a ray, spanned by unit vectors t and b.
vec3 vogelOffset3D(int k, int n, float radius, vec2 d, vec3 t, vec3 b) { return vogelRadius(k, n) * radius * (d.x * t + d.y * b); }

#endif
