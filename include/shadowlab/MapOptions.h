#pragma once
/// @file MapOptions.h
/// Options of technique "map": a shadow map per light (Wolberg; Ganovelli et al.
/// §8.2-8.4; Navarro Rosales), the block `lights[i].shadow.map` of a scene file.
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
    Rgba8,    ///< "rgba8": depth packed into an RGBA8 colour target (Ganovelli et al. §8.3.1), compared in the shader
    R8,       ///< "r8": 8 bits of depth (rounded up) in an R8 colour target: enough when every caster is nearer the light than what it shadows (Ganovelli et al. exercise 8.6.2-1, variation 2)
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
    Grid,     ///< "grid": kernel x kernel samples (the lectures' PCF, up to 64; "pcf" is its alias)
    Dither4,  ///< "dither4": Wolberg's 4-sample dithered PCF
    Poisson,  ///< "poisson": a rotated Vogel disk of `samples` taps within `radius` texels (point lights: within `diskRadius`, across the light's ray)
    Pcf20,    ///< "pcf20": point lights only: Lawonn's 20 offset directions times `diskRadius`
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
    Lecture,     ///< "lecture": Wolberg's polygon offset (2, 4), dithered PCF, no normal offset
    LearnOpenGL, ///< "learnopengl": LearnOpenGL 5.advanced_lighting/3.1.3's 1024^2, ortho camera and slope bias (point: 3.2.2's cube)
    Lecture000,  ///< "lecture-000": point lights: Wolberg's one 60-degree map towards the origin instead of a cube
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

enum class MapOutside {
    Lit,    ///< "lit": a receiver outside the map's box or past its far plane is lit (default)
    Repeat, ///< "repeat": the map read as if tiled and points past its far plane shadowed (LearnOpenGL's over-sampling, before its fix)
};

enum class MapCubePasses {
    One, ///< "one": each caster drawn once, a geometry shader sends each triangle to the faces it touches (default)
    Six, ///< "six": one pass per face, the face attached as the target
};

/// Technique "map"'s options. What each one does, its range and its
/// default are documented once, in the options table (map/options/OptionTable.cpp:
/// `shadowlab techniques`, docs/techniques/map.md); a field's comment here
/// gives its unit and default only.
struct MapOptions {
    static constexpr const char* kTechnique = "map";
    int size = 0;                        ///< texels per side; default 0 (follows the frame: frameMapSize)
    MapFormat format = MapFormat::Depth32F;
    MapFit fit = MapFit::Tight;
    MapWarp warp = MapWarp::None;
    float warpNear = 1.0f;               ///< scene units; default 1
    MapFilter filter = MapFilter::Hardware;
    int kernel = 3;                      ///< taps per side; default 3
    bool earlyOut = true;                ///< default true
    MapGridTaps gridTaps = MapGridTaps::Auto;
    int samples = 16;                    ///< taps; default 16
    int blockerSamples = 16;             ///< taps; default 16
    float radius = 1.5f;                 ///< texels; default 1.5
    float constantBias = 0.0f;           ///< share of the map's depth range; default 0
    float slopeBias = 1.5f;              ///< polygon offset factor; default 1.5
    float offsetUnits = 8.0f;            ///< polygon offset units; default 8
    float normalBias = 1.0f;             ///< map texels; default 1
    bool cullFront = false;              ///< default false
    float lodTexels = 0.5f;              ///< map texels; default 0.5
    float shadowedLight = 0.0f;          ///< share of the light; default 0
    bool mipmaps = false;                ///< default false
    MapOutside outside = MapOutside::Lit;
    /// Default "default". Scene files, `--set` and `bench --vary` resolve
    /// it as they are read; code that sets it on MapOptions itself calls withPreset.
    MapPreset preset = MapPreset::Default;
    // Directional lights: cascaded shadow maps.
    int cascades = 1;                    ///< maps along the view; default 1
    float cascadeLambda = 0.75f;         ///< 0 uniform .. 1 logarithmic; default 0.75
    std::string cascadeSplits;           ///< scene units along the view, e.g. "4 15 50"; default ""
    bool stabilize = true;               ///< default true
    float cascadeBlend = 0.1f;           ///< share of a slice; default 0.1
    // Directional and spot lights: filterable maps.
    MapRepresentation representation = MapRepresentation::Depth;
    MapMomentFormat momentFormat = MapMomentFormat::Rgba32f;
    int blur = 0;                        ///< texels each side; default 0
    float bleedReduction = 0.0f;         ///< share of the bound; default 0
    // Point lights (cube maps) only.
    MapCubePasses cubePasses = MapCubePasses::One;
    bool faceCulling = true;             ///< default true
    float diskRadius = 0.04f;            ///< scene units at the fragment; default 0.04
    float diskGrowth = 1.0f;             ///< times viewer distance / far; default 1
    // Spot and point lights: a tile of the scene's shadow atlas (Scene::shadowAtlas).
    bool atlas = false;                  ///< default false
};

/// MapOptions::size 0: the map's side for a frame of `width` x `height` pixels.
inline constexpr int kFrameMapMinimum = 768;             ///< texels: the least side that follows the frame (what 800x600 takes)
inline constexpr float kFrameMapTexelsPerPixel = 0.96f;  ///< texels per pixel of the frame's larger side (768 at 800)
inline constexpr int kFrameMapMaximum = 4096;            ///< texels: the most (a 4096^2 depth32f map is 64 MiB; a cube six times that)
SHADOWLAB_API int frameMapSize(int width, int height);

/// `o` with its preset's values in every field whose JSON key is not in
/// `written` (the keys the scene gave, `--set` included): a preset is a set
/// of option defaults under the user's keys. `pointLight`: the light is a
/// point light (Lawonn's and LearnOpenGL's cube presets). Preset
/// "default" changes nothing.
SHADOWLAB_API MapOptions withPreset(const MapOptions& o, bool pointLight, const std::vector<std::string>& written = {});

/// The options table of "map" (JSON keys, units, ranges, defaults, docs).
SHADOWLAB_API const OptionTable& mapOptionTable();

} // namespace shadowlab
