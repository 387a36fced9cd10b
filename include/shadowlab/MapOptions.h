#pragma once
/// @file MapOptions.h
/// Options of technique "map": a shadow map per light (lecture 000, 002
/// §8.2-8.4, 004), the block `lights[i].shadow.map` of a scene file.
/// Directional lights get an orthographic light camera (or cascades of
/// them), spot lights a perspective one, point lights a cube map.
/// Every field's JSON key, unit, range and default is in its OptionTable
/// (mapOptionTable(), and docs/scene-format.md).
#include <shadowlab/Export.h>
#include <shadowlab/Options.h>

#include <string>
#include <vector>

namespace shadowlab {

enum class MapFormat {
    Depth16,  ///< "depth16": DEPTH_COMPONENT16
    Depth24,  ///< "depth24": DEPTH_COMPONENT24
    Depth32F, ///< "depth32f": DEPTH_COMPONENT32F (default)
    Rgba8,    ///< "rgba8": depth packed into an RGBA8 colour target (002 §8.3.1), compared in the shader
    R8,       ///< "r8": 8 bits of depth (rounded up) in an R8 colour target: enough when every caster is nearer the light than what it shadows (002 exercise 8.6.2-1, variation 2)
};

enum class MapFit {
    Tight, ///< "tight": the casters that can shadow what the camera sees (default)
    Scene, ///< "scene": the lecture's box around the whole scene (directional) / the whole cone (spot)
    Sdsm,  ///< "sdsm": directional lights: the tight fit around the receiver points the camera sees, reduced on the GPU from a depth pre-pass of the same frame (Lauritzen's sample distribution shadow maps)
};

enum class MapWarp {
    None,   ///< "none": the light camera as fitted (default)
    Lispsm, ///< "lispsm": directional lights, one map: the fitted box warped by a perspective along the view (light space perspective shadow maps, Wimmer et al. 2004), more texels near the camera
};

enum class MapFilter {
    None,     ///< "none": one nearest sample
    Hardware, ///< "hardware": one 2x2 bilinear hardware compare (default)
    Grid,     ///< "grid": kernel x kernel samples (the lecture's PCF, up to 64)
    Dither4,  ///< "dither4": the lecture's 4-sample dithered PCF (000)
    Poisson,  ///< "poisson": a rotated Vogel disk of `samples` taps within `radius` texels (point lights: within `diskRadius`, across the light's ray)
    Pcf20,    ///< "pcf20": point lights only: the lecture's 20 offset directions times `diskRadius` (001)
    Pcss,     ///< "pcss": percentage-closer soft shadows (Fernando 2005) for the light's `size`: a blocker search of `blockerSamples` taps, then `samples` taps over the penumbra it predicts
    Box,      ///< "box": four bilinear hardware compares half a texel from the point, a tent over 3x3 texels (point lights: eight at the corners of a cube of side one texel)
};

enum class MapGridTaps {
    Auto,     ///< "auto": nearest on a software rasteriser (llvmpipe ...), bilinear on a GPU (default)
    Bilinear, ///< "bilinear": ceil(kernel/2)^2 bilinear hardware compares
    Nearest,  ///< "nearest": kernel^2 nearest compares
};

enum class MapPreset {
    Default,     ///< "default": the fields as given
    Lecture,     ///< "lecture": lecture 000's polygon offset (2, 4), dithered PCF, no normal offset
    LearnOpenGL, ///< "learnopengl": LearnOpenGL 5.advanced_lighting/3.1.3's 1024^2, ortho camera and slope bias (point: 3.2.2's cube)
    Lecture000,  ///< "lecture-000": point lights: lecture 000's one 60-degree map towards the origin instead of a cube
};

enum class MapRepresentation {
    Depth, ///< "depth": the nearest depth, compared per tap (default)
    Vsm,   ///< "vsm": variance shadow maps, two moments of depth, Chebyshev's bound (Donnelly and Lauritzen 2006)
    Evsm2, ///< "evsm2": exponential VSM, the positive exponential warp's two moments (Lauritzen and McCool 2008)
    Evsm4, ///< "evsm4": exponential VSM with both warps, four moments
    Msm,   ///< "msm": moment shadow maps, four moments of depth, Hamburger's bound (Peters and Klein 2015)
};

enum class MapMomentFormat {
    Rgba32f, ///< "rgba32f": 32-bit float moments (default)
    Rgba16f, ///< "rgba16f": 16-bit float moments: half the memory and bandwidth, more light bleeding; EVSM's exponents drop to 5.54
};

enum class MapCubePasses {
    One, ///< "one": each caster drawn once, a geometry shader sends each triangle to the faces it touches (default)
    Six, ///< "six": one pass per face, the face attached as the target
};

struct MapOptions {
    static constexpr const char* kTechnique = "map";
    /// texels per side of the map (a cube: of each face), 16..16384; 0
    /// (the default): follows the frame, kFrameMapMinimum or
    /// kFrameMapTexelsPerPixel texels per pixel of the frame's larger side,
    /// whichever is more (rounded up to a multiple of 16), at most
    /// kFrameMapMaximum and the GPU's limit: 768 up to 800 pixels across,
    /// 1856 at 1920x1080 (preset "lecture" on a 2D map: the frame's larger side)
    int size = 0;
    MapFormat format = MapFormat::Depth32F;
    MapFit fit = MapFit::Tight;
    MapWarp warp = MapWarp::None;
    float warpNear = 1.0f;               ///< lispsm: the view distance (scene units) below which the warp gives no more texels, like Filament's near hint; 0.01..1000, default 1
    MapFilter filter = MapFilter::Hardware;
    int kernel = 3;                      ///< grid: samples per side, 2..8; default 3
    /// grid (nearest taps, 2D maps) and pcf20: the kernel's corners first (with
    /// an odd grid's centre), and where they all agree the taps between them
    /// are skipped; pcss: where every blocker tap finds a blocker and the
    /// filter's disk lies inside their hull, the filter is skipped (umbra).
    /// The answer differs from every tap's only where a caster's edge bends
    /// or ends between agreeing taps. false: every tap, every pixel. Default true
    bool earlyOut = true;
    MapGridTaps gridTaps = MapGridTaps::Auto; ///< grid: how the kernel^2 comparisons are fetched (same result); default auto
    int samples = 16;                    ///< poisson and pcss: filter taps, 4..64; default 16
    int blockerSamples = 16;             ///< pcss: blocker-search taps, 4..64; default 16
    float radius = 1.5f;                 ///< poisson: disk radius, texels; default 1.5
    float constantBias = 0.0f;           ///< light-space depth, shadow-map texels of the light's depth range; default 0
    float slopeBias = 1.5f;              ///< glPolygonOffset factor in the shadow pass; default 1.5
    float offsetUnits = 8.0f;            ///< glPolygonOffset units in the shadow pass; default 8
    float normalBias = 1.0f;             ///< receiver moved along its normal by this many map texels (world size) times (1 - N.L); default 1
    bool cullFront = false;              ///< draw back faces only into the map (closed meshes; 002 §8.4.1.1); default false
    /// Every map but the atlas's and fit sdsm's: a dense caster (4096
    /// triangles or more) is drawn from the coarsest simplified level
    /// of its mesh whose surface lies within this many of the map's texels
    /// (their world size at the caster) of the mesh's, pushed that far away
    /// from the light; 0: every caster's own triangles; 0..4 texels, default
    /// 0.5 (its shadow's outline moves by at most a texel, the map's own
    /// resolution; docs/techniques.md)
    float lodTexels = 0.5f;
    float shadowedLight = 0.0f;          ///< share of the light's diffuse and specular a shadowed point keeps (a look; compare judges the test); default 0
    bool mipmaps = false;                ///< mipmap the map and sample it with mipmapping (002 exercise 8.6.1-4); default false
    /// A set of option defaults (docs/techniques.md): every field the scene
    /// does not write takes the preset's value. Scene files, `--set` and
    /// `bench --vary` resolve it as they are read (withPreset); code that
    /// sets it on MapOptions itself calls withPreset. Default "default"
    MapPreset preset = MapPreset::Default;
    // Directional lights: cascaded shadow maps (one layer per cascade).
    int cascades = 1;                    ///< maps along the view, 1..8 (1: one map over the whole view); default 1
    float cascadeLambda = 0.75f;         ///< the splits: 0 uniform .. 1 logarithmic (the practical scheme); default 0.75
    std::string cascadeSplits;           ///< explicit far distances of the first cascades - 1 slices, scene units along the view, e.g. "4 15 50"; default "" (cascadeLambda's scheme)
    bool stabilize = true;               ///< cascades: a sphere per slice snapped to whole texels, so shadows do not shimmer as the camera moves (false: each slice fitted tightly); default true
    float cascadeBlend = 0.1f;           ///< cascades: share of each slice, at its far end, over which it fades into the next; default 0.1
    // Directional and spot lights: filterable maps.
    MapRepresentation representation = MapRepresentation::Depth;
    MapMomentFormat momentFormat = MapMomentFormat::Rgba32f;
    int blur = 0;                        ///< moments: separable Gaussian blur, texels each side (sigma = blur / 2), 0..16; default 0 (none: the bilinear lookup alone, faster and no less accurate against hard shadows; docs/techniques.md)
    float bleedReduction = 0.0f;         ///< moments: light-bleeding reduction, the bound's values below this count as 0 (rescaled above), 0..0.9; default 0
    // Point lights (cube maps) only.
    MapCubePasses cubePasses = MapCubePasses::One;
    bool faceCulling = true;             ///< draw a caster only into the faces it can touch (false: all six, as LearnOpenGL does); default true
    float diskRadius = 0.04f;            ///< point-light grid, pcf20 and poisson: filter radius at the fragment, world units; default 0.04 (1/25, 001)
    float diskGrowth = 1.0f;             ///< the radius grows by this times (viewer distance / far); default 1 (001: (1 + d/far)/25)
    /// Spot and point lights: the map is a tile (a point light's faces six
    /// tiles) of the scene's shared shadow atlas (Scene::shadowAtlas), sized
    /// each frame from the light's reach on screen, and the light is shaded in
    /// the one pass over the tiled light list; default false
    bool atlas = false;
};

/// MapOptions::size 0: the map's side for a frame of `width` x `height` pixels.
inline constexpr int kFrameMapMinimum = 768;             ///< texels: the least side that follows the frame (what 800x600 takes)
inline constexpr float kFrameMapTexelsPerPixel = 0.96f;  ///< texels per pixel of the frame's larger side (768 at 800)
inline constexpr int kFrameMapMaximum = 4096;            ///< texels: the most (a 4096^2 depth32f map is 64 MiB; a cube six times that)
SHADOWLAB_API int frameMapSize(int width, int height);

/// `o` with its preset's values in every field whose JSON key is not in
/// `written` (the keys the scene gave, `--set` included): a preset is a set
/// of option defaults under the user's keys. `pointLight`: the light is a
/// point light (lecture 001's and LearnOpenGL's cube presets). Preset
/// "default" changes nothing.
SHADOWLAB_API MapOptions withPreset(const MapOptions& o, bool pointLight, const std::vector<std::string>& written = {});

/// The options table of "map" (JSON keys, units, ranges, defaults, docs).
SHADOWLAB_API const OptionTable& mapOptionTable();

} // namespace shadowlab
