// Technique "map": the texture arrays (passes/Arrays.h).
#include "techniques/map/passes/Arrays.h"

#include "gl/Calls.h"
#include "techniques/map/options/Settings.h"

#include <shadowlab/Error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace shadowlab::map {

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

GLenum depthFormat(const ArrayKey& key) {
    return key.representation != MapRepresentation::Depth ? GL_DEPTH_COMPONENT32F : depthFormat(key.format);
}

bool momentsFromDepth(const MapOptions& o) {
    return o.representation != MapRepresentation::Depth && o.blur == 0 && !o.mipmaps && o.momentFormat == MapMomentFormat::Rgba32f;
}

int momentCount(MapRepresentation r) { return r == MapRepresentation::Depth ? 0 : r == MapRepresentation::Vsm || r == MapRepresentation::Evsm2 ? 2 : 4; }

bool sharedDepthBuffer(const ArrayKey& key) { return key.format == MapFormat::R8 && !key.cube; }

namespace {

// Bytes a texel of each texture of an array takes.
double depthTexelBytes(const ArrayKey& key) { return depthFormat(key) == GL_DEPTH_COMPONENT16 ? 2.0 : 4.0; }  // depth24 is stored in 4 bytes
double colourTexelBytes(const ArrayKey& key) { return key.format == MapFormat::Rgba8 ? 4.0 : key.format == MapFormat::R8 ? 1.0 : 0.0; }
double momentTexelBytes(const ArrayKey& key) {
    if (!key.storedMoments) return 0.0;  // taken from the depth (momentsFromDepth)
    return momentCount(key.representation) * (key.momentFormat == MapMomentFormat::Rgba16f ? 2.0 : 4.0);
}

} // namespace

double texelBytes(const ArrayKey& key) {
    return (sharedDepthBuffer(key) ? 0.0 : depthTexelBytes(key)) + colourTexelBytes(key) + momentTexelBytes(key);
}

GLenum momentFormatOf(const ArrayKey& k) {
    const bool half = k.momentFormat == MapMomentFormat::Rgba16f;
    return momentCount(k.representation) == 2 ? (half ? GL_RG16F : GL_RG32F) : (half ? GL_RGBA16F : GL_RGBA32F);
}

namespace {

// What one array of `layers` maps of `key` takes, every texture makeArray
// and addTransmittance give it: depth, packed colour and moments (a mip
// chain adds a third), the moment blur's scratch layer, and with
// translucent casters the transmittance and its depth (8 bytes a texel).
double arrayBytes(const ArrayKey& key, int layers, bool translucent) {
    const double texels = static_cast<double>(key.size) * static_cast<double>(key.size);
    const double maps = static_cast<double>(layers) * (key.cube ? 6.0 : 1.0);
    const double mips = key.mipmaps ? 4.0 / 3.0 : 1.0;
    const double colourBytes = colourTexelBytes(key), momentBytes = momentTexelBytes(key);
    const bool colour = colourBytes > 0.0 || momentBytes > 0.0;  // then the depth array has one level (makeArray)
    double bytes = sharedDepthBuffer(key) ? 4.0 * texels : depthTexelBytes(key) * texels * maps * (colour ? 1.0 : mips);
    bytes += (colourBytes + momentBytes) * texels * maps * mips;
    if (momentBytes > 0.0) bytes += momentBytes * texels;  // the blur's scratch
    if (translucent) bytes += 8.0 * texels * maps;
    return bytes;
}

// Stated limits, before anything is allocated: layers per array, and all
// maps together within kMapBudgetBytes (a 16384^2 depth32f map is 1 GiB;
// more than that is almost always a typo, and on llvmpipe it would take
// system memory and seconds per frame). The light named is the first of
// the array that takes the most.
void checkLimits(const std::map<ArrayKey, int>& layersWanted, const std::map<ArrayKey, int>& firstLightOf, const GlInfo& info,
                 std::size_t lightCount, bool translucent, double atlasBytes) {
    constexpr double kMapBudgetBytes = 1024.0 * 1024.0 * 1024.0;
    double bytes = atlasBytes, largest = -1.0;
    int largestLight = 0, largestLayers = 0;
    ArrayKey largestKey;
    for (const auto& wanted : layersWanted) {
        const ArrayKey& key = wanted.first;
        const int perLight = key.cube ? 6 : 1;
        const int firstLight = firstLightOf.at(key);
        const double these = arrayBytes(key, wanted.second, translucent);
        bytes += these;
        if (these > largest) {
            largest = these;
            largestLight = firstLight;
            largestKey = key;
            largestLayers = wanted.second * perLight;
        }
        if (wanted.second * perLight > info.maxArrayLayers)
            throw InputError("lights[" + std::to_string(firstLight) + "].shadow.map: " + std::to_string(wanted.second * perLight) +
                        " map layers in one array (" + (perLight == 6 ? std::to_string(wanted.second) + " point light(s), six each" : "lights and cascades") +
                        "), past this GPU's limit of " + std::to_string(info.maxArrayLayers) + " layers");
    }
    if (bytes > kMapBudgetBytes && largest < 0.0)
        throw InputError("shadowAtlas.size: the shadow atlas needs " + std::to_string(atlasBytes / kMapBudgetBytes).substr(0, 4) +
                    " GiB, more than the maps' budget of 1 GiB (a side of at most 16384 texels, 8192 by default)");
    if (bytes > kMapBudgetBytes) {
        // Named at the map block of the light whose array takes the most, so
        // that the source named is whichever set its size, cascades or
        // format (a --set of cascades on a file's size, say).
        char text[400];
        std::snprintf(text, sizeof text,
                      "the shadow maps of %zu light(s) need %.2f GiB, more than the budget of 1 GiB%s (the largest array, from this light: %d layer(s) of %d^2, %.2f GiB; lower lights[i].shadow.map.size or cascades, or set technique \"none\" on lights that need no shadow)",
                      lightCount, bytes / kMapBudgetBytes, atlasBytes > 0.0 ? " with the shadow atlas's" : "", largestLayers, largestKey.size, largest / kMapBudgetBytes);
        throw InputError("lights[" + std::to_string(largestLight) + "].shadow.map: " + text);
    }
}

// A new array of `layers` maps for `key`, with the colour, moment and blur
// textures its kind needs.
MapArray makeArray(const ArrayKey& key, int layers, std::uint64_t generation) {
    MapArray g;
    g.key = key;
    g.layers = layers;
    g.generation = generation;
    const int size = key.size;
    const int levels = key.mipmaps ? 1 + static_cast<int>(std::floor(std::log2(static_cast<double>(size)))) : 1;
    const bool colour = isPacked(key.format) || g.hasMoments();  // the depth array only serves the depth test
    g.depth = gl::Texture(g.target());
    gl::textureStorage3D(g.depth.id(), colour ? 1 : levels, depthFormat(key), size, size,
                       sharedDepthBuffer(key) ? 1 : layers * g.layersPerLight());
    if (isPacked(key.format)) {
        g.packed = gl::Texture(g.target());
        gl::textureStorage3D(g.packed.id(), levels, key.format == MapFormat::R8 ? GL_R8 : GL_RGBA8, size, size, layers * g.layersPerLight());
    }
    if (g.storesMoments()) {
        g.moments = gl::Texture(g.target());
        gl::textureStorage3D(g.moments.id(), levels, momentFormatOf(key), size, size, layers);
        g.blurScratch = gl::Texture(GL_TEXTURE_2D);
        gl::textureStorage2D(g.blurScratch.id(), 1, momentFormatOf(key), size, size);
        g.blurFbo = gl::Framebuffer();
        gl::namedFramebufferTexture(g.blurFbo.id(), GL_COLOR_ATTACHMENT0, g.blurScratch.id(), 0);
        gl::namedFramebufferDrawBuffer(g.blurFbo.id(), GL_COLOR_ATTACHMENT0);
        gl::checkFramebuffer(g.blurFbo, "moment blur framebuffer");
        g.momentFbo = gl::Framebuffer();
        gl::namedFramebufferDrawBuffer(g.momentFbo.id(), GL_COLOR_ATTACHMENT0);
    }
    return g;
}

} // namespace

void MapArrays::allocate(const std::map<ArrayKey, int>& layersWanted, const std::map<ArrayKey, int>& firstLightOf, const GlInfo& info,
                         std::size_t lightCount, bool translucent, double atlasBytes) {
    checkLimits(layersWanted, firstLightOf, info, lightCount, translucent, atlasBytes);
    std::vector<MapArray> arrays;
    for (const auto& wanted : layersWanted) {
        const ArrayKey& key = wanted.first;  // not a structured binding: clang 14 cannot capture one
        const int layers = wanted.second;
        // Keep an existing array when it still fits, so maps are not reallocated every frame.
        auto same = std::find_if(arrays_.begin(), arrays_.end(), [&](const MapArray& g) { return g.key == key && g.layers == layers; });
        if (same != arrays_.end())
            arrays.push_back(std::move(*same));
        else
            arrays.push_back(makeArray(key, layers, ++generations_));
    }
    arrays_ = std::move(arrays);
}

void MapArrays::addTransmittance() {
    for (MapArray& g : arrays_)
        if (!g.transmit) {
            g.transmit = gl::Texture(g.target());
            gl::textureStorage3D(g.transmit.id(), 1, GL_RGBA8, g.size(), g.size(), g.layers * g.layersPerLight());
            g.transmitDepth = gl::Texture(g.target());
            gl::textureStorage3D(g.transmitDepth.id(), 1, GL_R32F, g.size(), g.size(), g.layers * g.layersPerLight());
        }
}

std::size_t MapArrays::indexOf(const ArrayKey& key) const {
    std::size_t found = 0;
    for (std::size_t g = 0; g < arrays_.size(); ++g)
        if (arrays_[g].key == key) found = g;
    return found;
}

} // namespace shadowlab::map
