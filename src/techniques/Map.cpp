// Technique "map": shadow maps for directional and spot lights, the lecture's
// two passes (000, 002 §8.2-8.4, 004), and cube maps for point lights (001).
// Shadow pass: the casters that can reach the light's frustum, drawn from
// the light camera (src/core/LightCamera) into one layer of a texture array
// shared by every light with the same format and size, colour writes off
// (or depth packed into RGBA8); a point light's six faces are six layers of
// a cube-map array, filled in one geometry-shader pass or six passes.
// Light pass: shaders/shadow_map.glsl compares the fragment's depth in the
// light's texture space with the map, filtered as the light asks.
#include "techniques/Map.h"

#include "core/LightCamera.h"
#include "core/Text.h"

#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>

#include "shadow_map_shared.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <map>
#include <span>

namespace shadowlab {

const OptionTable& mapOptionTable() {
    static const OptionTable table =
        OptionTableFor<MapOptions>("map")
            .integer(&MapOptions::size, "size", 16, 16384, "texels", "side of the square shadow map")
            .choice(&MapOptions::format, "format", {"depth16", "depth24", "depth32f", "rgba8", "r8"},
                    "depth texture format; rgba8 packs depth into colour (lecture 002 §8.3.1); r8 keeps 8 bits of depth, enough only when every caster is nearer the light than what it shadows (lecture 002 exercise 8.6.2-1, variation 2)")
            .choice(&MapOptions::fit, "fit", {"tight", "scene"},
                    "light camera: around what the viewer sees and the casters over it, or around the whole scene")
            .choice(&MapOptions::filter, "filter", {"none", "hardware", "grid", "dither4", "poisson", "pcf20", "pcss"},
                    "one nearest tap; one bilinear hardware compare; kernel x kernel taps (point lights: kernel^3 in a cube of side 2 diskRadius); the lecture's dithered 4 taps (2D maps); a rotated disk; the lecture's 20 directions (point lights); soft shadows for the light's size (PCSS)")
            .integer(&MapOptions::kernel, "kernel", 2, 8, "taps per side", "grid filter: kernel x kernel taps one texel apart")
            .choice(&MapOptions::gridTaps, "gridTaps", {"auto", "bilinear", "nearest"},
                    "grid filter: the same comparisons from ceil(kernel/2)^2 bilinear or kernel^2 nearest fetches; auto: nearest on a software rasteriser")
            .integer(&MapOptions::samples, "samples", 4, 64, "taps", "poisson and pcss filters: taps on the disk")
            .integer(&MapOptions::blockerSamples, "blockerSamples", 4, 64, "taps", "pcss filter: taps of the blocker search")
            .number(&MapOptions::radius, "radius", 0.0, 32.0, "texels", "poisson filter: disk radius")
            .number(&MapOptions::constantBias, "constantBias", 0.0, 0.1, "depth (0..1)", "subtracted from the receiver's map depth")
            .number(&MapOptions::slopeBias, "slopeBias", 0.0, 16.0, "polygon offset factor", "shadow pass: depth offset per unit of depth slope")
            .number(&MapOptions::offsetUnits, "offsetUnits", 0.0, 1024.0, "polygon offset units", "shadow pass: constant depth offset in the format's smallest steps")
            .number(&MapOptions::normalBias, "normalBias", 0.0, 16.0, "texels",
                    "receiver moved along its normal by this many map texels (their world size) times 1 - N.L")
            .boolean(&MapOptions::cullFront, "cullFront", "shadow pass draws back faces only (closed meshes; lecture 002 §8.4.1.1)")
            .number(&MapOptions::shadowedLight, "shadowedLight", 0.0, 1.0, "share of the light",
                    "what a shadowed point keeps of the light (lecture 002 listing 8.4: 0.6); compare judges the shadow test, not this look")
            .boolean(&MapOptions::mipmaps, "mipmaps", "mipmap the map and compare at the pixel's level (lecture 002 exercise 8.6.1-4; docs/techniques.md says what it does)")
            .choice(&MapOptions::preset, "preset", {"default", "lecture", "learnopengl", "lecture-000"},
                    "replace the settings with the lecture's or LearnOpenGL's (docs/techniques.md); lecture-000: a point light through lecture 000's one 60-degree map")
            .integer(&MapOptions::cascades, "cascades", 1, 8, "maps",
                     "directional lights: cascaded shadow maps, one per slice of the view's depth (layers of one array); 1: one map")
            .number(&MapOptions::cascadeLambda, "cascadeLambda", 0.0, 1.0, "0 uniform .. 1 logarithmic",
                    "cascades: where the slices split, lambda x logarithmic + (1 - lambda) x uniform (the practical scheme)")
            .text(&MapOptions::cascadeSplits, "cascadeSplits", "cascades - 1 increasing distances, scene units, e.g. \"4 15 50\"",
                  "cascades: the slices' far ends along the view instead of cascadeLambda's (the last slice ends at the camera's far plane when stabilised, else at the farthest receiver in view)")
            .boolean(&MapOptions::stabilize, "stabilize",
                     "cascades: a bounding sphere per slice and the map snapped to whole texels, so shadows do not shimmer as the camera moves; false: each slice fitted tightly")
            .number(&MapOptions::cascadeBlend, "cascadeBlend", 0.0, 0.5, "share of a slice",
                    "cascades: the far part of each slice over which its shadow fades into the next cascade's")
            .choice(&MapOptions::representation, "representation", {"depth", "vsm", "evsm2", "evsm4", "msm"},
                    "directional and spot lights: what the map stores; depth, compared per tap, or moments of depth that are blurred and filtered like colour (variance, exponential variance with 2 or 4 moments, moment shadow maps)")
            .choice(&MapOptions::momentFormat, "momentFormat", {"rgba32f", "rgba16f"},
                    "moments: 32- or 16-bit floats (16: half the memory, more light bleeding)")
            .integer(&MapOptions::blur, "blur", 0, 16, "texels each side", "moments: separable Gaussian blur of sigma blur / 2 texels before the light pass")
            .number(&MapOptions::bleedReduction, "bleedReduction", 0.0, 0.9, "share of the bound",
                    "moments: light-bleeding reduction, the upper bound's values under this become 0 and the rest is stretched to 0..1 (darkens penumbrae)")
            .choice(&MapOptions::cubePasses, "cubePasses", {"one", "six"},
                    "point lights: each caster drawn once through a geometry shader that picks its faces, or one pass per face (the same map)")
            .boolean(&MapOptions::faceCulling, "faceCulling",
                     "point lights: each caster drawn only into the cube faces its bounds (and, in one pass, each triangle) can touch; false: into all six")
            .number(&MapOptions::diskRadius, "diskRadius", 0.0, 10.0, "world units",
                    "point lights, filters grid, pcf20 and poisson: the filter's radius at the fragment")
            .number(&MapOptions::diskGrowth, "diskGrowth", 0.0, 100.0, "per viewer distance / far",
                    "point lights: the radius times 1 + diskGrowth x (viewer distance / far)")
            .build();
    return table;
}

namespace {

GLenum depthFormat(MapFormat f) {
    switch (f) {
    case MapFormat::Depth16: return GL_DEPTH_COMPONENT16;
    case MapFormat::Depth24: return GL_DEPTH_COMPONENT24;
    case MapFormat::Depth32F: return GL_DEPTH_COMPONENT32F;
    case MapFormat::Rgba8:
    case MapFormat::R8: return GL_DEPTH_COMPONENT24;  // the depth test's own buffer; the map is the colour
    }
    return GL_DEPTH_COMPONENT32F;
}

// Whether the map is depth packed into a colour target (rgba8's four
// base-255 digits, or r8's one), compared in the shader.
bool isPacked(MapFormat f) { return f == MapFormat::Rgba8 || f == MapFormat::R8; }

// The shader defines of a packed format.
std::string packDefines(MapFormat f) {
    return std::string("#define MAP_RGBA8 ") + (isPacked(f) ? "1" : "0") + "\n#define MAP_R8 " + (f == MapFormat::R8 ? "1" : "0") + "\n";
}

// Texels around the fitted region that the filter may read.
float footprint(const MapOptions& o) {
    if (o.representation != MapRepresentation::Depth) return static_cast<float>(o.blur) + 2.0f;  // the blur, then a bilinear lookup
    switch (o.filter) {
    case MapFilter::None: return 1.0f;
    case MapFilter::Hardware: return 1.5f;
    case MapFilter::Grid: return 0.5f * static_cast<float>(o.kernel) + 1.0f;
    case MapFilter::Dither4: return 3.0f;
    case MapFilter::Poisson: return o.radius + 1.0f;
    case MapFilter::Pcf20: return 1.0f;  // point lights only
    case MapFilter::Pcss: return 0.125f * static_cast<float>(o.size) + 1.0f;  // its search and filter reach an eighth of the map
    }
    return 1.0f;
}

// Texels from a filter's centre to its farthest tap (the receiver-plane
// bias covers that distance; the presets keep their own biases instead).
float reach(const MapOptions& o) {
    if (o.preset != MapPreset::Default || o.representation != MapRepresentation::Depth) return 0.0f;  // moments bound the depths' spread instead
    switch (o.filter) {
    case MapFilter::None: return 0.0f;
    case MapFilter::Hardware: return 1.0f;  // the 2x2 bilinear footprint
    case MapFilter::Grid: return 0.5f * static_cast<float>(o.kernel - 1) * 1.41421356f;
    case MapFilter::Dither4: return 1.5f * 1.41421356f;
    case MapFilter::Poisson: return o.radius;
    case MapFilter::Pcf20: return 0.0f;  // point lights only (shadow_map.glsl computes theirs)
    case MapFilter::Pcss: return 0.0f;   // each tap compares against the receiver's plane (shadow_map.glsl)
    }
    return 0.0f;
}

// What the lecture's and LearnOpenGL's presets share: a depth32f map and no
// bias but the one they set themselves.
void presetBase(MapOptions& o) {
    o.format = MapFormat::Depth32F;
    o.slopeBias = 0.0f;
    o.offsetUnits = 0.0f;
    o.normalBias = 0.0f;
    o.constantBias = 0.0f;
    o.cullFront = false;
}

// The light's options with its preset applied (docs/techniques.md cites each value).
MapOptions effective(const Light& light) {
    MapOptions o = light.shadow.get<MapOptions>();
    const bool cube = light.type == LightType::Point && o.preset != MapPreset::Lecture000;
    if (cube && o.preset == MapPreset::Lecture) {
        // Lecture 001's cube: near 1, far 25 (cubeNearFar), no bias but a
        // constant one in world units (upload() turns it into stored depth),
        // and its three stages by the light's filter: "none", one sample with
        // bias 0.05; "grid", the 64-sample 3-D grid (4 per axis, offsets to
        // 0.1) with bias 0.05; anything else, the 20 offset directions with
        // a fixed disk radius of 0.05 and bias 0.15.
        presetBase(o);
        o.diskGrowth = 0.0f;
        if (o.filter == MapFilter::None) {
            o.constantBias = 0.05f;
        } else if (o.filter == MapFilter::Grid) {
            o.kernel = 4;
            o.diskRadius = 0.1f;
            o.constantBias = 0.05f;
        } else {
            o.filter = MapFilter::Pcf20;
            o.diskRadius = 0.05f;
            o.constantBias = 0.15f;
        }
        return o;
    }
    if (cube && o.preset == MapPreset::LearnOpenGL) {
        // LearnOpenGL 5.advanced_lighting/3.2.2: a 1024^2 cube, near 1, far
        // 25, bias 0.15, 20 offset directions with radius (1 + d/far)/25.
        presetBase(o);
        o.size = 1024;
        o.filter = MapFilter::Pcf20;
        o.diskRadius = 0.04f;
        o.diskGrowth = 1.0f;
        o.constantBias = 0.15f;
        return o;
    }
    if (o.preset == MapPreset::Lecture || o.preset == MapPreset::Lecture000) {
        // Lecture 000: glPolygonOffset(2.0, 4.0), a DEPTH_COMPONENT32F map
        // of the window's size (prepare() sets it), the 4-sample dithered
        // PCF; no normal offset, no constant bias.
        presetBase(o);
        o.slopeBias = 2.0f;
        o.offsetUnits = 4.0f;
        o.cullFront = light.shadow.get<MapOptions>().cullFront;  // 000 says nothing of it
        o.filter = MapFilter::Dither4;
        o.fit = MapFit::Scene;
        // Lecture 002 listing 8.4: a shadowed point keeps 60 % (color *= 0.6).
        o.shadowedLight = 0.6f;
    } else if (o.preset == MapPreset::LearnOpenGL) {
        // LearnOpenGL 5.advanced_lighting/3.1.3: 1024^2 DEPTH_COMPONENT
        // (float), 3x3 PCF of nearest taps, bias max(0.05 (1 - N.L), 0.005),
        // no polygon offset or normal offset; the light camera is fixed (Map.cpp: learnOpenGlCamera).
        presetBase(o);
        o.size = 1024;
        o.filter = MapFilter::Grid;
        o.kernel = 3;
    }
    return o;
}

// LearnOpenGL's light camera: lookAt((-2, 4, -1), origin, +Y) with
// ortho(-10, 10, -10, 10, 1, 7.5). Its light position is minus the light's
// direction scaled to that length, so the scene file keeps one direction.
LightCamera learnOpenGlCamera(const Light& light, int size) {
    LightCamera cam;
    const glm::vec3 eye = -glm::normalize(light.direction) * std::sqrt(21.0f);
    cam.viewFromWorld = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    cam.nearPlane = 1.0f;
    cam.farPlane = 7.5f;
    cam.clipFromView = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, cam.nearPlane, cam.farPlane);
    cam.texelSize = 20.0f / static_cast<float>(size);
    return cam;
}

// Lecture 000's camera for its point light (the torus-and-pyramid scene):
// lookAt(light, origin, +Y) and perspective(60 degrees, 0.1, 1000), one map
// towards the origin instead of a cube.
LightCamera lecturePointCamera(const Light& light, int size) {
    LightCamera cam;
    const glm::vec3 towards = -light.position;
    const glm::vec3 up = glm::length(glm::cross(towards, glm::vec3(0.0f, 1.0f, 0.0f))) > 1e-6f * glm::length(towards)
                             ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    cam.viewFromWorld = glm::lookAt(light.position, glm::vec3(0.0f), up);
    cam.nearPlane = 0.1f;
    cam.farPlane = 1000.0f;
    cam.clipFromView = glm::perspective(glm::radians(60.0f), 1.0f, cam.nearPlane, cam.farPlane);
    cam.perspective = true;
    cam.texelSize = 2.0f * std::tan(glm::radians(30.0f)) / static_cast<float>(size);
    return cam;
}

// The maps of a directional light's cascades (1 for any other light).
int cascadeCount(const Light& light, const MapOptions& o) { return light.type == LightType::Directional ? o.cascades : 1; }

// cascadeSplits' distances; `problem` says what is wrong with them, if anything.
std::vector<float> parseSplits(const MapOptions& o, std::string& problem) {
    std::vector<float> out;
    if (o.cascadeSplits.find_first_not_of(" ,\t") == std::string::npos) return out;
    std::string text = o.cascadeSplits;
    std::replace(text.begin(), text.end(), ',', ' ');
    const char* at = text.c_str();
    for (;;) {
        while (*at == ' ' || *at == '\t') ++at;
        if (*at == '\0') break;
        char* end = nullptr;
        const float v = std::strtof(at, &end);
        if (end == at || !std::isfinite(v) || v <= 0.0f || (!out.empty() && v <= out.back())) {
            problem = "expected increasing distances > 0";
            return {};
        }
        out.push_back(v);
        at = end;
    }
    if (static_cast<int>(out.size()) != o.cascades - 1)
        problem = "expected " + std::to_string(o.cascades - 1) + " distance(s) for " + std::to_string(o.cascades) + " cascades, got " + std::to_string(out.size());
    return out;
}

// A point light's map is a cube unless preset lecture-000 asks for 000's single map.
bool isCube(const Light& light) {
    return light.type == LightType::Point && light.shadow.get<MapOptions>().preset != MapPreset::Lecture000;
}
// Lecture 000's 2D settings (the window-sized map, the dither spread).
bool isLecture2D(const MapOptions& o, const Light& light) {
    return !isCube(light) && (o.preset == MapPreset::Lecture || o.preset == MapPreset::Lecture000);
}
// The presets' fixed near and far planes for a cube (001 and LearnOpenGL: 1 and 25); 0: fitted.
std::pair<float, float> cubeNearFar(const MapOptions& o) {
    return o.preset == MapPreset::Lecture || o.preset == MapPreset::LearnOpenGL ? std::pair{1.0f, 25.0f} : std::pair{0.0f, 0.0f};
}

// Texture space from clip space: the lecture's bias matrix (scale and offset by 0.5).
const glm::mat4 kBias = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));

// What lights must agree on to share one texture array.
struct GroupKey {
    MapFormat format = MapFormat::Depth32F;
    bool mipmaps = false;
    bool cube = false;  ///< a cube-map array: six layers per light
    MapRepresentation representation = MapRepresentation::Depth;
    MapMomentFormat momentFormat = MapMomentFormat::Rgba32f;  ///< moments only
    int size = 0;
    static GroupKey of(const MapOptions& o, bool cube) {
        const bool moments = o.representation != MapRepresentation::Depth;
        return {o.format, o.mipmaps, cube, o.representation, moments ? o.momentFormat : MapMomentFormat::Rgba32f, o.size};
    }
    auto tie() const { return std::tie(format, mipmaps, cube, representation, momentFormat, size); }
    bool operator<(const GroupKey& o) const { return tie() < o.tie(); }
    bool operator==(const GroupKey& o) const { return tie() == o.tie(); }
};

// Moments stored per texel: 0 for depth maps.
int momentCount(MapRepresentation r);

// Whether the group's depth-test buffer is one layer shared by all its
// lights (r8 2D maps: each pass clears it first), not a layer per map.
bool sharedDepthBuffer(const GroupKey& key) { return key.format == MapFormat::R8 && !key.cube; }

// Bytes a texel of one map layer takes: its depth (the map itself for
// depth formats; the depth test's buffer for rgba8 and moments, r8 shares
// one), a packed format's colour, the moments.
double texelBytes(const GroupKey& key) {
    const double depth = sharedDepthBuffer(key) ? 0.0 : key.format == MapFormat::Depth16 ? 2.0 : 4.0;  // depth24 is stored in 4 bytes
    const double colour = key.format == MapFormat::Rgba8 ? 4.0 : key.format == MapFormat::R8 ? 1.0 : 0.0;
    return depth + colour + momentCount(key.representation) * (key.momentFormat == MapMomentFormat::Rgba16f ? 2.0 : 4.0);
}

// Moments stored per texel: 0 for depth maps.
int momentCount(MapRepresentation r) { return r == MapRepresentation::Depth ? 0 : r == MapRepresentation::Vsm || r == MapRepresentation::Evsm2 ? 2 : 4; }
GLenum momentFormatOf(const GroupKey& k) {
    const bool half = k.momentFormat == MapMomentFormat::Rgba16f;
    return momentCount(k.representation) == 2 ? (half ? GL_RG16F : GL_RG32F) : (half ? GL_RGBA16F : GL_RGBA32F);
}

struct Group {
    GroupKey key;
    int layers = 0;
    std::uint64_t generation = 0;     ///< unique per allocation: framebuffers attached to an older one are rebuilt
    gl::Texture depth{gl::NoCreate};  ///< DEPTH_COMPONENT* array: the map, or the depth test's buffer for rgba8 and moments
    gl::Texture packed{gl::NoCreate}; ///< RGBA8 array: the map for rgba8
    gl::Texture moments{gl::NoCreate};///< RG/RGBA float array: the map for moment representations
    gl::Texture blurScratch{gl::NoCreate};   ///< moments: one layer's horizontal blur
    gl::Texture transmit{gl::NoCreate};      ///< RGBA8 array: the translucent casters' transmittance per layer (cube: per face)
    gl::Texture transmitDepth{gl::NoCreate}; ///< R32F array: the nearest translucent caster's depth per layer
    gl::Framebuffer blurFbo{gl::NoCreate};   ///< the scratch as a target
    GLenum target() const { return key.cube ? GL_TEXTURE_CUBE_MAP_ARRAY : GL_TEXTURE_2D_ARRAY; }
    int layersPerLight() const { return key.cube ? 6 : 1; }
    bool hasMoments() const { return key.representation != MapRepresentation::Depth; }
    // Shorthands.
    MapFormat format() const { return key.format; }
    bool mipmaps() const { return key.mipmaps; }
    bool cube() const { return key.cube; }
    int size() const { return key.size; }
};

// A rectangle of a map's texels, [x0, x1) x [y0, y1); empty when x0 >= x1.
struct TexelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    static TexelRect whole() { return {0, 0, 1 << 30, 1 << 30}; }
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    TexelRect united(const TexelRect& o) const {
        if (empty()) return o;
        if (o.empty()) return *this;
        return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
    }
    TexelRect clamped(int size) const { return {std::max(x0, 0), std::max(y0, 0), std::min(x1, size), std::min(y1, size)}; }
};

// The texels of a `size`-texel face that `box` may cover through
// `faceClip` (a texel of margin; the whole face when a corner is behind the
// face's camera).
TexelRect projectedRect(const glm::mat4& faceClip, const Bounds& box, int size) {
    float lo[2] = {1.0f, 1.0f}, hi[2] = {-1.0f, -1.0f};
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
        const glm::vec4 clip = faceClip * glm::vec4(corner, 1.0f);
        if (!(clip.w > 1e-6f)) return TexelRect::whole().clamped(size);
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], clip[a] / clip.w);
            hi[a] = std::max(hi[a], clip[a] / clip.w);
        }
    }
    auto texel = [&](float ndc) { return static_cast<int>(std::floor((ndc * 0.5f + 0.5f) * static_cast<float>(size))); };
    return TexelRect{texel(lo[0]) - 1, texel(lo[1]) - 1, texel(hi[0]) + 2, texel(hi[1]) + 2}.clamped(size);
}

struct PerLight {
    MapOptions options;
    bool spot = false;  ///< the shadow pass discards outside the cone
    LightCamera camera;
    std::size_t group = 0;
    int layer = 0;
    gl::Framebuffer fbo{gl::NoCreate};  ///< the layer attached (at prepare, when the array or layer changes); cube: the whole array, layered
    std::uint64_t attachedGeneration = 0;
    int attachedLayer = -1;
    // Point lights.
    bool cube = false;
    CubeCamera cubeCamera;
    std::array<gl::Framebuffer, 6> faceFbos{gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate},
                                            gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}};
    /// Per face, the texels that may hold casters' depths from an earlier
    /// frame (cleared again only there, and where casters are drawn now);
    /// whole faces after (re)attaching.
    std::array<TexelRect, 6> faceDirty{TexelRect::whole(), TexelRect::whole(), TexelRect::whole(),
                                       TexelRect::whole(), TexelRect::whole(), TexelRect::whole()};
    // Directional lights with cascades: a camera per slice (the first is
    // also `camera`) in layers layer .. layer + n - 1, each slice's far end
    // along the view, and the view's forward direction (the light pass picks
    // a cascade by the depth along it).
    std::vector<LightCamera> cascades;
    std::vector<float> cascadeFar;
    glm::vec3 viewForward{0.0f, 0.0f, -1.0f};
    std::vector<gl::Framebuffer> cascadeFbos;
    /// The cameras its 2D map layers were drawn from: the cascades, or the one camera.
    std::span<const LightCamera> cameras() const { return cascades.empty() ? std::span<const LightCamera>(&camera, 1) : std::span<const LightCamera>(cascades); }
};

gl::Sampler makeSampler(GLenum minFilter, GLenum magFilter, bool compare) {
    gl::Sampler s;
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, minFilter);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, magFilter);
    // Outside the map: the border, depth 1 (lit).
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glSamplerParameterfv(s.id(), GL_TEXTURE_BORDER_COLOR, one);
    if (compare) {
        glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    return s;
}

class ShadowMap final : public Technique {
public:
    void prepare(TechniqueHost& host, const FrameInfo& frame, std::span<const int> lights) override {
        // A software rasteriser compares four texels for a bilinear fetch,
        // so there the grid's nearest fetches are faster (docs/techniques.md).
        software_ = gl::isSoftwareRasterizer(host.glInfo().renderer);
        if (!compareNearest_) {
            compareNearest_ = makeSampler(GL_NEAREST, GL_NEAREST, true);
            compareLinear_ = makeSampler(GL_LINEAR, GL_LINEAR, true);
            plainNearest_ = makeSampler(GL_NEAREST, GL_NEAREST, false);
            compareNearestMip_ = makeSampler(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, true);
            compareLinearMip_ = makeSampler(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, true);
            plainNearestMip_ = makeSampler(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, false);
            // Moments are filtered like colour; past the edge, the edge.
            momentLinear_ = makeSampler(GL_LINEAR, GL_LINEAR, false);
            momentLinearMip_ = makeSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, false);
            for (const gl::Sampler* m : {&momentLinear_, &momentLinearMip_}) {
                glSamplerParameteri(m->id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
                glSamplerParameteri(m->id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            }
            ubo_ = gl::Buffer();
            glNamedBufferStorage(ubo_.id(), sizeof(shared::MapUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        }
        // Lights with the same format and size share one texture array.
        std::map<GroupKey, int> layersWanted;
        const int windowSize = std::clamp(std::max(frame.viewport.x, frame.viewport.y), 16, host.glInfo().maxTextureSize);
        auto effectiveHere = [&](const Light& light) {
            MapOptions o = effective(light);
            if (isLecture2D(o, light)) o.size = windowSize;  // 000: the map has the window's size
            return o;
        };
        for (int index : lights) {
            const MapOptions o = effectiveHere(frame.scene.lights[static_cast<std::size_t>(index)]);
            const int limit = host.glInfo().maxTextureSize;
            if (o.size > limit)
                throw Error("lights[" + std::to_string(index) + "].shadow.map.size: " + std::to_string(o.size) +
                            " texels is past this GPU's limit of " + std::to_string(limit));
            const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
            const bool cube = isCube(light);
            layersWanted[GroupKey::of(o, cube)] += cube ? 1 : cascadeCount(light, o);
        }
        // Stated limits, before anything is allocated: layers per array, and
        // all maps together within kMapBudgetBytes (a 16384^2 depth32f map is
        // 1 GiB; more than that is almost always a typo, and on llvmpipe it
        // would take system memory and seconds per frame).
        constexpr double kMapBudgetBytes = 1024.0 * 1024.0 * 1024.0;
        double bytes = 0.0;
        for (const auto& wanted : layersWanted) {
            const GroupKey& key = wanted.first;
            const int perLight = key.cube ? 6 : 1;
            bytes += texelBytes(key) * static_cast<double>(key.size) * static_cast<double>(key.size) * wanted.second * perLight +
                     (sharedDepthBuffer(key) ? 4.0 * static_cast<double>(key.size) * static_cast<double>(key.size) : 0.0);
            if (wanted.second * perLight > host.glInfo().maxArrayLayers)
                throw Error("lights[" + std::to_string(lights[0]) + "].shadow.map: " + std::to_string(wanted.second * perLight) +
                            " map layers in one array (" + (perLight == 6 ? std::to_string(wanted.second) + " point light(s), six each" : "lights and cascades") +
                            "), past this GPU's limit of " + std::to_string(host.glInfo().maxArrayLayers) + " layers");
        }
        if (bytes > kMapBudgetBytes) {
            char text[256];
            std::snprintf(text, sizeof text, "the shadow maps of %zu light(s) need %.2f GiB, more than the budget of 1 GiB (lower lights[i].shadow.map.size)",
                          lights.size(), bytes / kMapBudgetBytes);
            throw Error("lights[" + std::to_string(lights[0]) + "].shadow.map.size: " + text);
        }
        std::vector<Group> groups;
        for (const auto& wanted : layersWanted) {
            const GroupKey& key = wanted.first;
            const int layers = wanted.second;
            // Keep an existing array when it still fits, so maps are not reallocated every frame.
            auto same = std::find_if(groups_.begin(), groups_.end(), [&](const Group& g) { return g.key == key && g.layers == layers; });
            if (same != groups_.end()) {
                groups.push_back(std::move(*same));
                continue;
            }
            Group g;
            g.key = key;
            g.layers = layers;
            g.generation = ++generations_;
            const int size = key.size;
            const int levels = key.mipmaps ? 1 + static_cast<int>(std::floor(std::log2(static_cast<double>(size)))) : 1;
            const bool colour = isPacked(key.format) || g.hasMoments();  // the depth array only serves the depth test
            g.depth = gl::Texture(g.target());
            glTextureStorage3D(g.depth.id(), colour ? 1 : levels, depthFormat(key.format), size, size,
                               sharedDepthBuffer(key) ? 1 : layers * g.layersPerLight());
            if (isPacked(key.format)) {
                g.packed = gl::Texture(g.target());
                glTextureStorage3D(g.packed.id(), levels, key.format == MapFormat::R8 ? GL_R8 : GL_RGBA8, size, size, layers * g.layersPerLight());
            }
            if (g.hasMoments()) {
                g.moments = gl::Texture(g.target());
                glTextureStorage3D(g.moments.id(), levels, momentFormatOf(key), size, size, layers);
                g.blurScratch = gl::Texture(GL_TEXTURE_2D);
                glTextureStorage2D(g.blurScratch.id(), 1, momentFormatOf(key), size, size);
                g.blurFbo = gl::Framebuffer();
                glNamedFramebufferTexture(g.blurFbo.id(), GL_COLOR_ATTACHMENT0, g.blurScratch.id(), 0);
                glNamedFramebufferDrawBuffer(g.blurFbo.id(), GL_COLOR_ATTACHMENT0);
                gl::checkFramebuffer(g.blurFbo, "moment blur framebuffer");
            }
            groups.push_back(std::move(g));
        }
        groups_ = std::move(groups);
        // Translucent casters (alphaMode blend) colour the light: each 2D
        // array gets its transmittance layers (made once, kept with the array).
        translucent_ = false;
        for (std::size_t i = 0; i < frame.items.size(); ++i) translucent_ = translucent_ || (frame.items[i].castsShadows && translucentCaster(frame, i));
        for (Group& g : groups_)
            if (translucent_ && !g.transmit) {
                g.transmit = gl::Texture(g.target());
                glTextureStorage3D(g.transmit.id(), 1, GL_RGBA8, g.size(), g.size(), g.layers * g.layersPerLight());
                g.transmitDepth = gl::Texture(g.target());
                glTextureStorage3D(g.transmitDepth.id(), 1, GL_R32F, g.size(), g.size(), g.layers * g.layersPerLight());
            }
        std::map<std::size_t, int> nextLayer;
        std::map<int, PerLight> perLight;
        for (int index : lights) {
            const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
            PerLight p;
            p.options = effectiveHere(light);
            p.cube = isCube(light);
            for (std::size_t g = 0; g < groups_.size(); ++g)
                if (groups_[g].key == GroupKey::of(p.options, p.cube)) p.group = g;
            p.layer = nextLayer[p.group];
            nextLayer[p.group] += p.cube ? 1 : cascadeCount(light, p.options);
            const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld, p.options.size, footprint(p.options)};
            p.spot = light.type == LightType::Spot;
            if (p.options.filter == MapFilter::Pcss && !(light.size > 0.0f))
                host.note("lights[" + std::to_string(index) + "].shadow.map.filter \"pcss\": the light's size is 0, so its shadows stay hard (set lights[" +
                          std::to_string(index) + "].size: a radius, or a directional light's angular diameter in degrees)");
            if (p.cube) {
                const auto [nearPlane, farPlane] = cubeNearFar(p.options);
                p.cubeCamera = fitCube(light, p.options.fit, in, nearPlane, farPlane);
            }
            if (p.options.preset == MapPreset::LearnOpenGL && light.type == LightType::Directional)
                p.camera = learnOpenGlCamera(light, p.options.size);
            else if (light.type == LightType::Point && !p.cube)  // preset "lecture-000"
                p.camera = lecturePointCamera(light, p.options.size);
            else if (p.cube)
                ;  // the cube's cameras above
            else if (light.type == LightType::Spot)
                p.camera = fitSpot(light, p.options.fit, in);
            else if (cascadeCount(light, p.options) > 1)
                fitCascades(p, light, frame, in);
            else
                p.camera = fitDirectional(glm::normalize(light.direction), p.options.fit, in);
            auto old = lights_.find(index);
            if (old != lights_.end()) {
                p.fbo = std::move(old->second.fbo);
                p.attachedGeneration = old->second.attachedGeneration;
                p.attachedLayer = old->second.attachedLayer;
                p.faceFbos = std::move(old->second.faceFbos);
                p.cascadeFbos = std::move(old->second.cascadeFbos);
                p.faceDirty = old->second.faceDirty;
            }
            attach(p);
            perLight.emplace(index, std::move(p));
        }
        lights_ = std::move(perLight);
    }

    bool hasShadowPass(const Light&) const override { return true; }

    void renderShadowPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view) override {
        if (lights_.at(view.index).cube) {
            renderCubePass(host, frame, view, lights_.at(view.index));
            return;
        }
        const PerLight& p = lights_.at(view.index);
        const Group& g = groups_[p.group];
        const bool packed = isPacked(g.format());
        upload(view);
        const gl::Program& program = host.program(
            {{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_depth.frag"}},
             packDefines(g.format()) + "#define MAP_SPOT " + (p.spot ? "1" : "0") + "\n#define MAP_MOMENTS " +
                 std::to_string(static_cast<int>(g.key.representation)) + "\n" + momentDefines(g.key.momentFormat)});
        std::size_t drawn = 0;
        const std::span<const LightCamera> cameras = p.cameras();
        for (std::size_t c = 0; c < cameras.size(); ++c) {
            const LightCamera& camera = cameras[c];
            const gl::Framebuffer& fbo = p.cascades.empty() ? p.fbo : p.cascadeFbos[c];
            glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
            glViewport(0, 0, g.size(), g.size());
            gl::RenderState state;  // all writes on for the clears
            host.apply(state);
            const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
            glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, one);
            if (packed) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, one);
            if (g.hasMoments()) {
                const glm::vec4 far = farMoments(g.key);
                glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, &far.x);
            }
            if (!packed && !g.hasMoments()) state.noColor();
            state.polygonOffset = p.options.slopeBias != 0.0f || p.options.offsetUnits != 0.0f;
            state.offsetFactor = p.options.slopeBias;
            state.offsetUnits = p.options.offsetUnits;
            state.cull = p.options.cullFront ? gl::Cull::Front : gl::Cull::None;
            // An orthographic light pancakes casters nearer than its near plane onto it.
            state.depthClamp = !camera.perspective;
            host.apply(state);
            // This cascade's camera for the depth pass (the block's first member).
            const glm::mat4 lightClip = camera.clipFromWorld();
            glNamedBufferSubData(ubo_.id(), 0, sizeof lightClip, &lightClip);
            // Casters that cannot reach the light's frustum are not drawn.
            std::size_t drawnHere = 0;
            host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) {
                const bool inside = castsInto(camera, frame, i, g.hasMoments());
                if (inside) drawnHere += frame.scene.meshes[static_cast<std::size_t>(frame.items[i].mesh)].triangleCount();
                return inside;
            });
            if (cameras.size() > 1) host.count("cascade" + std::to_string(c) + ".triangles", static_cast<double>(drawnHere));
            drawn += drawnHere;
            if (g.hasMoments() && p.options.blur > 0) blurLayer(host, g, p.layer + static_cast<int>(c), p.options.blur, fbo);
            if (translucent_) drawTranslucent(host, frame, g, p, camera, p.layer + static_cast<int>(c));
        }
        host.count("triangles", static_cast<double>(drawn));
        // The memory of this light's layers (the map the light pass reads and what its pass needs beside it).
        host.count("mapBytes", texelBytes(g.key) * static_cast<double>(g.size()) * static_cast<double>(g.size()) * static_cast<double>(cameras.size()));
        if (g.mipmaps()) {
            // Every level from the map: averaged depths or moments (of all layers; each light's pass refreshes them).
            const auto scope = host.timeScope("mipmaps");
            glGenerateTextureMipmap(packed ? g.packed.id() : g.hasMoments() ? g.moments.id() : g.depth.id());
        }
        if (frame.measureFloors) drawFloor(host, frame, p);
    }

    std::string lightPassDefines(const Light& light) const override {
        const MapOptions o = effective(light);
        return "#define MAP_FILTER " + std::to_string(static_cast<int>(o.filter)) + "\n#define MAP_KERNEL " +
               std::to_string(o.kernel) + "\n" + packDefines(o.format) +
               "\n#define MAP_GRID_BILINEAR " + (bilinearGrid(o) ? "1" : "0") + "\n#define MAP_CUBE " + (isCube(light) ? "1" : "0") +
               "\n#define MAP_CASCADES " + std::to_string(cascadeCount(light, o)) + "\n#define MAP_MOMENTS " +
               std::to_string(isCube(light) ? 0 : static_cast<int>(o.representation)) + "\n" + momentDefines(o.momentFormat);
    }

    void bindLightPass(TechniqueHost&, const FrameInfo&, const LightView& view) override {
        const PerLight& p = lights_.at(view.index);
        const Group& g = groups_[p.group];
        upload(view);
        if (p.cube) {
            // Filters read across face edges (the test with a plane over the seams).
            glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
            const bool packed = isPacked(g.format());
            glBindTextureUnit(SL_UNIT_SHADOW_FIRST, packed ? g.packed.id() : g.depth.id());
            const bool linear = p.options.filter == MapFilter::Hardware || p.options.filter == MapFilter::Pcss;
            glBindSampler(SL_UNIT_SHADOW_FIRST, packed ? plainNearest_.id() : linear ? compareLinear_.id() : compareNearest_.id());
            bindRawDepth(p, g);
            bindTransmittance(p, g);
            return;
        }
        if (g.hasMoments()) {
            glBindTextureUnit(SL_UNIT_SHADOW_FIRST, g.moments.id());
            glBindSampler(SL_UNIT_SHADOW_FIRST, g.mipmaps() ? momentLinearMip_.id() : momentLinear_.id());
        } else if (isPacked(g.format())) {
            glBindTextureUnit(SL_UNIT_SHADOW_FIRST, g.packed.id());
            glBindSampler(SL_UNIT_SHADOW_FIRST, g.mipmaps() ? plainNearestMip_.id() : plainNearest_.id());
        } else {
            glBindTextureUnit(SL_UNIT_SHADOW_FIRST, g.depth.id());
            // Bilinear compares: the hardware filter, and the grid's paired taps (shadow_map.glsl).
            const bool linear = p.options.filter == MapFilter::Hardware || p.options.filter == MapFilter::Pcss ||
                                (p.options.filter == MapFilter::Grid && bilinearGrid(p.options));
            glBindSampler(SL_UNIT_SHADOW_FIRST, g.mipmaps() ? (linear ? compareLinearMip_.id() : compareNearestMip_.id())
                                                          : (linear ? compareLinear_.id() : compareNearest_.id()));
            bindRawDepth(p, g);
        }
        bindTransmittance(p, g);
    }

    // PCSS's blocker search reads the stored depths themselves: the same
    // depth array on the next unit through a sampler without comparison.
    void bindTransmittance(const PerLight&, const Group& g) const {
        if (!translucent_ || !g.transmit) return;
        glBindTextureUnit(SL_UNIT_SHADOW_FIRST + 2, g.transmit.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST + 2, plainNearest_.id());  // outside the map: the border, white
        glBindTextureUnit(SL_UNIT_SHADOW_FIRST + 3, g.transmitDepth.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST + 3, plainNearest_.id());  // and depth 1
    }

    void bindRawDepth(const PerLight& p, const Group& g) const {
        if (p.options.filter != MapFilter::Pcss || isPacked(g.format())) return;
        glBindTextureUnit(SL_UNIT_SHADOW_FIRST + 1, g.depth.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST + 1, g.mipmaps() ? plainNearestMip_.id() : plainNearest_.id());
    }

    void debugImages(TechniqueHost& host, const FrameInfo& frame, const LightView& view, std::vector<DebugImage>& out) override {
        const PerLight& p = lights_.at(view.index);
        const Group& g = groups_[p.group];
        if (p.cube) {
            std::vector<float> values;
            ImageRGBA8 cross = cubeCross(p, values);
            out.push_back({"cube", std::move(cross), std::move(values)});
            return;
        }
        const std::size_t n = static_cast<std::size_t>(g.size()) * static_cast<std::size_t>(g.size());
        const std::span<const LightCamera> cameras = p.cameras();
        for (std::size_t c = 0; c < cameras.size(); ++c) {
            const LightCamera& camera = cameras[c];
            const std::vector<float> depth = readLayer(g, p.layer + static_cast<int>(c));
            ImageRGBA8 image{g.size(), g.size(), std::vector<std::uint8_t>(n * 4, 255)};
            const float nearP = camera.nearPlane, farP = camera.farPlane;
            for (int y = 0; y < g.size(); ++y)
                for (int x = 0; x < g.size(); ++x) {
                    float d = depth[static_cast<std::size_t>(y) * g.size() + x];
                    if (camera.perspective && d < 1.0f) {
                        // Perspective depth linearised: eye distance from window depth, then 0..1 over near..far.
                        const float z = 2.0f * d - 1.0f;
                        const float eye = 2.0f * nearP * farP / (farP + nearP - z * (farP - nearP));
                        d = (eye - nearP) / (farP - nearP);
                    }
                    const auto v = static_cast<std::uint8_t>(std::clamp(d, 0.0f, 1.0f) * 255.0f + 0.5f);
                    // Rows top to bottom: the map's v = 1 at the top.
                    std::uint8_t* px = &image.pixels[(static_cast<std::size_t>(g.size() - 1 - y) * g.size() + x) * 4];
                    px[0] = px[1] = px[2] = v;
                }
            out.push_back({cameras.size() > 1 ? "cascade" + std::to_string(c) + "-map" : std::string("map"), std::move(image), {}});
        }
        out.push_back({"texel-density", frameView(host, frame, view, "shadow_map_density.frag"), {}});
        if (cameras.size() > 1) out.push_back({"cascades", frameView(host, frame, view, "shadow_map_cascades.frag"), {}});
    }

    void lightFrustums(const LightView& view, std::vector<glm::mat4>& out) const override {
        const auto found = lights_.find(view.index);
        if (found == lights_.end()) return;
        const PerLight& p = found->second;
        if (p.cube)
            out.insert(out.end(), p.cubeCamera.faceClipFromWorld.begin(), p.cubeCamera.faceClipFromWorld.end());
        else
            for (const LightCamera& camera : p.cameras()) out.push_back(camera.clipFromWorld());
    }

private:
    // The translucent casters into layer `layer`'s transmittance: their
    // colours multiplied together and their nearest depth, where no opaque
    // caster is nearer (the map's own depth, tested, not written).
    void drawTranslucent(TechniqueHost& host, const FrameInfo& frame, const Group& g, const PerLight& p, const LightCamera& camera, int layer) {
        const auto scope = host.timeScope("translucent");
        const gl::Framebuffer fbo = beginTranslucent(host, g, layer, sharedDepthBuffer(g.key) ? 0 : layer, !camera.perspective);
        const glm::mat4 lightClip = camera.clipFromWorld();
        glNamedBufferSubData(ubo_.id(), 0, sizeof lightClip, &lightClip);
        const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_transmit.frag"}},
                                                   std::string("#define MAP_SPOT ") + (p.spot ? "1" : "0") + "\n"});
        host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) { return translucentCaster(frame, i) && castsInto(camera, frame, i, true); });
        endTranslucent(host);
    }

    static bool translucentCaster(const FrameInfo& frame, std::size_t i) {
        const int m = frame.items[i].material;
        return m >= 0 && frame.scene.materials[static_cast<std::size_t>(m)].alphaMode == AlphaMode::Blend;
    }

    // The target of the translucent casters for one layer (a 2D map's, or a
    // cube face's): its transmittance and nearest-depth layers as colours,
    // cleared to white, over the opaque depth of `depthLayer`, tested, not
    // written; transmittances multiply (dst x src), depths keep the least.
    gl::Framebuffer beginTranslucent(TechniqueHost& host, const Group& g, int layer, int depthLayer, bool depthClamp) {
        gl::Framebuffer fbo;
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, g.transmit.id(), 0, layer);
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT1, g.transmitDepth.id(), 0, layer);
        glNamedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, g.depth.id(), 0, depthLayer);
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fbo.id(), 2, buffers);
        gl::checkFramebuffer(fbo, "translucent casters framebuffer");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, g.size(), g.size());
        gl::RenderState state;
        host.apply(state);
        const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, white);
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, white);
        state.depthWrite = false;
        state.depthClamp = depthClamp;
        host.apply(state);
        glEnablei(GL_BLEND, 0);
        glBlendEquationi(0, GL_FUNC_ADD);
        glBlendFunci(0, GL_ZERO, GL_SRC_COLOR);
        glEnablei(GL_BLEND, 1);
        glBlendEquationi(1, GL_MIN);
        glBlendFunci(1, GL_ONE, GL_ONE);
        return fbo;
    }
    void endTranslucent(TechniqueHost& host) {
        glDisablei(GL_BLEND, 0);
        glDisablei(GL_BLEND, 1);
        host.apply(gl::RenderState{});
    }

    // Moment maps: the exponents of EVSM's warps (32-bit floats: 40 and 5, as
    // MJP's sample; 16-bit: 5.54 each, the most e^(2c) allows under 65504)
    // and MSM's and VSM's floors, as GLSL defines for every program that
    // writes or reads moments.
    static std::string momentDefines(MapMomentFormat format) {
        const bool half = format == MapMomentFormat::Rgba16f;
        char text[200];
        std::snprintf(text, sizeof text, "#define MAP_EVSM_POSITIVE %.4f\n#define MAP_EVSM_NEGATIVE %.4f\n#define MAP_MOMENT_BIAS %.1e\n#define MAP_MIN_VARIANCE %.1e\n",
                      half ? 5.54 : 40.0, half ? 5.54 : 5.0, half ? 1e-3 : 3e-5, half ? 1e-4 : 1e-6);
        return text;
    }
    // The moments of depth 1 (nothing in front of the far plane): the clear colour.
    static glm::vec4 farMoments(const GroupKey& k) {
        const bool half = k.momentFormat == MapMomentFormat::Rgba16f;
        const float positive = half ? 5.54f : 40.0f, negative = half ? 5.54f : 5.0f;
        switch (k.representation) {
        case MapRepresentation::Evsm2:
        case MapRepresentation::Evsm4:
            return {std::exp(positive), std::exp(2.0f * positive), -std::exp(-negative), std::exp(-2.0f * negative)};
        default: return glm::vec4(1.0f);
        }
    }
    // The separable Gaussian blur of one moment layer: across into the
    // scratch texture, then down back into the layer (its framebuffer `fbo`).
    void blurLayer(TechniqueHost& host, const Group& g, int layer, int radius, const gl::Framebuffer& fbo) {
        const auto scope = host.timeScope("blur");
        host.apply(gl::RenderState{.depthTest = false, .depthWrite = false});
        for (int axis = 0; axis < 2; ++axis) {
            const glm::vec4 blur(static_cast<float>(radius), static_cast<float>(axis), static_cast<float>(layer), 0.0f);
            glNamedBufferSubData(ubo_.id(), offsetof(shared::MapUniforms, blur), sizeof blur, &blur);
            glBindFramebuffer(GL_FRAMEBUFFER, axis == 0 ? g.blurFbo.id() : fbo.id());
            glBindTextureUnit(SL_UNIT_SHADOW_FIRST, axis == 0 ? g.moments.id() : g.blurScratch.id());
            glBindSampler(SL_UNIT_SHADOW_FIRST, 0);
            const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_blur.frag"}},
                                                       "#define BLUR_FROM_ARRAY " + std::to_string(axis == 0 ? 1 : 0) + "\n"});
            glUseProgram(program.id());
            host.drawFullscreenTriangle();
        }
        glBindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
    }

    // A directional light's cascades: the view's depth split into slices
    // (core/LightCamera: cascadeSplits, fitCascade), one camera each.
    static void fitCascades(PerLight& p, const Light& light, const FrameInfo& frame, const FitInput& in) {
        const Camera& camera = frame.scene.camera;
        const float aspect = static_cast<float>(frame.viewport.x) / static_cast<float>(std::max(frame.viewport.y, 1));
        // Stabilised slices must not move with the camera: they end at its far
        // plane; tight ones at the farthest receiver it sees.
        const float near = camera.nearPlane;
        const float far = p.options.stabilize ? camera.farPlane : viewReach(camera, in);
        std::string problem;  // checked when the scene was read (the registry's unsupported())
        const std::vector<float> given = parseSplits(p.options, problem);
        p.cascadeFar = cascadeSplits(near, far, p.options.cascades, p.options.cascadeLambda, given);
        p.cascades.clear();
        for (std::size_t c = 0; c < p.cascadeFar.size(); ++c)
            p.cascades.push_back(fitCascade(glm::normalize(light.direction), camera, aspect, c == 0 ? near : p.cascadeFar[c - 1], p.cascadeFar[c],
                                            p.options.stabilize, in));
        p.camera = p.cascades.front();
        const glm::mat4& v = frame.viewFromWorld;
        p.viewForward = -glm::vec3(v[0][2], v[1][2], v[2][2]);
    }

    // One layer of a group's array (a 2D map, or one face of a cube) as
    // stored depths in 0..1: read back, or unpacked from rgba8's base-255
    // digits (the 4th is below float precision here) or r8's one byte.
    std::vector<float> readLayer(const Group& g, int layer) const {
        const std::size_t n = static_cast<std::size_t>(g.size()) * static_cast<std::size_t>(g.size());
        std::vector<float> depth(n);
        if (g.format() == MapFormat::Rgba8) {
            std::vector<std::uint8_t> rgba(n * 4);
            glGetTextureSubImage(g.packed.id(), 0, 0, 0, layer, g.size(), g.size(), 1, GL_RGBA, GL_UNSIGNED_BYTE,
                                 static_cast<GLsizei>(rgba.size()), rgba.data());
            for (std::size_t i = 0; i < n; ++i) depth[i] = rgba[4 * i] / 255.0f + rgba[4 * i + 1] / 65025.0f + rgba[4 * i + 2] / 16581375.0f;
        } else if (g.format() == MapFormat::R8) {
            std::vector<std::uint8_t> r(n);
            glGetTextureSubImage(g.packed.id(), 0, 0, 0, layer, g.size(), g.size(), 1, GL_RED, GL_UNSIGNED_BYTE, static_cast<GLsizei>(n), r.data());
            for (std::size_t i = 0; i < n; ++i) depth[i] = r[i] / 255.0f;
        } else {
            glGetTextureSubImage(g.depth.id(), 0, 0, 0, layer, g.size(), g.size(), 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                                 static_cast<GLsizei>(n * sizeof(float)), depth.data());
        }
        return depth;
    }

    // A point light's six faces as a horizontal cross (+Y above; -X, +Z, +X,
    // -Z across; -Y below: neighbouring edges touch), each face's rows as GL
    // stores them (t down), tiles of at most 512 texels. Stored depth is
    // distance / far, already linear: stretched over its range for
    // contrast; white where no caster was drawn.
    ImageRGBA8 cubeCross(const PerLight& p, std::vector<float>& values) const {
        const Group& g = groups_[p.group];
        const int tile = std::min(g.size(), 512);
        std::array<std::vector<float>, 6> faces;
        float lo = 1.0f, hi = 0.0f;
        for (int f = 0; f < 6; ++f) {
            std::vector<float>& depth = faces[static_cast<std::size_t>(f)];
            depth = readLayer(g, 6 * p.layer + f);
            for (float d : depth)
                if (d < 1.0f) {
                    lo = std::min(lo, d);
                    hi = std::max(hi, d);
                }
        }
        ImageRGBA8 image{4 * tile, 3 * tile, std::vector<std::uint8_t>(static_cast<std::size_t>(12 * tile * tile) * 4, 0)};
        for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
        // Face index at (column, row) of the cross.
        const int place[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
        for (int f = 0; f < 6; ++f) {
            const std::vector<float>& depth = faces[static_cast<std::size_t>(f)];
            for (int y = 0; y < tile; ++y)
                for (int x = 0; x < tile; ++x) {
                    const int sx = x * g.size() / tile, sy = y * g.size() / tile;
                    const float d = depth[static_cast<std::size_t>(sy) * g.size() + sx];
                    const float v = d >= 1.0f ? 1.0f : 0.1f + 0.8f * (hi > lo ? (d - lo) / (hi - lo) : 0.0f);
                    const auto grey = static_cast<std::uint8_t>(v * 255.0f + 0.5f);
                    const std::size_t px = (static_cast<std::size_t>(place[f][1] * tile + y) * static_cast<std::size_t>(4 * tile) +
                                            static_cast<std::size_t>(place[f][0] * tile + x)) * 4;
                    image.pixels[px] = image.pixels[px + 1] = image.pixels[px + 2] = grey;
                }
        }
        values.clear();
        for (const std::vector<float>& depth : faces) values.insert(values.end(), depth.begin(), depth.end());
        return image;
    }

    // Attaches the light's layer to its framebuffer when the array or the
    // layer changed (a new array gets a new framebuffer: the old one may
    // still name the deleted texture).
    void attach(PerLight& p) {
        const Group& g = groups_[p.group];
        const bool attached = p.attachedGeneration == g.generation && p.attachedLayer == p.layer &&
                              (p.cascades.empty() ? static_cast<bool>(p.fbo) : p.cascadeFbos.size() == p.cascades.size());
        if (attached) return;
        if (!p.fbo || p.attachedGeneration != g.generation) p.fbo = gl::Framebuffer();
        const bool packed = isPacked(g.format());
        // The colour the pass writes: depth packed into RGBA8, or moments.
        const GLuint colour = packed ? g.packed.id() : g.hasMoments() ? g.moments.id() : 0;
        auto attachOne = [&](gl::Framebuffer& fbo, int layer, const char* what) {
            if (layer < 0) {  // the whole array, layered (gl_Layer picks)
                glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, g.depth.id(), 0);
                if (colour) glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, colour, 0);
            } else {
                glNamedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, g.depth.id(), 0, sharedDepthBuffer(g.key) ? 0 : layer);
                if (colour) glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, colour, 0, layer);
            }
            glNamedFramebufferDrawBuffer(fbo.id(), colour ? GL_COLOR_ATTACHMENT0 : GL_NONE);
            glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
            gl::checkFramebuffer(fbo, what);
        };
        if (p.cube) {
            attachOne(p.fbo, -1, "cube shadow map framebuffer (layered)");
            for (int f = 0; f < 6; ++f) {
                gl::Framebuffer& face = p.faceFbos[static_cast<std::size_t>(f)];
                face = gl::Framebuffer();
                attachOne(face, 6 * p.layer + f, "cube shadow map framebuffer (one face)");
            }
            p.faceDirty.fill(TexelRect::whole());  // a new array or layer: its contents are undefined
        } else if (!p.cascades.empty()) {
            p.cascadeFbos.clear();
            for (std::size_t c = 0; c < p.cascades.size(); ++c) {
                p.cascadeFbos.emplace_back();
                attachOne(p.cascadeFbos.back(), p.layer + static_cast<int>(c), "cascade shadow map framebuffer");
            }
        } else {
            attachOne(p.fbo, p.layer, "shadow map framebuffer");
        }
        p.attachedGeneration = g.generation;
        p.attachedLayer = p.layer;
    }
    std::uint64_t generations_ = 0;

    bool bilinearGrid(const MapOptions& o) const {
        return !isPacked(o.format) &&
               (o.gridTaps == MapGridTaps::Bilinear || (o.gridTaps == MapGridTaps::Auto && !software_));
    }
    bool software_ = false;

    // The frame from the camera, each visible point coloured by
    // `fragmentFile` with the light's map block: shadow-map texels per
    // screen pixel (shadow_map_density.frag), the cascade
    // (shadow_map_cascades.frag).
    ImageRGBA8 frameView(TechniqueHost& host, const FrameInfo& frame, const LightView& view, const char* fragmentFile) {
        const glm::ivec2 size = frame.viewport;
        gl::Texture colour(GL_TEXTURE_2D), depth(GL_TEXTURE_2D);
        glTextureStorage2D(colour.id(), 1, GL_RGBA8, size.x, size.y);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT24, size.x, size.y);
        gl::Framebuffer fbo;
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, colour.id(), 0);
        glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        gl::checkFramebuffer(fbo, "texel-density framebuffer");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, size.x, size.y);
        host.apply(gl::RenderState{});
        const float background[4] = {0.0f, 0.0f, 0.0f, 1.0f}, one = 1.0f;
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, background);
        glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
        upload(view);
        const int cascades = static_cast<int>(lights_.at(view.index).cameras().size());
        host.drawItems(ItemFilter::All, host.program({{{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, fragmentFile}},
                                                      "#define MAP_CASCADES " + std::to_string(cascades) + "\n"}));
        ImageRGBA8 image{size.x, size.y, std::vector<std::uint8_t>(static_cast<std::size_t>(size.x) * size.y * 4)};
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTextureImage(colour.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.pixels.size()), image.pixels.data());
        // GL's rows go bottom to top; images top to bottom.
        const std::size_t row = static_cast<std::size_t>(size.x) * 4;
        for (int y = 0; y < size.y / 2; ++y)
            std::swap_ranges(image.pixels.begin() + static_cast<long>(y * row), image.pixels.begin() + static_cast<long>((y + 1) * row),
                             image.pixels.begin() + static_cast<long>((size.y - 1 - y) * row));
        return image;
    }

    // The floor of a shadow pass: the same casters, depth only, into a
    // scratch target of the same size and format, with no bias, culling or
    // packing: what the pass itself costs at least.
    void ensureFloorTarget(const Group& g) {
        if (!floorTarget_ || floorSize_ != g.size() || floorFormat_ != g.format()) {
            floorTarget_ = gl::Texture(GL_TEXTURE_2D);
            glTextureStorage2D(floorTarget_.id(), 1, depthFormat(g.format()), g.size(), g.size());
            floorFbo_ = gl::Framebuffer();
            glNamedFramebufferTexture(floorFbo_.id(), GL_DEPTH_ATTACHMENT, floorTarget_.id(), 0);
            glNamedFramebufferDrawBuffer(floorFbo_.id(), GL_NONE);
            floorSize_ = g.size();
            floorFormat_ = g.format();
        }
    }

    // The floor's target for `g`, bound, and its bare depth-only program.
    const gl::Program& bindFloor(TechniqueHost& host, const Group& g) {
        ensureFloorTarget(g);
        glBindFramebuffer(GL_FRAMEBUFFER, floorFbo_.id());
        glViewport(0, 0, g.size(), g.size());
        return host.program(
            {{{GL_VERTEX_SHADER, "shadow_map_depth.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_depth.frag"}}, "#define MAP_RGBA8 0\n#define MAP_SPOT 0\n#define MAP_MOMENTS 0\n"});
    }

    // Clears the floor's target (all writes on), then leaves depth-only writes.
    void clearFloor(TechniqueHost& host, bool depthClamp) {
        gl::RenderState state;
        host.apply(state);
        const float one = 1.0f;
        glClearNamedFramebufferfv(floorFbo_.id(), GL_DEPTH, 0, &one);
        state.noColor();
        state.depthClamp = depthClamp;
        host.apply(state);
    }

    void drawFloor(TechniqueHost& host, const FrameInfo& frame, const PerLight& p) {
        const auto scope = host.timeScope("floor");
        const gl::Program& bare = bindFloor(host, groups_[p.group]);
        for (const LightCamera& camera : p.cameras()) {
            clearFloor(host, !camera.perspective);
            const glm::mat4 lightClip = camera.clipFromWorld();
            glNamedBufferSubData(ubo_.id(), 0, sizeof lightClip, &lightClip);
            host.drawItems(ItemFilter::Casters, bare, [&](std::size_t i) { return castsInto(camera, frame, i, groups_[p.group].hasMoments()); });
        }
    }

    // Whether item i is drawn into `camera`'s map: it may cast there, and
    // its bounds reach the frustum (an orthographic light's sides only: it
    // clamps depth). A moment map takes every caster in the frustum, the
    // floors too: its filtered moments must hold the receivers' own depths
    // beside the occluders', or an edge's blur would mix the occluder with
    // the empty far plane and light the receiver under it.
    static bool castsInto(const LightCamera& camera, const FrameInfo& frame, std::size_t i, bool moments) {
        if (!moments && !mayCast(camera, i)) return false;
        const glm::mat4 lightClip = camera.clipFromWorld();
        return !camera.perspective ? mayIntersectSides(lightClip, frame.itemBounds[i]) : mayIntersect(lightClip, frame.itemBounds[i]);
    }

    gl::Texture floorTarget_{gl::NoCreate};
    gl::Framebuffer floorFbo_{gl::NoCreate};
    int floorSize_ = 0;
    MapFormat floorFormat_ = MapFormat::Depth32F;

    // A point light's cube: its faces cleared where they hold or will hold
    // casters, then the casters drawn once through the geometry shader
    // (each triangle to the faces it touches) or once per face they touch.
    void renderCubePass(TechniqueHost& host, const FrameInfo& frame, const LightView& view, PerLight& p) {
        const Group& g = groups_[p.group];
        const bool packed = isPacked(g.format());
        std::array<bool, 6> used{};
        std::array<TexelRect, 6> covered{};
        std::array<double, 6> faceTriangles{};
        std::size_t drawn = 0;
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            const std::uint8_t mask = faceMask(p, i);
            if (!mask || !frame.items[i].castsShadows) continue;
            const auto triangles = static_cast<double>(frame.scene.meshes[static_cast<std::size_t>(frame.items[i].mesh)].triangleCount());
            drawn += static_cast<std::size_t>(triangles);
            for (std::size_t f = 0; f < 6; ++f)
                if (mask & (1u << f)) {
                    used[f] = true;
                    faceTriangles[f] += triangles;
                    covered[f] = covered[f].united(projectedRect(p.cubeCamera.faceClipFromWorld[f], frame.itemBounds[i], g.size()));
                }
        }
        upload(view);
        gl::RenderState state;  // all writes on for the clears
        host.apply(state);
        {
            const auto scope = host.timeScope("clear");
            const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
            for (int f = 0; f < 6; ++f) {
                const auto face = static_cast<std::size_t>(f);
                // Only texels that held casters or will: the rest is still clear.
                const TexelRect r = p.faceDirty[face].clamped(g.size()).united(covered[face]);
                p.faceDirty[face] = covered[face];
                if (r.empty()) continue;
                glClearTexSubImage(g.depth.id(), 0, r.x0, r.y0, 6 * p.layer + f, r.x1 - r.x0, r.y1 - r.y0, 1, GL_DEPTH_COMPONENT, GL_FLOAT, one);
                if (packed) glClearTexSubImage(g.packed.id(), 0, r.x0, r.y0, 6 * p.layer + f, r.x1 - r.x0, r.y1 - r.y0, 1, GL_RGBA, GL_FLOAT, one);
            }
        }
        if (!packed) state.noColor();
        state.cull = p.options.cullFront ? gl::Cull::Front : gl::Cull::None;
        host.apply(state);
        const bool onePass = p.options.cubePasses == MapCubePasses::One;
        const std::string defines = packDefines(g.format()) + "#define MAP_CUBE_ONE_PASS " + (onePass ? "1" : "0") +
                                    "\n#define MAP_CUBE_CULL " + (p.options.faceCulling ? "1" : "0") + "\n";
        glViewport(0, 0, g.size(), g.size());
        if (onePass) {
            const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "shadow_map_cube.vert"},
                                                        {GL_GEOMETRY_SHADER, "shadow_map_cube.geom"},
                                                        {GL_FRAGMENT_SHADER, "shadow_map_cube.frag"}},
                                                       defines});
            glBindFramebuffer(GL_FRAMEBUFFER, p.fbo.id());
            host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) {
                if (!faceMask(p, i)) return false;
                glProgramUniform1ui(program.id(), 0, faceMask(p, i));
                return true;
            });
        } else {
            const gl::Program& program = host.program(
                {{{GL_VERTEX_SHADER, "shadow_map_cube.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_cube.frag"}}, defines});
            for (int f = 0; f < 6; ++f) {
                if (!used[static_cast<std::size_t>(f)]) continue;
                glBindFramebuffer(GL_FRAMEBUFFER, p.faceFbos[static_cast<std::size_t>(f)].id());
                glProgramUniform1i(program.id(), 1, f);
                host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) { return (faceMask(p, i) & (1u << f)) != 0; });
            }
        }
        static const char* faceNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
        host.count("triangles", static_cast<double>(drawn));
        for (std::size_t f = 0; f < 6; ++f) host.count(std::string("faceTriangles.") + faceNames[f], faceTriangles[f]);
        if (translucent_) drawCubeTranslucent(host, frame, g, p);
        if (frame.measureFloors) drawCubeFloor(host, p, used);
    }

    // A point light's translucent casters into its cube's transmittance
    // layers, face by face, after the opaque depth (drawTranslucent's cube form).
    void drawCubeTranslucent(TechniqueHost& host, const FrameInfo& frame, const Group& g, const PerLight& p) {
        const auto scope = host.timeScope("translucent");
        const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "shadow_map_cube.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_cube_transmit.frag"}},
                                                   "#define MAP_CUBE_ONE_PASS 0\n"});
        for (int f = 0; f < 6; ++f) {
            const int layer = 6 * p.layer + f;
            const gl::Framebuffer fbo = beginTranslucent(host, g, layer, layer, false);
            glProgramUniform1i(program.id(), 1, f);
            host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) { return translucentCaster(frame, i) && (faceMask(p, i) & (1u << f)) != 0; });
            endTranslucent(host);
        }
    }

    // The cube faces item i is drawn into: those its bounds touch, or all
    // six without face culling; none for an item that cannot shadow anything seen.
    static std::uint8_t faceMask(const PerLight& p, std::size_t i) {
        const std::uint8_t mask = p.cubeCamera.faceMasks[i];
        return p.options.faceCulling || !mask ? mask : std::uint8_t{0x3F};
    }

    // A cube's floor: per face it uses, a bare depth-only draw of that
    // face's casters into a scratch target of the face's size and format.
    void drawCubeFloor(TechniqueHost& host, const PerLight& p, const std::array<bool, 6>& used) {
        const auto scope = host.timeScope("floor");
        const gl::Program& bare = bindFloor(host, groups_[p.group]);
        for (int f = 0; f < 6; ++f) {
            if (!used[static_cast<std::size_t>(f)]) continue;
            clearFloor(host, false);
            // The bare vertex shader reads map.lightClipFromWorld: this face's camera.
            shared::MapUniforms u = uniforms_;
            u.lightClipFromWorld = p.cubeCamera.faceClipFromWorld[static_cast<std::size_t>(f)];
            glNamedBufferSubData(ubo_.id(), 0, sizeof u, &u);
            host.drawItems(ItemFilter::Casters, bare, [&](std::size_t i) { return (faceMask(p, i) & (1u << f)) != 0; });
        }
        glNamedBufferSubData(ubo_.id(), 0, sizeof uniforms_, &uniforms_);
    }

    // Casters the fit found unable to shadow anything visible are skipped.
    static bool mayCast(const LightCamera& camera, std::size_t item) { return camera.casts.empty() || camera.casts[item] != 0; }

    // Directional lights clamp depth, so only the four side planes cull.
    static bool mayIntersectSides(const glm::mat4& clipFromWorld, const Bounds& box) {
        glm::mat4 flattened = clipFromWorld;
        for (int c = 0; c < 4; ++c) flattened[c][2] = 0.0f;  // z' = 0: never beyond near or far
        return mayIntersect(flattened, box);
    }

    void upload(const LightView& view) {
        const PerLight& p = lights_.at(view.index);
        const Group& g = groups_[p.group];
        const Light& light = view.light;
        shared::MapUniforms u{};
        u.lightClipFromWorld = p.camera.clipFromWorld();
        u.shadowFromWorld = kBias * u.lightClipFromWorld;
        u.params = glm::vec4(static_cast<float>(p.layer), reach(p.options), p.camera.texelSize, p.camera.perspective ? 1.0f : 0.0f);
        u.bias = glm::vec4(p.options.constantBias, 0.0f, 0.0f, p.options.normalBias);
        if (p.options.preset == MapPreset::LearnOpenGL && !p.cube) u.bias = glm::vec4(0.0f, 0.05f, 0.005f, 0.0f);
        // Dither spread: one texel (the lecture's 2.5 x 0.001 uv at 1024 texels, about 2.5 texels, with preset lecture).
        const float spread = isLecture2D(p.options, light) ? 2.5f * 0.001f * static_cast<float>(g.size()) : 1.0f;
        u.taps = glm::vec4(1.0f / static_cast<float>(g.size()), p.options.radius, static_cast<float>(p.options.samples), spread);
        u.light = light.type == LightType::Directional ? glm::vec4(-glm::normalize(light.direction), p.options.shadowedLight)
                                                         : glm::vec4(light.position, p.options.shadowedLight);
        // The light camera's view direction: minus the view matrix's third row.
        const glm::mat4& v = p.camera.viewFromWorld;
        u.axis = glm::vec4(-glm::vec3(v[0][2], v[1][2], v[2][2]), 0.0f);
        if (p.cube) {
            const CubeCamera& c = p.cubeCamera;
            for (std::size_t f = 0; f < 6; ++f) u.faceClipFromWorld[f] = c.faceClipFromWorld[f];
            const bool presetBias = p.options.preset != MapPreset::Default;
            // The presets give their constant bias in world units (001, LearnOpenGL: 0.15).
            u.bias.x = presetBias ? p.options.constantBias / c.farPlane : p.options.constantBias;
            // The constant offset in the format's smallest steps.
            const float step = g.format() == MapFormat::Depth16 ? 1.0f / 65535.0f : g.format() == MapFormat::Depth24 ? 1.0f / 16777215.0f : 1.0f / 16777216.0f;
            u.cube = glm::vec4(c.farPlane, p.options.slopeBias, 2.0f / static_cast<float>(g.size()), p.options.diskRadius);
            u.cubeMore = glm::vec4(p.options.diskGrowth, p.options.offsetUnits * step, presetBias ? 1.0f : 0.0f, 0.0f);
        }
        for (std::size_t c = 0; c < p.cascades.size(); ++c) {
            u.cascadeShadowFromWorld[c] = kBias * p.cascades[c].clipFromWorld();
            u.cascadeFar[c / 4][static_cast<int>(c % 4)] = p.cascadeFar[c];
            u.cascadeTexel[c / 4][static_cast<int>(c % 4)] = p.cascades[c].texelSize;
        }
        u.cascade = glm::vec4(glm::normalize(p.viewForward), p.options.cascadeBlend);
        for (std::size_t c = 0; c < p.cascades.size(); ++c) u.cascadeRange[c] = glm::vec4(p.cascades[c].nearPlane, p.cascades[c].farPlane, 0.0f, 0.0f);
        // PCSS: the light's size as the similar triangles take it.
        const float size = light.type == LightType::Directional ? std::tan(glm::radians(0.5f * light.size)) : light.size;
        u.pcss = glm::vec4(size, p.camera.nearPlane, p.camera.farPlane, static_cast<float>(p.options.blockerSamples));
        u.moments = glm::vec4(p.options.bleedReduction, 0.0f, 0.0f, 0.0f);
        u.transmit = glm::vec4(translucent_ ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
        uniforms_ = u;
        glNamedBufferSubData(ubo_.id(), 0, sizeof u, &u);
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_TECHNIQUE, ubo_.id());
    }

    std::vector<Group> groups_;
    std::map<int, PerLight> lights_;
    bool translucent_ = false;  ///< the frame has translucent casters: 2D maps get transmittance layers
    gl::Sampler compareNearest_{gl::NoCreate}, compareLinear_{gl::NoCreate}, plainNearest_{gl::NoCreate};
    gl::Sampler compareNearestMip_{gl::NoCreate}, compareLinearMip_{gl::NoCreate}, plainNearestMip_{gl::NoCreate};
    gl::Sampler momentLinear_{gl::NoCreate}, momentLinearMip_{gl::NoCreate};
    gl::Buffer ubo_{gl::NoCreate};
    shared::MapUniforms uniforms_{};  ///< what upload() last wrote
};

} // namespace

TechniqueEntry mapTechnique() {
    return {"map", "a shadow map per light: orthographic for directional, perspective for spot lights", &mapOptionTable(),
            "shadow_map.glsl", [] { return std::make_unique<ShadowMap>(); }, [](const Light& light) {
                const MapOptions& o = light.shadow.get<MapOptions>();
                if (isCube(light)) {
                    if (o.filter == MapFilter::Dither4)
                        return std::string("map: filter \"dither4\" is for 2D maps (directional and spot lights); a point light's cube takes none, hardware, grid, poisson or pcf20");
                    if (o.mipmaps) return std::string("map: mipmaps are for 2D maps (directional and spot lights), not a point light's cube");
                    if (o.representation != MapRepresentation::Depth)
                        return std::string("map: representation \"vsm\", \"evsm2\", \"evsm4\" and \"msm\" are for 2D maps (directional and spot lights), not a point light's cube");
                } else if (o.filter == MapFilter::Pcf20 && o.preset == MapPreset::Default) {
                    return std::string("map: filter \"pcf20\" (the lecture's 20 directions) is for point lights' cube maps");
                }
                if (o.representation != MapRepresentation::Depth) {
                    if (isPacked(o.format)) return std::string("map: moment maps have their own format (momentFormat); formats \"rgba8\" and \"r8\" pack depth only");
                    if (o.filter != MapFilter::Hardware)
                        return std::string("map: a moment map is filtered by its blur and bilinear lookups; filter must be \"hardware\" (the default)");
                    if (o.preset != MapPreset::Default) return std::string("map: moment maps do not combine with a preset; use preset \"default\"");
                }
                if (o.cascades > 1) {
                    if (light.type != LightType::Directional)
                        return std::string("map: cascades are for directional lights; a spot or point light takes one map (cascades 1)");
                    if (o.preset != MapPreset::Default)
                        return std::string("map: cascades do not combine with a preset (each preset is one map); use preset \"default\"");
                    if (o.fit == MapFit::Scene)
                        return std::string("map: cascades fit each slice of the view; fit \"scene\" is one map around the whole scene");
                    std::string problem;
                    parseSplits(o, problem);
                    if (!problem.empty()) return "map: cascadeSplits \"" + text::escapeControl(o.cascadeSplits) + "\": " + problem;
                } else if (!o.cascadeSplits.empty() && o.cascadeSplits.find_first_not_of(" ,\t") != std::string::npos) {
                    return std::string("map: cascadeSplits is given but cascades is 1");
                }
                return std::string();
            },
            "shadow_map_vertex.glsl"};
}

} // namespace shadowlab
