// The clustered light list's binning (geometry/LightTiles.h): conservative, so
// a light is listed in the cluster (tile and depth slice) of every pixel
// it can reach.
#include "geometry/LightTiles.h"

#include <shadowlab/Scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace shadowlab;

namespace {

// The cluster of a pixel in `tile` at view depth `depth`: its first cell and count.
std::size_t clusterOf(const LightTiles& t, glm::uvec2 tile, float depth) {
    return (static_cast<std::size_t>(t.sliceOf(depth)) * t.tiles.y + tile.y) * t.tiles.x + tile.x;
}

bool listed(const LightTiles& t, glm::uvec2 tile, float depth, std::uint32_t light) {
    const std::size_t i = clusterOf(t, tile, depth);
    const auto first = t.cells.begin() + t.cells[2 * i];
    return std::find(first, first + t.cells[2 * i + 1], light) != first + t.cells[2 * i + 1];
}

float uniform(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

} // namespace

// 300 spheres around a camera (in view, at the frame's edges, crossing the
// eye's plane, behind it), 2000 points on and in each: every point in
// front of the near plane that projects into the frame is in a cluster
// (its tile, the slice of its view depth) that lists its sphere. The seed
// is fixed. And the slices pay: a point's cluster lists fewer lights than
// its whole tile (one slice) does.
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
    const LightTiles tiles = binLights(reach, view, projection, size, 16, 16);
    const LightTiles flat = binLights(reach, view, projection, size, 16, 1);
    ASSERT_EQ(tiles.tiles, glm::uvec2(20, 13));
    ASSERT_EQ(tiles.slices, 16u);
    int checked = 0;
    double inCluster = 0.0, inTile = 0.0;
    for (std::uint32_t k = 0; k < reach.size(); ++k) {
        for (int s = 0; s < 2000; ++s) {
            const glm::vec3 d = glm::normalize(glm::vec3(uniform(rng), uniform(rng), uniform(rng)) * 2.0f - 1.0f);
            const float r = reach[k].everywhere ? 20.0f * uniform(rng) : reach[k].radius * (s % 2 ? 1.0f : uniform(rng));
            const glm::vec4 clip = projection * view * glm::vec4(reach[k].centre + r * d, 1.0f);
            if (clip.w <= camera.nearPlane) continue;
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(size);
            if (pixel.x < 0.0f || pixel.y < 0.0f || pixel.x >= float(size.x) || pixel.y >= float(size.y)) continue;
            ASSERT_TRUE(listed(tiles, glm::uvec2(pixel) / 16u, clip.w, k)) << "light " << k << " at pixel " << pixel.x << ", " << pixel.y << ", depth " << clip.w;
            ASSERT_TRUE(listed(flat, glm::uvec2(pixel) / 16u, clip.w, k)) << "light " << k << " at pixel " << pixel.x << ", " << pixel.y;
            inCluster += tiles.cells[2 * clusterOf(tiles, glm::uvec2(pixel) / 16u, clip.w) + 1];
            inTile += flat.cells[2 * clusterOf(flat, glm::uvec2(pixel) / 16u, clip.w) + 1];
            ++checked;
        }
    }
    EXPECT_GT(checked, 50000);
    // And not every light everywhere: the spheres behind the camera or off
    // to the side are culled, the rest listed in part of the frame.
    EXPECT_GT(tiles.culled, 30u);
    EXPECT_LT(flat.entries, reach.size() * flat.tiles.x * flat.tiles.y / 3);
    // Measured: 14.6 lights a point's cluster on average, against 29.8 its
    // tile's (300 spheres in a 30 m box, many overlapping); the bar, 0.6x.
    EXPECT_LT(inCluster, 0.6 * inTile) << inCluster / checked << " lights a cluster, " << inTile / checked << " a tile";
}

// 200 spots of half-angles 5-85 degrees (reachOf: the sphere around the
// cone, and the cone), 2000 points inside each cone within its range
// (half of them on its side or at its range): every point in view is in a
// cluster that lists its spot. The cone pays: a point's cluster lists
// fewer lights than with the sphere alone. Fixed seed.
TEST(LightTilesTest, EveryPixelASpotReachesListsIt) {
    Camera camera;
    camera.position = {0.0f, 16.0f, 24.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    const glm::ivec2 size(400, 300);
    const glm::mat4 view = camera.viewFromWorld(), projection = camera.clipFromView(float(size.x) / float(size.y));
    std::mt19937 rng(11);
    std::vector<LightReach> reach, spheres;
    std::vector<Light> spots;
    for (int k = 0; k < 200; ++k) {
        Light light;
        light.type = LightType::Spot;
        light.position = glm::vec3(uniform(rng) * 40.0f - 20.0f, uniform(rng) * 6.0f, uniform(rng) * 30.0f - 15.0f);
        light.direction = glm::normalize(glm::vec3(uniform(rng), uniform(rng), uniform(rng)) * 2.0f - 1.0f);
        light.outerConeDeg = 5.0f + 80.0f * uniform(rng);
        light.innerConeDeg = light.outerConeDeg * 0.5f;
        light.range = 1.0f + 6.0f * uniform(rng);
        spots.push_back(light);
        reach.push_back(reachOf(light));
        ASSERT_TRUE(reach.back().cone);
        spheres.push_back(reach.back());
        spheres.back().cone = false;
    }
    const LightTiles tiles = binLights(reach, view, projection, size, 16, 32);
    const LightTiles sphereTiles = binLights(spheres, view, projection, size, 16, 32);
    int checked = 0;
    double withCone = 0.0, withSphere = 0.0;
    for (std::uint32_t k = 0; k < spots.size(); ++k) {
        const Light& light = spots[k];
        const glm::vec3 axis = glm::normalize(light.direction);
        const glm::vec3 side = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
        const glm::vec3 up = glm::cross(side, axis);
        const float angle = glm::radians(light.outerConeDeg);
        for (int s = 0; s < 2000; ++s) {
            // A direction inside the cone (on its side for odd s), a distance within the range (at it for s % 4 == 2).
            const float off = angle * (s % 2 ? 0.9999f : uniform(rng)), turn = 6.2831853f * uniform(rng);
            const glm::vec3 d = std::cos(off) * axis + std::sin(off) * (std::cos(turn) * side + std::sin(turn) * up);
            const float r = light.range * (s % 4 == 2 ? 0.9999f : uniform(rng));
            const glm::vec4 clip = projection * view * glm::vec4(light.position + r * d, 1.0f);
            if (clip.w <= camera.nearPlane) continue;
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(size);
            if (pixel.x < 0.0f || pixel.y < 0.0f || pixel.x >= float(size.x) || pixel.y >= float(size.y)) continue;
            ASSERT_TRUE(listed(tiles, glm::uvec2(pixel) / 16u, clip.w, k)) << "spot " << k << " at pixel " << pixel.x << ", " << pixel.y << ", depth " << clip.w;
            withCone += tiles.cells[2 * clusterOf(tiles, glm::uvec2(pixel) / 16u, clip.w) + 1];
            withSphere += sphereTiles.cells[2 * clusterOf(sphereTiles, glm::uvec2(pixel) / 16u, clip.w) + 1];
            ++checked;
        }
    }
    EXPECT_GT(checked, 100000);
    // Measured: 4.86 lights a point's cluster with the cones, 6.58 with
    // the spheres alone; the bar, 0.85x (and fewer entries in all).
    EXPECT_LT(tiles.entries, sphereTiles.entries);
    EXPECT_LT(withCone, 0.85 * withSphere) << withCone / checked << " lights a cluster with cones, " << withSphere / checked << " with spheres";
}
