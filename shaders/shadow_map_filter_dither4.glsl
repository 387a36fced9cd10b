// Technique "map", filter "dither4": the lecture's 4-sample dithered PCF
// (Wolberg), one of four patterns from gl_FragCoord mod 2, taps `spread`
// texels apart (map.ditherSpread). 2D maps only.
#if MAP_CUBE
#error filter dither4 is for 2D maps
#endif
float mapFilter(MapLookup m, vec2 uv, float ref) {
    float w = map.ditherSpread * map.texelUv;
    vec2 o = mod(floor(gl_FragCoord.xy), 2.0) * w;
    float sum = mapTap(m.layer, uv + vec2(-1.5 * w + o.x, 1.5 * w - o.y), ref) + mapTap(m.layer, uv + vec2(-1.5 * w + o.x, -0.5 * w - o.y), ref) +
                mapTap(m.layer, uv + vec2(0.5 * w + o.x, 1.5 * w - o.y), ref) + mapTap(m.layer, uv + vec2(0.5 * w + o.x, -0.5 * w - o.y), ref);
    return 0.25 * sum;
}
