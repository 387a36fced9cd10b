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
vec2 vogelTurn(vec2 d) {
    const vec2 g = vec2(cos(SL_MAP_GOLDEN_ANGLE), sin(SL_MAP_GOLDEN_ANGLE));
    return vec2(d.x * g.x - d.y * g.y, d.x * g.y + d.y * g.x);
}
// Tap k of n, in direction `d`, on a disk of `radius` texels, in uv (`du`: one texel).
vec2 vogelOffset2D(int k, int n, float radius, vec2 d, float du) { return du * vogelRadius(k, n) * radius * d; }
// Tap k of n, in direction `d`, on a disk of `radius` across a ray, spanned by unit vectors t and b.
vec3 vogelOffset3D(int k, int n, float radius, vec2 d, vec3 t, vec3 b) { return vogelRadius(k, n) * radius * (d.x * t + d.y * b); }

#endif
