// Technique "map": its typed shader variants (Variants.h).
#include "techniques/map/Variants.h"
#include "techniques/map/passes/Arrays.h"

#include "techniques/map/moments/Constants.h"
#include "techniques/map/options/Filters.h"
#include "techniques/map/options/Settings.h"

#include "shadow_map_shared.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace shadowlab::map {

// The GLSL tests MAP_MOMENTS against these values (MAP_FILTER's come from the filters' table).
static_assert(static_cast<int>(MapRepresentation::Depth) == 0 && static_cast<int>(MapRepresentation::Vsm) == SL_MAP_MOMENTS_VSM &&
              static_cast<int>(MapRepresentation::Evsm2) == SL_MAP_MOMENTS_EVSM2 && static_cast<int>(MapRepresentation::Evsm4) == SL_MAP_MOMENTS_EVSM4 &&
              static_cast<int>(MapRepresentation::Msm) == SL_MAP_MOMENTS_MSM,
              "MapRepresentation's values must be shadow_map_shared.h's SL_MAP_MOMENTS_* (0: depth)");

namespace {

// `#define NAME VALUE` lines, in the order given.
class Defines {
public:
    Defines& set(const char* name, int value) {
        text_ += std::string("#define ") + name + " " + std::to_string(value) + "\n";
        return *this;
    }
    Defines& set(const char* name, bool value) { return set(name, value ? 1 : 0); }
    // A packed format's: rgba8's four digits or r8's one byte (shadow_map_shared.h packDepth).
    Defines& packing(MapFormat f) { return set("MAP_RGBA8", isPacked(f)).set("MAP_R8", f == MapFormat::R8); }
    // Every filter's SL_MAP_FILTER_<NAME> (its enum value), then this one's as MAP_FILTER.
    Defines& filter(MapFilter f) {
        for (const FilterInfo& info : filters()) {
            std::string name = std::string("SL_MAP_FILTER_") + info.name;
            std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
            set(name.c_str(), static_cast<int>(info.filter));
        }
        return set("MAP_FILTER", static_cast<int>(f));
    }
    // A moment map's constants (moments/Moments.h), as the GLSL reads them.
    Defines& moments(MapMomentFormat format) {
        const MomentConstants c = MomentConstants::of(format);
        char text[200];
        std::snprintf(text, sizeof text, "#define MAP_EVSM_POSITIVE %.4f\n#define MAP_EVSM_NEGATIVE %.4f\n#define MAP_MOMENT_BIAS %.1e\n#define MAP_MIN_VARIANCE %.1e\n",
                      c.evsmPositive, c.evsmNegative, c.momentBias, c.minVariance);
        text_ += text;
        return *this;
    }
    std::string str() const { return text_; }

private:
    std::string text_;
};

} // namespace

LightPassVariant LightPassVariant::of(const MapOptions& o, const Light& light, bool softwareRasterizer, bool translucentCasters) {
    LightPassVariant v;
    v.filter = o.filter;
    v.kernel = o.kernel;
    v.format = o.format;
    v.gridBilinear = bilinearGrid(o, softwareRasterizer);
    v.cube = isCube(o, light);
    v.cascades = cascadeCount(light, o);
    v.representation = v.cube ? MapRepresentation::Depth : o.representation;
    v.momentFormat = o.momentFormat;
    v.transmittance = translucentCasters;
    v.plainFetch = map::plainFetch(o, v.cube, softwareRasterizer);
    v.pcssNearest = softwareRasterizer && o.filter == MapFilter::Pcss;
    v.quadShared = o.filter == MapFilter::Pcss && v.representation == MapRepresentation::Depth && !o.atlas;
    v.earlyOut = map::earlyOut(o, v.cube, softwareRasterizer);
    v.warped = !v.cube && o.warp == MapWarp::Lispsm;
    v.cascadeAxes = v.cascades > 1 && !v.warped && o.fit != MapFit::Sdsm;
    v.atlas = o.atlas;
    v.presetBias = !o.atlas && usesPresetBias(o, v.cube);
    v.momentsFromDepth = !v.cube && !o.atlas && map::momentsFromDepth(o);
    v.layerView = map::layerView(o, v.cube, v.cascades);
    v.mipmaps = !v.cube && !o.atlas && o.mipmaps && v.representation == MapRepresentation::Depth && !v.presetBias;
    v.outsideRepeat = !v.cube && !o.atlas && v.cascades == 1 && o.outside == MapOutside::Repeat;
    v.rayDepthOffset = !v.cube && !o.atlas && light.type != LightType::Directional;
    return v;
}

std::string LightPassVariant::defines() const {
    return Defines()
        .filter(filter)
        .set("MAP_KERNEL", kernel)
        .packing(format)
        .set("MAP_GRID_BILINEAR", gridBilinear)
        .set("MAP_CUBE", cube)
        .set("MAP_CASCADES", cascades)
        .set("MAP_MOMENTS", static_cast<int>(representation))
        .moments(momentFormat)
        .set("MAP_TRANSMIT", transmittance)
        .set("MAP_PLAIN_FETCH", plainFetch)
        .set("MAP_PCSS_NEAREST", pcssNearest)
        .set("MAP_QUAD_SHARED", quadShared)
        .set("MAP_EARLY_OUT", earlyOut)
        .set("MAP_WARP", warped)
        .set("MAP_CASCADE_AXES", cascadeAxes)
        .set("MAP_CUBE_WINDOW", cube && cubeWindowDepth(format, filter))
        .set("MAP_ATLAS", atlas)
        .set("MAP_PRESET_BIAS", presetBias)
        .set("MAP_MOMENTS_FROM_DEPTH", momentsFromDepth)
        .set("MAP_LAYER_VIEW", layerView)
        .set("MAP_MIPMAPS", mipmaps)
        .set("MAP_OUTSIDE_REPEAT", outsideRepeat)
        .set("MAP_RAY_DEPTH_OFFSET", rayDepthOffset)
        .str();
}

std::string LightPassVariant::kernelFile() const {
    if (atlas) return "shadow_map_atlas.glsl";
    return representation != MapRepresentation::Depth ? std::string("shadow_map_moments.glsl") : map::kernelFile(filter);
}

std::string LookupFloorVariant::defines() const { return Defines().set("LOOKUP_FETCH", fetch).set("LOOKUP_CUBE", cube).str(); }

std::string DepthPassVariant::defines() const { return Defines().packing(format).set("MAP_HOLES", holes).str(); }

std::string CubePassVariant::defines() const {
    return Defines()
        .packing(format)
        .set("MAP_CUBE_ONE_PASS", onePass)
        .set("MAP_CUBE_CULL", faceCulling)
        .set("MAP_CUBE_WINDOW", windowDepth)
        .set("MAP_HOLES", holes)
        .str();
}

std::string TranslucentVariant::defines() const { return Defines().str(); }

std::string FrameViewVariant::defines() const { return Defines().set("MAP_CASCADES", cascades).set("MAP_CUBE", cube).str(); }

std::string BlurVariant::defines() const {
    Defines d;
    d.set("BLUR_FROM_DEPTH", fromDepth).set("BLUR_RADIUS", radius);
    if (fromDepth) d.set("MAP_SPOT", spot).set("MAP_MOMENTS", static_cast<int>(representation)).moments(momentFormat);
    return d.str();
}

} // namespace shadowlab::map
