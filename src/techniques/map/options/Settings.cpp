// Technique "map": the light's effective options and what follows from
// them (options/Settings.h).
#include "techniques/map/options/Settings.h"

#include "shadow_map_shared.h"
#include "techniques/map/options/Filters.h"

#include <shadowlab/Text.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <any>
#include <array>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <vector>

namespace shadowlab::map {

namespace {

// What the lecture's and LearnOpenGL's presets share: a depth32f map, no
// bias but the one they set themselves, and every caster's every triangle.
void presetBase(MapOptions& o) {
    o.format = MapFormat::Depth32F;
    o.lodTexels = 0.0f;
    o.slopeBias = 0.0f;
    o.offsetUnits = 0.0f;
    o.normalBias = 0.0f;
    o.constantBias = 0.0f;
    o.cullFront = false;
}

} // namespace

// Whether the map is depth packed into a colour target (rgba8's four
// base-255 digits, or r8's one), compared in the shader.
bool isPacked(MapFormat f) { return f == MapFormat::Rgba8 || f == MapFormat::R8; }

bool cubeWindowDepth(MapFormat f, MapFilter filter) {
    return f == MapFormat::Depth32F && (filter == MapFilter::None || filter == MapFilter::Hardware);
}

bool bilinearGrid(const MapOptions& o, bool softwareRasterizer) {
    return !isPacked(o.format) && (o.gridTaps == MapGridTaps::Bilinear || (o.gridTaps == MapGridTaps::Auto && !softwareRasterizer));
}

DepthTaps depthTaps(const MapOptions& o, bool cube, bool softwareRasterizer) {
    const FilterInfo& f = filterInfo(o.filter);
    const bool linear = cube ? f.linearCube : f.linear2D(bilinearGrid(o, softwareRasterizer));
    const bool plain = softwareRasterizer && o.format == MapFormat::Depth32F && !o.mipmaps && (cube || o.representation == MapRepresentation::Depth);
    return linear ? DepthTaps::Linear : plain ? DepthTaps::Plain : DepthTaps::Nearest;
}

bool layerView(const MapOptions& o, bool cube, int cascades) {
    if (o.atlas || isPacked(o.format) || o.mipmaps) return false;
    if (cube) return o.filter != MapFilter::None && o.filter != MapFilter::Hardware;
    return cascades == 1 && o.representation == MapRepresentation::Depth;
}

int kernelRounds(const MapOptions& o, bool cube) {
    if (!o.earlyOut || o.representation != MapRepresentation::Depth) return 0;
    if (o.filter == MapFilter::Pcf20 && cube) return 5;
    if (o.filter == MapFilter::Grid && !cube && o.kernel >= 3) return 1 + (o.kernel * o.kernel - 4 - o.kernel % 2) / 4;
    return 0;
}

bool earlyOut(const MapOptions& o, bool cube, bool softwareRasterizer) {
    if (o.filter == MapFilter::Pcss) return o.earlyOut && o.representation == MapRepresentation::Depth;
    return kernelRounds(o, cube) > 0 && !(o.filter == MapFilter::Grid && bilinearGrid(o, softwareRasterizer));
}

namespace {

// vogelHullInradius, computed.
float hullInradiusOf(int n) {
    std::vector<glm::dvec2> taps;
    for (int k = 0; k < n; ++k) {
        const double r = std::sqrt((k + 0.5) / n), a = k * static_cast<double>(SL_MAP_GOLDEN_ANGLE);
        taps.push_back(r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    // The convex hull, counter-clockwise (Andrew's monotone chain).
    std::sort(taps.begin(), taps.end(), [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<glm::dvec2> hull;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t start = hull.size();
        for (const glm::dvec2& t : taps) {
            while (hull.size() >= start + 2 && cross(hull[hull.size() - 2], hull.back(), t) <= 0.0) hull.pop_back();
            hull.push_back(t);
        }
        hull.pop_back();  // the chain's last point starts the other chain
        std::reverse(taps.begin(), taps.end());
    }
    if (hull.size() < 3) return 0.0f;
    // The centre's distance to each edge, positive on the inside (left).
    double inradius = 1.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        inradius = std::min(inradius, cross(a, b, glm::dvec2(0.0)) / glm::length(b - a));
    }
    return static_cast<float>(std::max(inradius, 0.0));
}

} // namespace

float vogelHullInradius(int n) {
    // Once for every tap count the options allow (at most 64): the block
    // that carries it is uploaded every frame.
    static const std::array<float, 65> table = [] {
        std::array<float, 65> t{};
        for (int k = 1; k <= 64; ++k) t[static_cast<std::size_t>(k)] = hullInradiusOf(k);
        return t;
    }();
    return n >= 1 && n <= 64 ? table[static_cast<std::size_t>(n)] : hullInradiusOf(n);
}

// Texels around the fitted region that the filter may read.
float footprint(const MapOptions& o) {
    if (o.representation != MapRepresentation::Depth) return static_cast<float>(o.blur) + 2.0f;  // the blur, then a bilinear lookup
    return filterInfo(o.filter).footprint(o);
}

float marginTexels(const MapOptions& o) { return filterInfo(o.filter).footprint(o) + std::max(o.normalBias, 0.0f) + 2.0f; }

// Texels from a filter's centre to its farthest tap (the receiver-plane
// bias covers that distance; the presets keep their own biases instead).
float reach(const MapOptions& o) {
    if (o.preset != MapPreset::Default || o.representation != MapRepresentation::Depth) return 0.0f;  // moments bound the depths' spread instead
    return filterInfo(o.filter).reach(o);
}

// Every field `o`'s preset sets, set (docs/techniques/map.md cites each value);
// withPreset keeps the fields the scene wrote.
MapOptions presetValues(MapOptions o, bool pointLight) {
    const bool cube = pointLight && o.preset != MapPreset::Lecture000;
    if (cube && o.preset == MapPreset::Lecture) {
        // Lawonn's cube: near 1, far 25 (cubeNearFar), no bias but a
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
        // Wolberg's lecture: glPolygonOffset(2.0, 4.0), a DEPTH_COMPONENT32F map
        // of the window's size (size 0: the frame's larger side), the
        // 4-sample dithered PCF; no normal offset, no constant bias.
        presetBase(o);
        o.size = 0;
        o.slopeBias = 2.0f;
        o.offsetUnits = 4.0f;
        o.filter = MapFilter::Dither4;
        o.fit = MapFit::Scene;
        // Ganovelli et al. listing 8.4: a shadowed point keeps 60 % (color *= 0.6).
        o.shadowedLight = 0.6f;
    } else if (o.preset == MapPreset::LearnOpenGL) {
        // LearnOpenGL 5.advanced_lighting/3.1.3: 1024^2 DEPTH_COMPONENT
        // (float), 3x3 PCF of nearest taps, bias max(0.05 (1 - N.L), 0.005),
        // no polygon offset or normal offset; the light camera is fixed (learnOpenGlCamera).
        presetBase(o);
        o.size = 1024;
        o.filter = MapFilter::Grid;
        o.kernel = 3;
    }
    return o;
}

} // namespace shadowlab::map

namespace shadowlab {

int frameMapSize(int width, int height) {
    const float want = kFrameMapTexelsPerPixel * static_cast<float>(std::max(width, height));
    const int side = (static_cast<int>(std::ceil(want)) + 15) / 16 * 16;
    return std::clamp(side, kFrameMapMinimum, kFrameMapMaximum);
}

MapOptions withPreset(const MapOptions& o, bool pointLight, const std::vector<std::string>& written) {
    if (o.preset == MapPreset::Default) return o;
    std::any out = map::presetValues(o, pointLight);
    const std::any given = o;
    const OptionTable& table = mapOptionTable();
    for (const std::string& key : written) {
        const OptionField* f = table.find(key);
        if (!f || key == "preset") continue;
        if (f->kind == OptionKind::Text)
            f->setText(out, f->getText(given));
        else
            f->set(out, f->get(given));
    }
    return std::any_cast<MapOptions>(out);
}

} // namespace shadowlab

namespace shadowlab::map {

// The light's options: its preset was resolved when the scene was read (withPreset).

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

// Wolberg's camera for its point light (the torus-and-pyramid scene):
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
        const std::string word(at, end == at ? std::strcspn(at, " \t") : static_cast<std::size_t>(end - at));
        if (end == at) {
            problem = "expected increasing distances > 0, got '" + word + "'";
            return {};
        }
        if (!std::isfinite(v)) {
            problem = "expected increasing distances > 0; " + word + " is not finite or past a 32-bit float's range (about 3.4e38)";
            return {};
        }
        if (v <= 0.0f || (!out.empty() && v <= out.back())) {
            problem = "expected increasing distances > 0" +
                      (v <= 0.0f ? ", got " + word : "; " + word + " does not follow " + text::numberText(out.back()) +
                                                         (std::strtod(word.c_str(), nullptr) != static_cast<double>(v) ? " (it is " + text::numberText(v) + " as a 32-bit float)" : ""));
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
bool isCube(const MapOptions& o, const Light& light) { return light.type == LightType::Point && o.preset != MapPreset::Lecture000; }
// Wolberg's 2D settings (the window-sized map, the dither spread).
bool isLecture2D(const MapOptions& o, const Light& light) {
    return !isCube(o, light) && (o.preset == MapPreset::Lecture || o.preset == MapPreset::Lecture000);
}
bool usesPresetBias(const MapOptions& o, bool cube) {
    return cube ? o.preset != MapPreset::Default : o.preset == MapPreset::LearnOpenGL;
}
// The presets' fixed near and far planes for a cube (Lawonn and LearnOpenGL: 1 and 25); 0: fitted.
std::pair<float, float> cubeNearFar(const MapOptions& o) {
    return o.preset == MapPreset::Lecture || o.preset == MapPreset::LearnOpenGL ? std::pair{1.0f, 25.0f} : std::pair{0.0f, 0.0f};
}

} // namespace shadowlab::map
