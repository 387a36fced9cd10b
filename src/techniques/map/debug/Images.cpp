// Technique "map": its debug images (debug/Images.h).
#include "techniques/map/debug/Images.h"

#include "gl/Calls.h"
#include "techniques/map/Variants.h"
#include "techniques/map/fit/Cameras.h"
#include "techniques/map/options/Settings.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <string>

namespace shadowlab::map {

namespace {

// One layer of a group's array (a 2D map, or one face of a cube) as
// stored depths in 0..1: read back, or unpacked from rgba8's base-255
// digits (the 4th is below float precision here) or r8's one byte.
std::vector<float> readLayer(const MapArray& g, int layer) {
    const std::size_t n = static_cast<std::size_t>(g.size()) * static_cast<std::size_t>(g.size());
    std::vector<float> depth(n);
    if (g.format() == MapFormat::Rgba8) {
        std::vector<std::uint8_t> rgba(n * 4);
        gl::getTextureSubImage(g.packed.id(), 0, 0, 0, layer, g.size(), g.size(), 1, GL_RGBA, GL_UNSIGNED_BYTE,
                             static_cast<GLsizei>(rgba.size()), rgba.data());
        for (std::size_t i = 0; i < n; ++i) depth[i] = rgba[4 * i] / 255.0f + rgba[4 * i + 1] / 65025.0f + rgba[4 * i + 2] / 16581375.0f;
    } else if (g.format() == MapFormat::R8) {
        std::vector<std::uint8_t> r(n);
        gl::getTextureSubImage(g.packed.id(), 0, 0, 0, layer, g.size(), g.size(), 1, GL_RED, GL_UNSIGNED_BYTE, static_cast<GLsizei>(n), r.data());
        for (std::size_t i = 0; i < n; ++i) depth[i] = r[i] / 255.0f;
    } else {
        gl::getTextureSubImage(g.depth.id(), 0, 0, 0, layer, g.size(), g.size(), 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                             static_cast<GLsizei>(n * sizeof(float)), depth.data());
    }
    return depth;
}

// A cube face of reversed window depth (cubeWindowDepth) as distance /
// far, texel by texel (a texel's distance is its depth along the face's
// axis times sqrt(1 + s^2 + t^2), s and t its place on the face, -1..1);
// cleared texels (0) are 1, as in a written cube.
void windowToDistance(std::vector<float>& depth, int size, const CubeCamera& c) {
    const float n = c.nearPlane, f = c.farPlane;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float& d = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)];
            if (d <= 0.0f) {
                d = 1.0f;
                continue;
            }
            const float s = 2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(size) - 1.0f;
            const float t = 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(size) - 1.0f;
            const float axis = n * f / (d * (f - n) + n);
            d = std::min(axis * std::sqrt(1.0f + s * s + t * t) / f, 1.0f);
        }
}

// A point light's six faces as a horizontal cross (+Y above; -X, +Z, +X,
// -Z across; -Y below: neighbouring edges touch), each face's rows as GL
// stores them (t down), tiles of at most 512 texels. Stored depth is
// distance / far (a window-depth cube's turned into it), linear:
// stretched over its range for contrast; white where no caster was drawn.
ImageRGBA8 cubeCross(const MapArray& g, const MapLight& p, std::vector<float>& values) {
    const int tile = std::min(g.size(), 512);
    std::array<std::vector<float>, 6> faces;
    float lo = 1.0f, hi = 0.0f;
    for (int f = 0; f < 6; ++f) {
        std::vector<float>& depth = faces[static_cast<std::size_t>(f)];
        depth = readLayer(g, 6 * p.layer + f);
        if (cubeWindowDepth(p.options)) windowToDistance(depth, g.size(), p.cubeCamera());
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

// The frame from the camera, each visible point coloured by
// `fragmentFile` with the light's map block: the texel footprint
// (shadow_map_density.frag, whose float output goes to `values` when
// given, rows as GL stores them), the cascade (shadow_map_cascades.frag).
ImageRGBA8 frameView(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, const MapLight& p,
                     const char* fragmentFile, std::vector<float>* values = nullptr) {
    const glm::ivec2 size = frame.viewport;
    gl::Texture colour(GL_TEXTURE_2D), depth(GL_TEXTURE_2D), measure(GL_TEXTURE_2D);
    gl::textureStorage2D(colour.id(), 1, GL_RGBA8, size.x, size.y);
    gl::textureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT24, size.x, size.y);
    gl::textureStorage2D(measure.id(), 1, GL_R32F, size.x, size.y);
    gl::Framebuffer fbo;
    gl::namedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, colour.id(), 0);
    gl::namedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT1, measure.id(), 0);
    gl::namedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl::namedFramebufferDrawBuffers(fbo.id(), values ? 2 : 1, buffers);
    gl::checkFramebuffer(fbo, "frame view framebuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, size.x, size.y);
    host.apply(gl::RenderState{});
    const float background[4] = {0.0f, 0.0f, 0.0f, 1.0f}, none[4] = {-1.0f, -1.0f, -1.0f, -1.0f}, one = 1.0f;
    gl::clearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, background);
    if (values) gl::clearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, none);
    gl::clearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
    res.block.upload(p, res.arrays[p.array], view.light, res.translucent);
    const int cascades = static_cast<int>(p.cameras().size());
    host.drawItems(ItemFilter::Opaque, host.program({{{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, fragmentFile}},
                                                  FrameViewVariant{p.cube() ? 1 : cascades, p.cube()}.defines()}));
    ImageRGBA8 image{size.x, size.y, std::vector<std::uint8_t>(static_cast<std::size_t>(size.x) * size.y * 4)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::getTextureImage(colour.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.pixels.size()), image.pixels.data());
    if (values) {
        values->assign(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y), -1.0f);
        gl::getTextureImage(measure.id(), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(values->size() * sizeof(float)), values->data());
    }
    // GL's rows go bottom to top; images top to bottom.
    const std::size_t row = static_cast<std::size_t>(size.x) * 4;
    for (int y = 0; y < size.y / 2; ++y)
        std::swap_ranges(image.pixels.begin() + static_cast<long>(y * row), image.pixels.begin() + static_cast<long>((y + 1) * row),
                         image.pixels.begin() + static_cast<long>((size.y - 1 - y) * row));
    return image;
}

// Layer `layer` of `g`, drawn from `camera`, as a grey image: stored
// depth (perspective depth linearised), near black, far white; texels
// outside `drawn` (the pass's part of the layer, drawnTexels), which no
// lookup reads and the pass neither clears nor draws, pale blue.
ImageRGBA8 mapImage(const MapArray& g, int layer, const LightCamera& camera, const std::optional<TexelRect>& drawn) {
    const std::size_t n = static_cast<std::size_t>(g.size()) * static_cast<std::size_t>(g.size());
    const std::vector<float> depth = readLayer(g, layer);
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
            if (drawn && !(x >= drawn->x0 && x < drawn->x1 && y >= drawn->y0 && y < drawn->y1)) {
                px[0] = 190;
                px[1] = 210;
                px[2] = 240;
            }
        }
    return image;
}

} // namespace

void debugImages(TechniqueHost& host, const FrameInfo& frame, const LightView& view, MapResources& res, const MapLight& p,
                 const DebugImageKinds& kinds, std::vector<DebugImage>& out) {
    const MapArray& g = res.arrays[p.array];
    const std::span<const LightCamera> cameras = p.cameras();
    if (p.cube() && kinds.wants(DebugImageKind::CubeCross)) {
        std::vector<float> values;
        ImageRGBA8 cross = cubeCross(g, p, values);
        out.push_back({"cube", std::move(cross), std::move(values), DebugImageKind::CubeCross});
    }
    if (!p.cube() && kinds.wants(DebugImageKind::ShadowMap))
        for (std::size_t c = 0; c < cameras.size(); ++c)
            out.push_back({cameras.size() > 1 ? "cascade" + std::to_string(c) + "-map" : std::string("map"), mapImage(g, p.layer + static_cast<int>(c), cameras[c], drawnTexels(frame, g, p, cameras[c])), {}, DebugImageKind::ShadowMap});
    if (kinds.wants(DebugImageKind::TexelDensity)) {
        std::vector<float> footprint;
        ImageRGBA8 density = frameView(host, frame, view, res, p, "shadow_map_density.frag", &footprint);
        out.push_back({"texel-density", std::move(density), std::move(footprint), DebugImageKind::TexelDensity});
    }
    if (!p.cube() && cameras.size() > 1 && kinds.wants(DebugImageKind::Cascades))
        out.push_back({"cascades", frameView(host, frame, view, res, p, "shadow_map_cascades.frag"), {}, DebugImageKind::Cascades});
}

} // namespace shadowlab::map
