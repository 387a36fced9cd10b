// Rectangles of pixels on the screen (ScreenRect.h).
#include "core/ScreenRect.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

PixelRect pixelsAround(glm::vec2 lo, glm::vec2 hi, glm::ivec2 viewport) {
    const glm::vec2 size(viewport);
    const glm::vec2 pixelLo = glm::clamp(glm::floor((lo * 0.5f + 0.5f) * size) - 1.0f, glm::vec2(0.0f), size);
    const glm::vec2 pixelHi = glm::clamp(glm::ceil((hi * 0.5f + 0.5f) * size) + 1.0f, glm::vec2(0.0f), size);
    return PixelRect(static_cast<int>(pixelLo.x), static_cast<int>(pixelLo.y), static_cast<int>(pixelHi.x), static_cast<int>(pixelHi.y));
}

PixelRect screenRectOf(const Bounds& box, const glm::mat4& clipFromWorld, glm::ivec2 viewport) {
    if (box.empty()) return PixelRect(0);
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 clip = clipFromWorld * glm::vec4(box.corner(c), 1.0f);
        if (!(clip.w > 1e-6f)) return PixelRect(0, 0, viewport.x, viewport.y);
        lo = glm::min(lo, glm::vec2(clip) / clip.w);
        hi = glm::max(hi, glm::vec2(clip) / clip.w);
    }
    return pixelsAround(lo, hi, viewport);
}

namespace {
PixelRect around(const PixelRect& a, const PixelRect& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.z, b.z), std::max(a.w, b.w)}; }
} // namespace

std::vector<PixelRect> mergedRects(std::vector<PixelRect> rects, std::size_t most) {
    std::erase_if(rects, [](const PixelRect& r) { return isEmpty(r); });
    // The pairwise merges below cost the cube of the count: past a few
    // hundred, the one rectangle around them all.
    if (rects.size() > kMergeAtMost) {
        PixelRect all = rects.front();
        for (const PixelRect& r : rects) all = around(all, r);
        return {all};
    }
    // Pairs whose rectangle adds few pixels to the two (a tenth of their
    // union at most), until none do: one draw instead of two, and no pixel
    // drawn twice where they overlap.
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t a = 0; a < rects.size() && !merged; ++a)
            for (std::size_t b = a + 1; b < rects.size() && !merged; ++b) {
                const double both = area(rects[a]) + area(rects[b]) - area(intersection(rects[a], rects[b]));
                if (area(around(rects[a], rects[b])) <= 1.1 * both) {
                    rects[a] = around(rects[a], rects[b]);
                    rects.erase(rects.begin() + static_cast<long>(b));
                    merged = true;
                }
            }
    }
    // Then the cheapest pairs, until few enough. Those left may overlap:
    // the pixels they share are drawn twice (the second draw's fail the
    // depth test), still right.
    while (rects.size() > std::max<std::size_t>(most, 1)) {
        std::size_t bestA = 0, bestB = 1;
        double best = std::numeric_limits<double>::max();
        for (std::size_t a = 0; a < rects.size(); ++a)
            for (std::size_t b = a + 1; b < rects.size(); ++b) {
                const double added = area(around(rects[a], rects[b])) - area(rects[a]) - area(rects[b]);
                if (added < best) {
                    best = added;
                    bestA = a;
                    bestB = b;
                }
            }
        rects[bestA] = around(rects[bestA], rects[bestB]);
        rects.erase(rects.begin() + static_cast<long>(bestB));
    }
    return rects;
}

} // namespace shadowlab
