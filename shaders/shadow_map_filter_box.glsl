// Technique "map", filter "box": four bilinear hardware compares half a
// texel from the point on each axis. Each weighs the 2x2 texels around it,
// so together they weigh the 3x3 texels around the point as a tent
// (Filament's and the GPU Gems 1 ch. 11 "4-tap" PCF): smoother than one
// bilinear compare for four fetches. Cube maps: eight bilinear compares at
// the corners of a cube half a texel (at the fragment's distance) on each
// side of the ray's end.
#if MAP_CUBE
float cubeReach(float texel, float radius) { return 0.5 * texel * 1.7320508 + texel; }  // a corner, and its bilinear footprint

float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    float h = 0.5 * length(v) * map.cubeTexelPerDistance;  // half a texel, world units
    float sum = 0.0;
    for (int k = 0; k < 8; ++k) {
        vec3 corner = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
        sum += cubeTap(v + h * corner, ref);
    }
    return 0.125 * sum;
}
#else
float mapFilter(MapLookup m, vec2 uv, float ref) {
    float h = 0.5 * map.texelUv;
    return 0.25 * (mapTap(m.layer, uv + vec2(-h, -h), ref) + mapTap(m.layer, uv + vec2(h, -h), ref) + mapTap(m.layer, uv + vec2(-h, h), ref) +
                   mapTap(m.layer, uv + vec2(h, h), ref));
}
#endif
