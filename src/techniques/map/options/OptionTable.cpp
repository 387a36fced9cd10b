// Technique "map": its options table (include/shadowlab/MapOptions.h), the
// combinations of options it refuses, with the reason, and what the
// registry asks of them (options/OptionTable.h).
#include "techniques/map/options/OptionTable.h"

#include "techniques/Kinds.h"
#include "techniques/map/options/Applies.h"

#include "techniques/map/options/Filters.h"
#include "techniques/map/options/Settings.h"

#include <shadowlab/Text.h>

#include <algorithm>

namespace shadowlab {

namespace map {
namespace {

// The "filter" row's names and doc, from the filters' table.
std::vector<std::string> filterNames() {
    std::vector<std::string> names;
    for (const FilterInfo& f : filters()) names.emplace_back(f.name);
    return names;
}
std::string filterDoc() {
    std::string doc;
    for (const FilterInfo& f : filters()) doc += (doc.empty() ? "" : "; ") + std::string(f.doc);
    return doc;
}

} // namespace
} // namespace map

const OptionTable& mapOptionTable() {
    static const OptionTable table =
        OptionTableFor<MapOptions>("map")
            .integer(&MapOptions::size, "size", 0, 16384, "texels",
                     "side of the square shadow map (a cube map: of each face), 16..16384; 0 (the default): follows the frame, 0.96 texels per pixel of its larger side, at least 768 and at most 4096; with fit scene, times how much wider the scene's box is than the tight fit's, in steps of 256, at most 4096 (docs/techniques/map.md)")
            .choice(&MapOptions::format, "format", {"depth16", "depth24", "depth32f", "rgba8", "r8"},
                    "depth texture format; rgba8 packs depth into colour (Ganovelli et al. §8.3.1); r8 keeps 8 bits of depth, enough only when every caster is nearer the light than what it shadows (Ganovelli et al. exercise 8.6.2-1, variation 2)")
            .choice(&MapOptions::fit, "fit", {"tight", "scene", "sdsm"},
                    "light camera: around what the viewer may see (receivers' boxes in the view) and the casters over it; around the whole scene; sdsm (directional lights): around the points the viewer does see, reduced from a depth pre-pass of the frame; with cascades, the first slice starts at the nearest depth it sees and the last ends at the farthest, and slices not stabilised are each fitted to the points seen in them (docs/techniques/fits.md)")
            .choice(&MapOptions::warp, "warp", {"none", "lispsm"},
                    "directional lights (one map, or cascades with stabilize false): none; lispsm, the fitted box warped by a perspective along the view (light space perspective shadow maps), more texels near the camera and fewer far away; a light along the view gets no warp (docs/techniques/fits.md)")
            .number(&MapOptions::warpNear, "warpNear", 0.01, 1000.0, "scene units",
                    "warp lispsm: the view distance below which the warp gives no more texels (the warp's near plane stands for max(warpNear, the nearest receiver seen)); larger: a milder warp")
            .choice(&MapOptions::filter, "filter", map::filterNames(), map::filterDoc())
            .alias("pcf", "grid", {{"kernel", 8.0}}, "the lectures' PCF: grid with 64 taps, kernel 8 or a cube's 4 unless given")
            .integer(&MapOptions::kernel, "kernel", 2, 8, "taps per side", "grid filter: kernel x kernel taps one texel apart")
            .choice(&MapOptions::gridTaps, "gridTaps", {"auto", "bilinear", "nearest"},
                    "grid filter: the same comparisons from ceil(kernel/2)^2 bilinear or kernel^2 nearest fetches; auto: nearest on a software rasteriser")
            .boolean(&MapOptions::earlyOut, "earlyOut",
                     "grid (nearest taps, 2D maps) and pcf20 filters: the kernel's corners first (and an odd grid's centre), and where they all agree the taps between them are skipped; pcss: where every blocker tap finds a blocker and the filter's disk lies inside their hull, the filter is skipped; either differs from taking every tap only where a caster's edge bends or ends between agreeing taps; false: every tap (docs/techniques/map.md)")
            .integer(&MapOptions::samples, "samples", 4, 64, "taps", "poisson and pcss filters: taps on the disk")
            .integer(&MapOptions::blockerSamples, "blockerSamples", 4, 64, "taps", "pcss filter: taps of the blocker search, shared by each 2x2 quad of pixels (each fetches every fourth; docs/techniques/pcss.md)")
            .number(&MapOptions::radius, "radius", 0.0, 32.0, "texels", "poisson filter: disk radius")
            .number(&MapOptions::constantBias, "constantBias", 0.0, 0.1, "depth (0..1)", "subtracted from the receiver's map depth")
            .number(&MapOptions::slopeBias, "slopeBias", 0.0, 16.0, "polygon offset factor", "shadow pass: depth offset per unit of depth slope")
            .number(&MapOptions::offsetUnits, "offsetUnits", 0.0, 1024.0, "polygon offset units", "shadow pass: constant depth offset in the format's smallest steps")
            .number(&MapOptions::normalBias, "normalBias", 0.0, 16.0, "texels",
                    "receiver moved along its normal by this many map texels (their world size) times 1 - N.L")
            .boolean(&MapOptions::cullFront, "cullFront", "shadow pass draws closed casters' back faces only, without the polygon offset (slopeBias, offsetUnits), which would lift them off the receivers at their foot; open casters (a plane, a ceiling) have no back face and are drawn whole, with the offset (Ganovelli et al. §8.4.1.1)")
            .number(&MapOptions::lodTexels, "lodTexels", 0.0, 4.0, "texels",
                    "a dense caster (4096 triangles or more) is drawn into the map (a cube's faces too) from the coarsest simplified level of its mesh whose surface lies within this many map texels of the mesh's, pushed that far away from the light; 0: every triangle; not in the shadow atlas or with fit sdsm (docs/techniques/map.md)")
            .number(&MapOptions::shadowedLight, "shadowedLight", 0.0, 1.0, "share of the light",
                    "what a shadowed point keeps of the light (Ganovelli et al. listing 8.4: 0.6); compare judges the shadow test, not this look")
            .boolean(&MapOptions::mipmaps, "mipmaps", "mipmap the map and compare at the pixel's level (Ganovelli et al. exercise 8.6.1-4; docs/techniques/map.md says what it does)")
            .choice(&MapOptions::outside, "outside", {"lit", "repeat"},
                    "directional and spot lights, one map: what a receiver outside the map gets; lit: outside its box and past its far plane, lit (LearnOpenGL's fix for over-sampling: a border of 1 and depths past 1 lit); repeat: the map read as if tiled and points past its far plane shadowed, as before that fix (de Vries, Shadow Mapping)")
            .choice(&MapOptions::preset, "preset", {"default", "lecture", "learnopengl", "lecture-000"},
                    "the lecture's or LearnOpenGL's settings as the defaults of every option the scene does not write (docs/techniques/map.md); lecture-000: a point light through Wolberg's one 60-degree map")
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
                    "moments: 32- or 16-bit floats; 16-bit moments are stored (a fullscreen pass makes them), while 32-bit ones with no blur and no mipmaps are taken from the depth by the light pass and take no memory of their own; 16 bits hold on scenes a few metres across and less well on large ones (docs/techniques/moments.md)")
            .integer(&MapOptions::blur, "blur", 0, 16, "texels each side", "moments: separable Gaussian blur of sigma blur / 2 texels before the light pass; 0 by default (none: the bilinear lookup's one-texel edge); more for wider soft edges (docs/techniques/moments.md)")
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
            .boolean(&MapOptions::atlas, "atlas",
                     "spot and point lights: the map is a tile of the scene's shared shadow atlas (a point light's faces, six tiles), sized each frame from the light's reach on screen (the scene's shadowAtlas), and the light is shaded with the other such lights in one pass over the clustered light list; format depth32f, filter none or hardware (docs/techniques/atlas.md)")
            .build();
    return table;
}

namespace map {

std::string unsupported(const Light& light) {
    const MapOptions& o = light.shadow.get<MapOptions>();
    if (o.size > 0 && o.size < 16) return "map: size: expected 0 (follow the frame) or 16..16384 texels, got " + std::to_string(o.size);
    if (isCube(o, light)) {
        if (o.filter == MapFilter::Dither4)
            return std::string("map: filter \"dither4\" is for 2D maps (directional and spot lights); a point light's cube takes none, hardware, grid, poisson or pcf20");
        if (o.mipmaps) return std::string("map: mipmaps are for 2D maps (directional and spot lights), not a point light's cube");
        if (o.representation != MapRepresentation::Depth)
            return std::string("map: representation \"vsm\", \"evsm2\", \"evsm4\" and \"msm\" are for 2D maps (directional and spot lights), not a point light's cube");
    } else if (o.filter == MapFilter::Pcf20 && o.preset == MapPreset::Default) {
        return std::string("map: filter \"pcf20\" (the lecture's 20 directions) is for point lights' cube maps");
    }
    if (o.outside == MapOutside::Repeat && (isCube(o, light) || o.atlas || o.cascades > 1))
        return std::string("map: outside \"repeat\" is for one 2D map (a directional or spot light without cascades or the atlas); use outside \"lit\"");
    if (o.atlas) {
        if (light.type == LightType::Directional)
            return std::string("map: atlas is for spot and point lights; a directional light's map (or cascades) is its own");
        if (o.preset != MapPreset::Default) return std::string("map: preset: the presets keep their own maps, not a tile of the atlas; use preset \"default\" with atlas");
        if (o.format != MapFormat::Depth32F) return std::string("map: format: the atlas is depth32f; use format \"depth32f\" (the default) with atlas");
        if (o.filter != MapFilter::None && o.filter != MapFilter::Hardware)
            return "map: filter \"" + std::string(filterInfo(o.filter).name) + "\": an atlas tile is looked up with one tap; use filter \"none\" or \"hardware\" with atlas";
        if (o.representation != MapRepresentation::Depth) return std::string("map: representation: the atlas holds depth; use representation \"depth\" with atlas");
        if (o.mipmaps) return std::string("map: mipmaps: atlas tiles have none; use mipmaps false with atlas");
    }
    const FilterInfo& filter = filterInfo(o.filter);
    if (isCube(o, light) && !filter.forCube)
        return "map: filter \"" + std::string(filter.name) + "\" is for 2D maps (directional and spot lights), not a point light's cube";
    if (!isCube(o, light) && !filter.for2D && o.preset == MapPreset::Default)
        return "map: filter \"" + std::string(filter.name) + "\" is for point lights' cube maps";
    if (o.representation != MapRepresentation::Depth) {
        if (isPacked(o.format))
            return std::string("map: format \"") + (o.format == MapFormat::Rgba8 ? "rgba8" : "r8") +
                   "\": moment maps have their own format (momentFormat); formats \"rgba8\" and \"r8\" pack depth only";
        if (o.filter != MapFilter::Hardware)
            return "map: filter \"" + std::string(filter.name) +
                   "\": a moment map is filtered by its blur and bilinear lookups; filter must be \"hardware\" (the default)";
        if (o.preset != MapPreset::Default) return std::string("map: preset: moment maps do not combine with a preset; use preset \"default\"");
    }
    if (o.fit == MapFit::Sdsm) {
        if (light.type != LightType::Directional)
            return std::string("map: fit \"sdsm\" is for directional lights (a spot or point light takes \"tight\" or \"scene\")");
        if (o.preset != MapPreset::Default)
            return std::string("map: fit \"sdsm\" does not combine with a preset (its fit is the preset's own); use fit \"tight\" or preset \"default\"");
    }
    if (o.warp == MapWarp::Lispsm) {
        if (light.type != LightType::Directional)
            return std::string("map: warp \"lispsm\" is for directional lights (a spot's map is a perspective already; a point light's cube takes \"none\")");
        if (o.cascades > 1 && o.stabilize)
            return std::string("map: warp \"lispsm\" with cascades takes stabilize false (a warped map cannot be snapped to whole texels); or use warp \"none\"");
        if (o.preset != MapPreset::Default) return std::string("map: warp \"lispsm\" does not combine with a preset (the presets' cameras are their own); use warp \"none\" or preset \"default\"");
        if (o.filter == MapFilter::Pcss)
            return std::string("map: filter \"pcss\" takes distances along the light from an unwarped map; with warp \"lispsm\" use another filter");
        if (o.representation != MapRepresentation::Depth)
            return std::string("map: representation: moment maps blur in texels of an unwarped map; with warp \"lispsm\" use representation \"depth\"");
    }
    if (o.cascades > 1) {
        if (light.type != LightType::Directional)
            return std::string("map: cascades are for directional lights; a spot or point light takes one map (cascades 1)");
        if (o.preset != MapPreset::Default)
            return std::string("map: cascades do not combine with a preset (each preset is one map); use cascades 1 or preset \"default\"");
        if (o.fit == MapFit::Scene)
            return std::string("map: fit \"scene\": cascades fit each slice of the view; fit \"scene\" is one map around the whole scene");
        std::string problem;
        parseSplits(o, problem);
        if (!problem.empty()) return "map: cascadeSplits \"" + text::escapeControl(o.cascadeSplits) + "\": " + problem;
    } else if (!o.cascadeSplits.empty() && o.cascadeSplits.find_first_not_of(" ,\t") != std::string::npos) {
        return std::string("map: cascadeSplits is given but cascades is 1");
    }
    return std::string();
}

void resolveOptions(std::any& options, const std::vector<std::string>& written, const Light& light) {
    MapOptions o = std::any_cast<const MapOptions&>(options);
    // filter "pcf" (the options table's alias: grid, kernel 8 where none is
    // written) is the lectures' 64 taps: on a point light's cube, a 4x4x4
    // grid (Lawonn's), not 8^3. Only the alias gives a grid kernel 8 the
    // block did not write (the grid's own default is 3).
    const bool kernelWritten = std::find(written.begin(), written.end(), "kernel") != written.end();
    if (light.type == LightType::Point && o.filter == MapFilter::Grid && o.kernel == 8 && !kernelWritten) o.kernel = 4;
    options = withPreset(o, light.type == LightType::Point, written);
}

ShadowBaseline plainestMap(const Light& light) {
    const MapOptions& o = light.shadow.get<MapOptions>();
    MapOptions plainest;
    plainest.size = o.size;
    ShadowBaseline baseline{light.shadow, o.cascades != 1 || o.filter != plainest.filter || o.representation != plainest.representation};
    baseline.shadow.options[MapOptions::kTechnique] = plainest;
    return baseline;
}

} // namespace map

TechniqueKind mapKind() {
    return {.name = "map",
            .summary = "a shadow map per light: orthographic for directional, perspective for spot, a cube for point lights",
            .options = &mapOptionTable(),
            .unsupported = &map::unsupported,
            .baseline = &map::plainestMap,
            .resolve = &map::resolveOptions,
            .unused = &map::unusedOption,
            .presetKeys = &map::presetKeys};
}

} // namespace shadowlab
