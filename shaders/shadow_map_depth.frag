// Technique "map", shadow pass. Variants: MAP_RGBA8 (pack depth into an
// RGBA8 colour, lecture 002 §8.3.1), MAP_SPOT (discard outside the cone:
// the cone is the circle inscribed in the square map, 002 §8.2.1.3).
in vec2 vLightNdc;
#if MAP_RGBA8
layout(location = 0) out vec4 outPacked;

// d in [0, 1) as four base-255 digits (lecture 002 §8.3.1, Listing 8.2).
// The lecture uses base 256, but an 8-bit UNORM channel stores x as
// round(255 x) / 255, so a digit k / 256 comes back as about k / 255: up to
// 0.4 % of the depth range wrong. With base 255 every digit is an exact
// UNORM step and the four channels give 32 bits of depth.
vec4 packDepth(float d) {
    if (d >= 1.0) return vec4(1.0);
    const vec4 shift = vec4(1.0, 255.0, 255.0 * 255.0, 255.0 * 255.0 * 255.0);
    const vec4 mask = vec4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
    vec4 res = fract(d * shift);
    res -= res.yzww * mask;
    return res;
}
#endif

void main() {
#if MAP_SPOT
    if (dot(vLightNdc, vLightNdc) > 1.0) discard;
#endif
#if MAP_RGBA8
    outPacked = packDepth(gl_FragCoord.z);
#endif
}
