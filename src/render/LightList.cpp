#include "render/LightList.h"

#include "render/RendererImpl.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>

namespace shadowlab {

namespace {

// A sphere around what the light reaches: its range, or for a spot the
// smallest sphere around the cone cut off at the range (through the apex
// and the rim for an outer half-angle under 45 degrees, around the rim
// above it).
LightReach reachOf(const Light& light) {
    LightReach r;
    if (light.type == LightType::Directional || !(light.range > 0.0f)) return r;  // everywhere
    r.everywhere = false;
    r.centre = light.position;
    r.radius = light.range;
    if (light.type == LightType::Spot) {
        const float angle = glm::radians(light.outerConeDeg);
        const glm::vec3 axis = glm::normalize(light.direction);
        const float along = angle < glm::radians(45.0f) ? light.range / (2.0f * std::cos(angle)) : light.range * std::cos(angle);
        const float radius = angle < glm::radians(45.0f) ? along : light.range * std::sin(angle);
        r.centre = light.position + axis * along;
        r.radius = radius * 1.001f;  // rounding: never smaller than the cone
    }
    return r;
}

} // namespace

void LightList::upload(const Scene& scene, const std::vector<int>& lights, const glm::mat4& viewFromWorld, const glm::mat4& clipFromView,
                       glm::ivec2 size) {
    std::vector<shared::ListedLight> listed;
    std::vector<LightReach> reach;
    listed.reserve(lights.size());
    for (int i : lights) {
        const Light& light = scene.lights[static_cast<std::size_t>(i)];
        const shared::LightUniforms u = lightUniforms(light);
        listed.push_back({u.radiance, u.position, u.direction, u.params});
        reach.push_back(reachOf(light));
    }
    tiles_ = binLights(reach, viewFromWorld, clipFromView, size, SL_LIGHT_TILE_SIZE);
    const std::size_t lightBytes = std::max<std::size_t>(listed.size(), 1) * sizeof(shared::ListedLight);
    const std::size_t cellBytes = sizeof(glm::uvec4) + tiles_.cells.size() * sizeof(std::uint32_t);
    gl::reserveBuffer(lights_, lightBytes_, lightBytes);
    gl::reserveBuffer(cells_, cellBytes_, cellBytes);
    if (!listed.empty()) glNamedBufferSubData(lights_.id(), 0, static_cast<GLsizeiptr>(listed.size() * sizeof(shared::ListedLight)), listed.data());
    const glm::uvec4 header(tiles_.tileSize, tiles_.tiles.x, tiles_.tiles.y, 0u);
    glNamedBufferSubData(cells_.id(), 0, sizeof header, &header);
    glNamedBufferSubData(cells_.id(), sizeof header, static_cast<GLsizeiptr>(tiles_.cells.size() * sizeof(std::uint32_t)), tiles_.cells.data());
}

void LightList::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_LIGHT_LIST, lights_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_LIGHT_TILES, cells_.id());
}

} // namespace shadowlab
