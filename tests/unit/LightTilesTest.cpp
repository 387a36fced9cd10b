// The tiled light list's binning (core/LightTiles.h): conservative, so a
// light is listed in the tile of every pixel it can reach.
#include "core/LightTiles.h"

#include <shadowlab/Scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace shadowlab;

namespace {

bool listed(const LightTiles& t, glm::uvec2 tile, std::uint32_t light) {
    const std::size_t i = static_cast<std::size_t>(tile.y) * t.tiles.x + tile.x;
    const auto first = t.cells.begin() + t.cells[2 * i];
    return std::find(first, first + t.cells[2 * i + 1], light) != first + t.cells[2 * i + 1];
}

float uniform(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

} // namespace

// 300 spheres around a camera (in view, at the frame's edges, crossing the
// eye's plane, behind it), 2000 points on and in each: every point in
// front of the near plane that projects into the frame is in a tile that
// lists its sphere. The seed is fixed.
TEST(LightTilesTest, EveryPixelASphereReachesListsIt) {
    Camera camera;
    camera.position = {1.0f, 3.0f, 9.0f};
    camera.target = {0.0f, 0.5f, 0.0f};
    const glm::ivec2 size(317, 203);  // partial tiles at the right and top
    const glm::mat4 view = camera.viewFromWorld(), projection = camera.clipFromView(float(size.x) / float(size.y));
    std::mt19937 rng(7);
    std::vector<LightReach> reach;
    for (int k = 0; k < 300; ++k) {
        LightReach r;
        r.everywhere = k % 50 == 0;
        r.centre = glm::vec3(uniform(rng) * 30.0f - 15.0f, uniform(rng) * 10.0f - 3.0f, uniform(rng) * 30.0f - 15.0f);
        r.radius = 0.2f + uniform(rng) * 4.0f;
        reach.push_back(r);
    }
    const LightTiles tiles = binLights(reach, view, projection, size, 16);
    ASSERT_EQ(tiles.tiles, glm::uvec2(20, 13));
    int checked = 0;
    for (std::uint32_t k = 0; k < reach.size(); ++k) {
        for (int s = 0; s < 2000; ++s) {
            const glm::vec3 d = glm::normalize(glm::vec3(uniform(rng), uniform(rng), uniform(rng)) * 2.0f - 1.0f);
            const float r = reach[k].everywhere ? 20.0f * uniform(rng) : reach[k].radius * (s % 2 ? 1.0f : uniform(rng));
            const glm::vec4 clip = projection * view * glm::vec4(reach[k].centre + r * d, 1.0f);
            if (clip.w <= camera.nearPlane) continue;
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(size);
            if (pixel.x < 0.0f || pixel.y < 0.0f || pixel.x >= float(size.x) || pixel.y >= float(size.y)) continue;
            ASSERT_TRUE(listed(tiles, glm::uvec2(pixel) / 16u, k)) << "light " << k << " at pixel " << pixel.x << ", " << pixel.y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 50000);
    // And not every light everywhere: the spheres behind the camera or off
    // to the side are culled, the rest listed in part of the frame.
    EXPECT_GT(tiles.culled, 30u);
    EXPECT_LT(tiles.entries, reach.size() * tiles.tiles.x * tiles.tiles.y / 3);
}
