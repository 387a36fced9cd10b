// Technique "map": the shadow atlas's tiles one by one (atlas/Tiles.h).
#include "techniques/map/atlas/Tiles.h"

#include "geometry/LightTiles.h"
#include "techniques/map/fit/Cameras.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace shadowlab::map {

float screenExtent(const Light& light, const FrameInfo& frame) {
    const auto ndc = screenRectOf(reachOf(light), frame.viewFromWorld, frame.clipFromView);
    if (!ndc) return 0.0f;
    const glm::vec2 pixels = (glm::vec2(ndc->z, ndc->w) - glm::vec2(ndc->x, ndc->y)) * 0.5f * glm::vec2(frame.viewport);
    return std::max(pixels.x, pixels.y);
}

shared::AtlasTile tileOf(const glm::mat4& clipFromWorld, float projectionY, glm::ivec2 origin, int side, int atlas, const TexelRect& covered) {
    const float s = static_cast<float>(atlas);
    const glm::vec2 lo = glm::vec2(origin) / s, extent = glm::vec2(static_cast<float>(side) / s);
    const glm::mat4 toTile = glm::translate(glm::mat4(1.0f), glm::vec3(lo + 0.5f * extent, 0.5f)) *
                             glm::scale(glm::mat4(1.0f), glm::vec3(0.5f * extent, 0.5f));
    shared::AtlasTile t{};
    t.atlasFromWorld = toTile * clipFromWorld;
    const float half = 0.5f / s;
    t.uvClamp = glm::vec4(lo + half, lo + extent - half);
    const glm::vec2 o(origin);
    t.casters = covered.empty() ? glm::vec4(2.0f, 2.0f, -2.0f, -2.0f)
                                : glm::vec4((o + glm::vec2(covered.x0, covered.y0) + 0.5f) / s, (o + glm::vec2(covered.x1, covered.y1) - 0.5f) / s);
    t.params = glm::vec4(2.0f / (static_cast<float>(side) * projectionY), covered.empty() ? 0.0f : 1.0f, 0.0f, 0.0f);
    return t;
}

bool castsIntoTile(const FrameInfo& frame, const MapLight& p, int t, std::size_t i) {
    if (!frame.items[i].castsShadows) return false;
    return p.cube() ? (p.faceMask(i) & (1u << t)) != 0 : castsInto(p.camera, frame, i, false);
}

gl::Sampler atlasSampler(bool compare) {
    gl::Sampler s;
    const GLenum filter = compare ? GL_LINEAR : GL_NEAREST;
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, filter);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, filter);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (compare) {
        glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    return s;
}

} // namespace shadowlab::map
