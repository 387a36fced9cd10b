#pragma once
/// @file DebugImage.h
/// The images a shadow technique offers for inspection
/// (Renderer::debugImages, `shadowlab render --debug-images`).
#include <shadowlab/Image.h>

#include <algorithm>
#include <string>
#include <vector>

namespace shadowlab {

/// What a debug image shows, set by the technique that makes it: tools pick
/// images by kind (`shadowlab render --debug shadow-maps`), never by name.
enum class DebugImageKind {
    Other,        ///< anything else (the default)
    ShadowMap,    ///< a 2D shadow map's stored depth (one per cascade; a light in the shadow atlas: its tiles side by side)
    CubeCross,    ///< a cube map's six faces as a cross (a point light's map)
    TexelDensity, ///< the frame coloured by the texel footprint (screen pixels a shadow-map texel covers); values: the footprint per pixel, rows as GL stores them, -1 where not measured
    Cascades,     ///< the frame coloured by the cascade each point falls in
    Atlas,        ///< the shadow atlas (one image, with its first light): every tile's stored depth (each stretched over its own range, near dark), each light's tiles outlined in a colour of its own; values: the atlas's depths over the part its tiles use, rows as GL stores them
};

/// The kinds of debug image a caller asks for: reading a map back to draw
/// it costs (a cube of 1024^2 faces: 6 M texels), so a caller that wants
/// one kind names it. Empty: every kind.
struct DebugImageKinds {
    std::vector<DebugImageKind> only;
    bool wants(DebugImageKind kind) const { return only.empty() || std::find(only.begin(), only.end(), kind) != only.end(); }
};

/// An image a technique offers for inspection (a depth map, a cube cross).
struct DebugImage {
    std::string name;   ///< file-name friendly, e.g. "light0-depth"
    ImageRGBA8 image;
    /// The exact values behind the picture where a technique has them (a
    /// cube map's stored depths: its six faces, +X..-Z, one after another,
    /// rows as GL stores them); empty otherwise. Not written by the CLI.
    std::vector<float> values;
    DebugImageKind kind = DebugImageKind::Other; ///< what it shows
    int light = -1;     ///< the light it belongs to, into Scene::lights (Renderer::debugImages sets it)
};

} // namespace shadowlab
