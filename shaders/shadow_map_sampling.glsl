// Technique "map": the sampling patterns its filter kernels share.
#ifndef SHADOW_MAP_SAMPLING_GLSL
#define SHADOW_MAP_SAMPLING_GLSL

// Interleaved gradient noise (Jimenez 2014): a per-pixel rotation for the disk.
float mapNoise(vec2 pixel) { return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715)))); }
// This pixel's rotation of the disk, radians.
float mapRotation() { return 6.2831853 * mapNoise(gl_FragCoord.xy); }

// A Vogel disk (the golden-angle spiral, uniform by area): tap k of n at
// radius vogelRadius(k, n) (of a unit disk) and angle vogelAngle(k, rotation).
float vogelRadius(int k, int n) { return sqrt((float(k) + 0.5) / float(n)); }
float vogelAngle(int k, float rotation) { return float(k) * 2.3999632 + rotation; }
// Tap k of n on a disk of `radius` texels, in uv (`du`: one texel).
vec2 vogelOffset2D(int k, int n, float radius, float rotation, float du) {
    float r = vogelRadius(k, n) * radius;
    float a = vogelAngle(k, rotation);
    return du * r * vec2(cos(a), sin(a));
}
// Tap k of n on a disk of `radius` across a ray, spanned by unit vectors t and b.
vec3 vogelOffset3D(int k, int n, float radius, float rotation, vec3 t, vec3 b) {
    float r = vogelRadius(k, n) * radius;
    float a = vogelAngle(k, rotation);
    return r * (cos(a) * t + sin(a) * b);
}

#endif
