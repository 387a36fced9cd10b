// compare's pixel classes and edge band (EdgeBand.h).
#include "reference/EdgeBand.h"

#include <algorithm>

namespace shadowlab::reference {

std::vector<Extension> surfaceExtensions(const Scene& scene, const SurfaceBuffer& surfaces, const std::vector<SurfaceSample>& samples) {
    const int w = surfaces.width, h = surfaces.height;
    const glm::mat4 worldFromClip = glm::inverse(scene.camera.clipFromView(static_cast<float>(w) / static_cast<float>(h)) * scene.camera.viewFromWorld());
    const glm::vec3 eye = scene.camera.position;
    std::vector<Extension> out;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const reference::SurfaceSample& s = samples[i];
            if (!s.valid) continue;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const reference::SurfaceSample& t = samples[static_cast<std::size_t>(ny) * w + nx];
                    if (t.valid) {
                        const glm::vec3 d = t.position - s.position;
                        // Same surface: within about 6 degrees of the tangent plane, normals alike.
                        if (std::fabs(glm::dot(d, s.normal)) <= 0.1f * glm::length(d) + 1e-6f && glm::dot(s.normal, t.normal) > 0.9f) continue;
                    }
                    // Rows are stored top first.
                    const glm::vec4 ndc((static_cast<float>(nx) + 0.5f) / static_cast<float>(w) * 2.0f - 1.0f,
                                        1.0f - (static_cast<float>(ny) + 0.5f) / static_cast<float>(h) * 2.0f, 0.0f, 1.0f);
                    const glm::vec4 p = worldFromClip * ndc;
                    const glm::vec3 dir = glm::normalize(glm::vec3(p) / p.w - eye);
                    const float facing = glm::dot(dir, s.normal);
                    if (std::fabs(facing) < 1e-4f) continue;
                    const float along = glm::dot(s.position - eye, s.normal) / facing;
                    if (!(along > 0.0f)) continue;
                    out.push_back({i, out.size(), eye + along * dir});
                }
        }
    return out;
}


PixelClasses classify(const Light& light, const std::vector<SurfaceSample>& samples, const SurfaceBuffer& surfaces,
                      const std::vector<float>& exact, float litThreshold, ImageGray8& reach) {
    const int w = surfaces.width, h = surfaces.height;
    const std::size_t n = static_cast<std::size_t>(w) * h;
    PixelClasses classes{w, h, lightReach(light, samples), std::vector<std::uint8_t>(n, 0), {}};
    std::vector<std::uint8_t>& receiver = classes.receiver;
    std::vector<std::uint8_t>& exactLit = classes.exactLit;
    reach = {w, h, std::vector<std::uint8_t>(n, 0)};
    for (std::size_t i = 0; i < n; ++i) {
        receiver[i] = receiver[i] && surfaces.normal[i].w >= 0.5f;
        reach.pixels[i] = receiver[i] ? 255 : 0;
        exactLit[i] = receiver[i] && exact[i] >= litThreshold;
    }
    return classes;
}

void markEdgeBand(PixelClasses& classes, const std::vector<Extension>& extensions, const std::vector<float>& extensionExact,
                  float litThreshold) {
    const int w = classes.w, h = classes.h;
    const std::vector<std::uint8_t>& receiver = classes.receiver;
    const std::vector<std::uint8_t>& exactLit = classes.exactLit;
    std::vector<std::uint8_t>& edge = classes.edge;
    edge.assign(static_cast<std::size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (!receiver[i]) continue;
            for (int dy = -1; dy <= 1 && !edge[i]; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
                    if (receiver[j] && exactLit[j] != exactLit[i]) { edge[i] = 1; break; }
                }
        }
    for (const Extension& e : extensions)
        if (receiver[e.pixel] && !edge[e.pixel] && (extensionExact[e.index] >= litThreshold) != (exactLit[e.pixel] != 0))
            edge[e.pixel] = 1;
}

void widenEdgeBand(PixelClasses& classes, int band) {
    const int w = classes.w, h = classes.h;
    for (int pass = 1; pass < band; ++pass) {
        const std::vector<std::uint8_t> before = classes.edge;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * w + x;
                if (!classes.receiver[i] || before[i]) continue;
                for (int dy = -1; dy <= 1 && !classes.edge[i]; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        if (before[static_cast<std::size_t>(ny) * w + nx]) { classes.edge[i] = 1; break; }
                    }
            }
    }
}

} // namespace shadowlab::reference
