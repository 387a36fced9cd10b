#pragma once
// Technique "map": what follows from a light's options alone, with no GL:
// the kind of map it gets, its preset cameras, the filter's footprint and
// reach, cascadeSplits' values. The options are the ones the technique
// resolved for the frame (MapLight::options: the preset applied as the
// scene was read, size 0 resolved in ShadowMap::prepare); nothing here
// reads them from the light.
#include "geometry/LightCamera.h"

#include <shadowlab/MapOptions.h>
#include <shadowlab/Scene.h>

#include <string>
#include <utility>
#include <vector>

namespace shadowlab::map {

/// A point light's map is a cube unless preset lecture-000 asks for 000's single map.
bool isCube(const MapOptions& o, const Light& light);
/// Wolberg's 2D settings (the window-sized map, the dither spread).
bool isLecture2D(const MapOptions& o, const Light& light);
/// Whether the light pass takes a preset's own bias in place of the normal
/// and receiver-plane offsets: LearnOpenGL's slope-scaled depth bias on a
/// 2D map, any preset's constant bias alone on a cube (MapBlock's values,
/// LightPassVariant::presetBias).
bool usesPresetBias(const MapOptions& o, bool cube);
/// The presets' fixed near and far planes for a cube (Lawonn and LearnOpenGL: 1 and 25); 0: fitted.
std::pair<float, float> cubeNearFar(const MapOptions& o);
/// Every field `o`'s preset sets, set to the preset's value (withPreset
/// keeps the fields the scene wrote); preset "default": `o` itself.
MapOptions presetValues(MapOptions o, bool pointLight);
/// The maps of a directional light's cascades (1 for any other light).
int cascadeCount(const Light& light, const MapOptions& o);
/// cascadeSplits' distances; `problem` says what is wrong with them, if anything.
std::vector<float> parseSplits(const MapOptions& o, std::string& problem);

/// Whether the map is depth packed into a colour target (rgba8's four
/// base-255 digits, or r8's one), compared in the shader.
bool isPacked(MapFormat f);
/// Whether a point light's cube stores the faces' window depth as
/// rasterised, reversed (near 1, far 0; glClipControl 0..1), with the slope
/// bias a polygon offset, rather than distance / far written as
/// gl_FragDepth. Writing gl_FragDepth costs the rasteriser's depth-only
/// path (llvmpipe: 1.5-2.2 ms of a 4.5 ms pass at 1024^2), but each tap
/// must then turn its reference into the window depth of its direction
/// (llvmpipe: 1.8 ms more for pcf20's 20 taps at 800x600, 5.5 ms for
/// pcss's 32). So: depth32f (its float keeps the reversed depth's precision
/// at every distance; depth16 and depth24 keep distance / far, their
/// fixed-point steps being even over it) with the one-tap filters, none and
/// hardware (the default).
bool cubeWindowDepth(MapFormat f, MapFilter filter);
inline bool cubeWindowDepth(const MapOptions& o) { return cubeWindowDepth(o.format, o.filter); }

/// Whether the grid filter takes its comparisons from bilinear compares
/// (gridTaps; auto: not on a software rasteriser, which compares four
/// texels for a bilinear fetch, so that the nearest fetches are faster).
bool bilinearGrid(const MapOptions& o, bool softwareRasterizer);

/// How the light pass's taps read a depth map (2D or cube): the one place
/// its sampler is chosen (lookup/Bindings.cpp binds it, Variants.h's
/// MAP_PLAIN_FETCH follows it).
enum class DepthTaps {
    Nearest, ///< a comparison sampler, nearest
    Linear,  ///< a comparison sampler, bilinear (the filter's table: linear2D, linearCube)
    /// The nearest stored depth fetched with an explicit level and compared
    /// in the shader: on a software rasteriser, for a depth32f map without
    /// mipmaps whose filter takes nearest taps (llvmpipe's comparison
    /// sampler costs more than the fetch and the compare; a GPU keeps the
    /// hardware compare). Gives the same result: a 32-bit float compared the
    /// same way, the same border.
    Plain,
};
DepthTaps depthTaps(const MapOptions& o, bool cube, bool softwareRasterizer);
inline bool plainFetch(const MapOptions& o, bool cube, bool softwareRasterizer) { return depthTaps(o, cube, softwareRasterizer) == DepthTaps::Plain; }
/// Whether the light pass samples a view of the light's own layers rather
/// than the depth array (MAP_LAYER_VIEW): one 2D map of depth (not
/// cascades or moments) as a 2D texture; a cube's six layers as a cube map
/// for its multi-tap filters (pcf20, grid, poisson, pcss); not the atlas, a
/// packed colour or mipmaps. The same texels either way; on llvmpipe a 2D
/// texture's taps cost less than an array layer's (learnopengl-shadow-
/// mapping's lookup 2.40 against 2.15-2.22 ms), and a cube's nearest and
/// raw taps less than a cube array's (penumbra-step's pcss 16.1-16.4
/// against 15.0-15.9 ms), while its one bilinear compare (none, hardware)
/// came out no faster (four-spheres-point 3.95-4.20 against 4.15-4.43 ms).
bool layerView(const MapOptions& o, bool cube, int cascades);

/// The filter's early out (MapOptions::earlyOut): how many rounds of four
/// taps its kernel takes after the first taps, 0 when it takes every tap
/// in one go. grid on a 2D map (kernel >= 3; its nearest taps only: see
/// earlyOut below): the odd
/// kernel's centre, then rounds of four from the corners (kernel^2 - 4,
/// less the centre, is a multiple of four); pcf20: five (the cube's eight
/// corners, then its twelve edge midpoints). The light pass stops after
/// the corners' round where they all agree. A loop bound from the block,
/// not a constant: a compiler unrolls a constant loop, and an unrolled
/// loop cannot stop early (llvmpipe runs a stopped branch's taps anyway).
int kernelRounds(const MapOptions& o, bool cube);
/// Whether the light pass takes the early out: pcss (its umbra: below), or
/// kernelRounds > 0 and a grid's taps nearest ones (bilinear pairs keep
/// every tap).
bool earlyOut(const MapOptions& o, bool cube, bool softwareRasterizer);

/// The Vogel disk of n taps (shaders/shadow_map_sampling.glsl): the radius,
/// as a share of the disk's, of the largest circle about the centre inside
/// the taps' convex hull (0 when the centre is not inside it). The same for
/// every rotation of the disk. pcss's early out: where every blocker tap
/// finds a blocker and the filter's disk lies within this circle of the
/// search's, a straight-edged caster covers every filter tap too (they
/// compare against the same receiver plane), so the filter is skipped.
float vogelHullInradius(int n);

/// Texels around the fitted region that the filter may read.
float footprint(const MapOptions& o);
/// Texels around a receiver's image in a 2D map that its lookup may read:
/// the filter's footprint (what it may read around the point), the normal
/// offset's reach (normalBias texels at most), and two for the rounding of
/// a box's corners and the rasteriser's coverage (a depth map's filters).
float marginTexels(const MapOptions& o);
/// Texels from a filter's centre to its farthest tap (the receiver-plane
/// bias covers that distance; the presets keep their own biases instead).
float reach(const MapOptions& o);

/// LearnOpenGL's light camera for a directional light.
LightCamera learnOpenGlCamera(const Light& light, int size);
/// Wolberg's camera for its point light: one map towards the origin.
LightCamera lecturePointCamera(const Light& light, int size);

} // namespace shadowlab::map
