#include "render/LightList.h"

#include "gl/Calls.h"
#include "render/RendererImpl.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>

namespace shadowlab {


void LightList::upload(const Scene& scene, const std::vector<int>& lights, const std::vector<glm::vec4>& shadows, const glm::mat4& viewFromWorld,
                       const glm::mat4& clipFromView, glm::ivec2 size) {
    std::vector<shared::ListedLight> listed;
    std::vector<LightReach> reach;
    listed.reserve(lights.size());
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const Light& light = scene.lights[static_cast<std::size_t>(lights[k])];
        const shared::LightUniforms u = lightUniforms(light);
        listed.push_back({u.radiance, u.position, u.direction, u.params, k < shadows.size() ? shadows[k] : glm::vec4(0.0f)});
        reach.push_back(reachOf(light));
    }
    tiles_ = binLights(reach, viewFromWorld, clipFromView, size, SL_LIGHT_TILE_SIZE, SL_LIGHT_SLICES);
    const std::size_t lightBytes = std::max<std::size_t>(listed.size(), 1) * sizeof(shared::ListedLight);
    const std::size_t cellBytes = sizeof(glm::uvec4) + sizeof(glm::vec4) + tiles_.cells.size() * sizeof(std::uint32_t);
    gl::reserveBuffer(lights_, lightBytes_, lightBytes);
    gl::reserveBuffer(cells_, cellBytes_, cellBytes);
    if (!listed.empty()) gl::namedBufferSubData(lights_.id(), 0, static_cast<GLsizeiptr>(listed.size() * sizeof(shared::ListedLight)), listed.data());
    // The header (lighting.frag's LightTiles): tiling, then the slices' depths.
    const glm::uvec4 header(tiles_.tileSize, tiles_.tiles.x, tiles_.tiles.y, tiles_.slices);
    const glm::vec4 slicing(tiles_.sliceNear, tiles_.sliceScale, 0.0f, 0.0f);
    gl::namedBufferSubData(cells_.id(), 0, sizeof header, &header);
    gl::namedBufferSubData(cells_.id(), sizeof header, sizeof slicing, &slicing);
    gl::namedBufferSubData(cells_.id(), sizeof header + sizeof slicing, static_cast<GLsizeiptr>(tiles_.cells.size() * sizeof(std::uint32_t)),
                         tiles_.cells.data());
}

void LightList::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_LIGHT_LIST, lights_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_LIGHT_TILES, cells_.id());
}

} // namespace shadowlab
