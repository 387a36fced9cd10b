// Technique "map", fit "sdsm" on the GPU: the reduction's blocks
// (shadow_map_sdsm_reduce.frag, one window) merged into one box by a
// workgroup of 256, and the steps both fits take (shadow_map_sdsm_fit.comp,
// shadow_map_sdsm_cascades.comp).

// The reduction's lowest and highest corner a block (w = 1: covered).
SL_BINDING(SL_UNIT_SHADOW_FIRST) uniform sampler2D blockLo;
SL_BINDING(SL_UNIT_SHADOW_FIRST + 1) uniform sampler2D blockHi;

shared vec3 sdsmLows[256], sdsmHighs[256];

// The box of every covered block (lo > hi: none), in invocation 0; each
// invocation takes its share, then the shares are merged by halves. Every
// invocation must call it (it waits at barriers).
void mergeBlocks(ivec2 blocks, out vec3 lo, out vec3 hi) {
    uint i = gl_LocalInvocationIndex;
    lo = vec3(3.0e38);
    hi = vec3(-3.0e38);
    int n = blocks.x * blocks.y;
    for (int k = int(i); k < n; k += 256) {
        ivec2 at = ivec2(k % blocks.x, k / blocks.x);
        vec4 a = texelFetch(blockLo, at, 0), b = texelFetch(blockHi, at, 0);
        if (a.w > 0.5) {
            lo = min(lo, a.xyz);
            hi = max(hi, b.xyz);
        }
    }
    sdsmLows[i] = lo;
    sdsmHighs[i] = hi;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (i < stride) {
            sdsmLows[i] = min(sdsmLows[i], sdsmLows[i + stride]);
            sdsmHighs[i] = max(sdsmHighs[i], sdsmHighs[i + stride]);
        }
        barrier();
    }
    lo = sdsmLows[0];
    hi = sdsmHighs[0];
}

// The margin the CPU's merge adds (MapSdsm: points taken back from depth
// are rounded where the light pass interpolates): 10^-4 of the box's diagonal.
void sdsmMargin(inout vec3 lo, inout vec3 hi) {
    vec3 margin = vec3(1e-4 * length(hi - lo));
    lo -= margin;
    hi += margin;
}

// A box's corners through an affine matrix: their box (Bounds::transformed).
void sdsmBoxThrough(mat4 m, inout vec3 lo, inout vec3 hi) {
    vec3 a = vec3(3.0e38), b = vec3(-3.0e38);
    for (int c = 0; c < 8; ++c) {
        vec3 p = (m * vec4((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y, (c & 4) != 0 ? hi.z : lo.z, 1.0)).xyz;
        a = min(a, p);
        b = max(b, p);
    }
    lo = a;
    hi = b;
}

// glm::ortho(l, r, b, t, n, f), column by column.
mat4 sdsmOrtho(float l, float r, float b, float t, float n, float f) {
    return mat4(vec4(2.0 / (r - l), 0.0, 0.0, 0.0), vec4(0.0, 2.0 / (t - b), 0.0, 0.0), vec4(0.0, 0.0, -2.0 / (f - n), 0.0),
                vec4(-(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1.0));
}

// Texture space from clip space: the bias matrix (scale and offset by 0.5).
const mat4 kSdsmBias = mat4(vec4(0.5, 0.0, 0.0, 0.0), vec4(0.0, 0.5, 0.0, 0.0), vec4(0.0, 0.0, 0.5, 0.0), vec4(0.5, 0.5, 0.5, 1.0));
