// Technique "map": the shadow atlas as images (atlas/Images.h).
#include "techniques/map/atlas/Images.h"

#include "gl/Calls.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace shadowlab::map {

DebugImage atlasImage(const MapAtlas& atlas, const std::map<int, const MapLight*>& lights, int maxSide) {
    // The used part: the tiles' bounding rectangle (Z-order keeps them near the origin).
    glm::ivec2 used(1);
    for (const auto& [index, p] : lights)
        for (int t = 0; t < p->atlas->count; ++t)
            used = glm::max(used, p->atlas->origins[static_cast<std::size_t>(t)] + glm::ivec2(p->atlas->sides[static_cast<std::size_t>(t)]));
    used = glm::min(used, glm::ivec2(std::max(atlas.size(), 1)));
    DebugImage out;
    out.name = "atlas";
    out.kind = DebugImageKind::Atlas;
    out.values.resize(static_cast<std::size_t>(used.x) * static_cast<std::size_t>(used.y));
    if (atlas.size() > 0)
        gl::getTextureSubImage(atlas.texture().id(), 0, 0, 0, 0, used.x, used.y, 1, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(out.values.size() * sizeof(float)),
                             out.values.data());
    const int step = std::max(1, (std::max(used.x, used.y) + maxSide - 1) / maxSide);
    const int width = (used.x + step - 1) / step, height = (used.y + step - 1) / step;
    out.image.width = width;
    out.image.height = height;
    out.image.pixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 255);  // white where no tile is
    const auto at = [&](int x, int y) { return out.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(used.x) + static_cast<std::size_t>(x)]; };
    const auto put = [&](int x, int y, glm::vec3 c) {  // image rows top first; GL's bottom row first
        if (x >= width || y >= height) return;
        const std::size_t i = (static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
        for (int k = 0; k < 3; ++k) out.image.pixels[i + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(std::clamp(c[k], 0.0f, 1.0f) * 255.0f + 0.5f);
        out.image.pixels[i + 3] = 255;
    };
    int hue = 0;
    for (const auto& [index, p] : lights) {
        const float h = std::fmod(0.618034f * static_cast<float>(hue++), 1.0f);
        const glm::vec3 colour = glm::clamp(glm::abs(glm::fract(glm::vec3(h) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
        for (int t = 0; t < p->atlas->count; ++t) {
            const glm::ivec2 o = p->atlas->origins[static_cast<std::size_t>(t)];
            float lo = 1.0f;
            const TexelRect& cover = p->atlas->covered[static_cast<std::size_t>(t)];
            for (int y = o.y + cover.y0; y < o.y + cover.y1; y += step)
                for (int x = o.x + cover.x0; x < o.x + cover.x1; x += step) lo = std::min(lo, at(x, y));
            const int x0 = (o.x + step - 1) / step, y0 = (o.y + step - 1) / step, x1 = (o.x + p->atlas->sides[static_cast<std::size_t>(t)]) / step,
                      y1 = (o.y + p->atlas->sides[static_cast<std::size_t>(t)]) / step;
            const TexelRect& c = p->atlas->covered[static_cast<std::size_t>(t)];
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const bool edge = x == x0 || y == y0 || x == x1 - 1 || y == y1 - 1;
                    const int tx = x * step - o.x, ty = y * step - o.y;  // tile-local: outside what was cleared and drawn, nothing (white)
                    const bool drawn = tx >= c.x0 && tx < c.x1 && ty >= c.y0 && ty < c.y1;
                    const float d = drawn ? at(x * step, y * step) : 1.0f;
                    const float grey = d >= 1.0f ? 1.0f : lo < 1.0f ? 0.15f + 0.8f * (d - lo) / (1.0f - lo) : 1.0f;
                    put(x, y, edge ? colour : glm::vec3(grey));
                }
        }
    }
    return out;
}

DebugImage atlasLightTiles(const MapAtlas& atlas, const MapLight& p) {
    DebugImage out;
    out.name = "atlas-tiles";
    out.kind = DebugImageKind::ShadowMap;  // the light's map: its tiles
    const int tiles = p.atlas->count;
    if (tiles == 0 || atlas.size() == 0) return out;
    // Each tile's first value and its column in the image: side by side, bottom-aligned.
    std::vector<std::size_t> first(static_cast<std::size_t>(tiles) + 1, 0);
    std::vector<int> column(static_cast<std::size_t>(tiles), 0);
    int height = 0;
    const int gap = 2;
    for (int t = 0; t < tiles; ++t) {
        const int side = p.atlas->sides[static_cast<std::size_t>(t)];
        first[static_cast<std::size_t>(t) + 1] = first[static_cast<std::size_t>(t)] + static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
        if (t > 0) column[static_cast<std::size_t>(t)] = column[static_cast<std::size_t>(t) - 1] + p.atlas->sides[static_cast<std::size_t>(t) - 1] + gap;
        height = std::max(height, side);
    }
    out.values.resize(first.back());
    for (int t = 0; t < tiles; ++t) {
        const glm::ivec2 o = p.atlas->origins[static_cast<std::size_t>(t)];
        const int side = p.atlas->sides[static_cast<std::size_t>(t)];
        const std::size_t area = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
        gl::getTextureSubImage(atlas.texture().id(), 0, o.x, o.y, 0, side, side, 1, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(area * sizeof(float)),
                             out.values.data() + first[static_cast<std::size_t>(t)]);
    }
    out.image.width = column.back() + p.atlas->sides[static_cast<std::size_t>(tiles) - 1];
    out.image.height = height;
    out.image.pixels.assign(static_cast<std::size_t>(out.image.width) * static_cast<std::size_t>(height) * 4, 255);
    for (int t = 0; t < tiles; ++t) {
        const int side = p.atlas->sides[static_cast<std::size_t>(t)];
        const std::size_t area = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
        float* d = out.values.data() + first[static_cast<std::size_t>(t)];
        // Outside what was cleared and drawn this frame: the far plane (nothing there).
        const TexelRect& c = p.atlas->covered[static_cast<std::size_t>(t)];
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                if (x < c.x0 || x >= c.x1 || y < c.y0 || y >= c.y1) d[static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x)] = 1.0f;
        float lo = 1.0f;
        for (std::size_t i = 0; i < area; ++i) lo = std::min(lo, d[i]);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const float v = d[static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x)];
                const float grey = v >= 1.0f || lo >= 1.0f ? 1.0f : 0.15f + 0.8f * (v - lo) / (1.0f - lo);
                const std::size_t i = (static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(out.image.width) +
                                       static_cast<std::size_t>(column[static_cast<std::size_t>(t)] + x)) * 4;
                const auto g = static_cast<std::uint8_t>(std::clamp(grey, 0.0f, 1.0f) * 255.0f + 0.5f);
                out.image.pixels[i] = out.image.pixels[i + 1] = out.image.pixels[i + 2] = g;
            }
    }
    return out;
}

} // namespace shadowlab::map
