#pragma once
// Technique "map": its shader variants as typed values. Each program the
// technique compiles is described by one of these; defines() turns it into
// the `#define` lines its GLSL tests, in this one place (Variants.cpp,
// which also checks at compile time that the enums agree with the GLSL
// values in shaders/shadow_map_shared.h). Everything else, the kernel's
// radius, the taps, the biases, is a uniform (MapBlock).
#include <shadowlab/MapOptions.h>
#include <shadowlab/Scene.h>

#include <string>

namespace shadowlab::map {

/// The light pass: shadow_map.glsl and shadow_map_vertex.glsl, per light.
struct LightPassVariant {
    MapFilter filter = MapFilter::Hardware;
    int kernel = 3;                 ///< grid: taps per side (a loop bound)
    MapFormat format = MapFormat::Depth32F;
    bool gridBilinear = false;      ///< grid: the taps from bilinear compares (MapSettings: bilinearGrid)
    bool cube = false;              ///< a point light's cube map
    int cascades = 1;               ///< directional lights: cascaded maps, 1..SL_MAP_MAX_CASCADES
    MapRepresentation representation = MapRepresentation::Depth;  ///< Depth for cubes
    MapMomentFormat momentFormat = MapMomentFormat::Rgba32f;
    /// The frame has translucent casters: the test reads the transmittance
    /// layers too. Only then: a software rasteriser runs both sides of a
    /// branch, so an unused lookup still costs (llvmpipe: 0.9 ms at 800x600).
    bool transmittance = false;
    bool plainFetch = false;        ///< nearest depths fetched and compared in the shader (MapSettings: plainFetch)
    /// pcss on a software rasteriser: its filter taps are nearest depths
    /// compared in the shader, not bilinear compares (llvmpipe does those
    /// four compares in software: 2.6 ms of a 16 ms frame for 16 taps at
    /// 800x600; RMSE against the area light 0.0250 against 0.0245). A GPU
    /// keeps the bilinear compare.
    bool pcssNearest = false;
    /// pcss (a depth map, not the atlas's): the blocker search shared by the
    /// 2x2 pixels of a quad, each fetching every fourth of its taps, the
    /// sums exchanged through fine derivatives (shadow_map_filter_pcss.glsl);
    /// the light pass runs the test before any branch or discard, where the
    /// quad's fragments all run (lighting.frag: SHADOW_QUAD_UNIFORM)
    bool quadShared = false;
    /// grid and pcf20: the corners first, the rest skipped where they agree (MapSettings: kernelRounds)
    bool earlyOut = false;
    /// warp lispsm: the offsets take the warped texel's size per point (a
    /// define, so that unwarped maps do not pay for it on llvmpipe)
    bool warped = false;
    /// cascades fitted on the CPU and not warped: they share one light view,
    /// each only scaled and offset from the first, so the point and its
    /// offsets go to the first cascade's texture space per vertex and each
    /// cascade's coordinates come from there by a scale and an offset
    /// (MapBlock: cascadeScale; llvmpipe: about half the lookup's cost)
    bool cascadeAxes = false;
    /// atlas: the light's tiles of the shadow atlas (shadow_map_atlas.glsl), not a map of its own
    bool atlas = false;
    /// A preset's own bias in place of the normal and receiver-plane
    /// offsets: LearnOpenGL's slope-scaled depth bias on a 2D map (with N.L
    /// from the vertex), a cube's constant bias alone. A define, so that the
    /// default maps carry neither the code nor the varying (llvmpipe: 0.2-0.3
    /// ms of an 800x600 frame's lookups).
    bool presetBias = false;
    /// The map through a 2D view of its layer (MapSettings: layerView)
    bool layerView = false;
    /// A mipmapped depth map (2D): the normal and receiver-plane offsets
    /// scaled per fragment to the texel of the level the lookup reads
    /// (2^level texels of level 0), against the acne of averaged depths
    bool mipmaps = false;
    bool outsideRepeat = false;       ///< outside "repeat": the map tiled, past its far plane compared as it is
    /// A perspective 2D map (a spot's): the receiver-plane offset handed on
    /// as a change of the texture-space depth, which keeps each point's ray
    /// to the light; moved along a vertex's ray and interpolated across a
    /// large triangle, the point slid across the map (shadow_map_vertex.glsl)
    bool rayDepthOffset = false;
    /// A moment map whose moments the light pass takes from the depth
    /// (passes/Arrays.h: momentsFromDepth), not from a texture of moments
    bool momentsFromDepth = false;
    /// The variant of `light` with options `o` (MapLight::options);
    /// `softwareRasterizer` picks the grid's taps; `translucentCasters`,
    /// whether the frame has any.
    static LightPassVariant of(const MapOptions& o, const Light& light, bool softwareRasterizer, bool translucentCasters);
    std::string defines() const;
    /// shadow_map.glsl's "@map_filter" slot: the filter's kernel file, or the moments'.
    std::string kernelFile() const;
};

/// The floor of the light pass's lookups: shadow_map_lookup_floor.vert/.frag
/// (MapFloors::drawLookup), with one nearest fetch a pixel or without it,
/// from a 2D map or a cube.
struct LookupFloorVariant {
    bool fetch = false;
    bool cube = false;
    std::string defines() const;
};

/// The 2D shadow pass: shadow_map_depth.vert/.frag (the floors' bare draw: the defaults).
/// Moment maps are drawn as depth32f (their moments made after: BlurVariant).
struct DepthPassVariant {
    MapFormat format = MapFormat::Depth32F;
    /// The casters it draws have holes (alphaMode mask) to cut: the fragment
    /// stage tests their alpha (passes/CasterDraw.h; opaque casters: no test)
    bool holes = false;
    std::string defines() const;
};

/// The cube pass: shadow_map_cube.vert/.geom/.frag.
struct CubePassVariant {
    MapFormat format = MapFormat::Depth32F;
    bool onePass = true;            ///< the geometry shader picks the faces (else one draw per face)
    bool faceCulling = true;        ///< one pass: each triangle only to the faces it touches
    bool windowDepth = false;       ///< the reversed window depth, not gl_FragDepth (MapSettings: cubeWindowDepth)
    bool holes = false;             ///< the casters have holes to cut (DepthPassVariant::holes)
    std::string defines() const;
};

/// The translucent casters' pass: shadow_map_transmit.frag (2D; a cube's
/// faces take CubePassVariant{.onePass = false}'s vertex stage). It has no
/// choices: a spot's map is drawn whole, like a directional light's.
struct TranslucentVariant {
    std::string defines() const;
};

/// The views of the frame coloured per light (shadow_map_density.frag, shadow_map_cascades.frag).
struct FrameViewVariant {
    int cascades = 1;
    bool cube = false;  ///< a point light's cube: the face a direction samples
    std::string defines() const;
};

/// The moments and their blur: shadow_map_blur.frag, across from the depth
/// layer (the moments made per tap) or down from the scratch.
struct BlurVariant {
    bool fromDepth = true;
    int radius = 1;  ///< BLUR_RADIUS: taps -radius .. radius (0: the moments alone), weights folded at compile time
    bool spot = false;  ///< fromDepth: a spot's depth linearised first
    MapRepresentation representation = MapRepresentation::Vsm;  ///< fromDepth: the moments made
    MapMomentFormat momentFormat = MapMomentFormat::Rgba32f;
    std::string defines() const;
};

} // namespace shadowlab::map
