// What the viewer draws over the picture, behind the panel: the selected
// light's texel density, and the selected light in wireframe with the
// frustums its technique rendered from.
#include "ViewerSession.h"

#include <imgui.h>

#include <array>
#include <cstdint>

namespace shadowlab::viewer {

namespace {

// A segment in world space onto the window, clipped at the camera's near
// side (w > 0) so that a frustum reaching behind the viewer stays drawn.
void drawSegment(ImDrawList* draw, const glm::mat4& clipFromWorld, glm::vec2 size, glm::vec3 a, glm::vec3 b, ImU32 colour) {
    glm::vec4 ca = clipFromWorld * glm::vec4(a, 1.0f), cb = clipFromWorld * glm::vec4(b, 1.0f);
    constexpr float kNear = 1e-3f;
    if (ca.w < kNear && cb.w < kNear) return;
    if (ca.w < kNear) ca = glm::mix(ca, cb, (kNear - ca.w) / (cb.w - ca.w));
    if (cb.w < kNear) cb = glm::mix(cb, ca, (kNear - cb.w) / (ca.w - cb.w));
    auto screen = [&](const glm::vec4& c) { return ImVec2((c.x / c.w * 0.5f + 0.5f) * size.x, (0.5f - c.y / c.w * 0.5f) * size.y); };
    draw->AddLine(screen(ca), screen(cb), colour, 1.5f);
}

// The twelve edges of the volume that is [-1, 1]^3 in `lightClip`'s clip space.
void drawFrustum(ImDrawList* draw, const glm::mat4& clipFromWorld, glm::vec2 size, const glm::mat4& lightClip, ImU32 colour) {
    const glm::mat4 worldFromLight = glm::inverse(lightClip);
    std::array<glm::vec3, 8> corner{};
    for (int k = 0; k < 8; ++k) {
        const glm::vec4 p = worldFromLight * glm::vec4(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f, 1.0f);
        corner[static_cast<std::size_t>(k)] = glm::vec3(p) / p.w;
    }
    for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(k & bit)) drawSegment(draw, clipFromWorld, size, corner[static_cast<std::size_t>(k)], corner[static_cast<std::size_t>(k | bit)], colour);
}

} // namespace

void ViewerSession::drawOverlay(int width, int height) {
    const glm::vec2 windowSize(static_cast<float>(width), static_cast<float>(height));
    ImDrawList* background = ImGui::GetBackgroundDrawList();
    // The selected light's texel density over the picture, half opaque.
    if (showDensity && densityTexture.id() != 0)
        background->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(densityTexture.id())), ImVec2(0.0f, 0.0f),
                             ImVec2(windowSize.x, windowSize.y), ImVec2(0.0f, 0.0f), ImVec2(1.0f, 1.0f), IM_COL32(255, 255, 255, 150));
    // The selected light in wireframe over the picture: a spot's cone out
    // to its reach, a point light's position, a directional light's
    // direction from the target; and in blue the frustums its technique
    // rendered from last frame, fitted (a 2D map's one, a cube's six).
    if (showLight && selectedLight >= 0 && static_cast<std::size_t>(selectedLight) < lastShown.lights.size()) {
        const Light& light = lastShown.lights[static_cast<std::size_t>(selectedLight)];
        const glm::mat4 clip = lastShown.camera.clipFromView(windowSize.x / windowSize.y) * lastShown.camera.viewFromWorld();
        const ImU32 colour = IM_COL32(255, 220, 90, 220), frustumColour = IM_COL32(90, 170, 255, 200);
        auto line = [&](const glm::vec3& a, const glm::vec3& b) { drawSegment(background, clip, windowSize, a, b, colour); };
        if (light.type == LightType::Spot) {
            const glm::vec3 axis = glm::normalize(light.direction);
            const glm::vec3 side = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
            const glm::vec3 other = glm::cross(axis, side);
            const float reach = light.range > 0.0f ? light.range : 1.1f * glm::length(lastShown.camera.target - light.position);
            const float radius = reach * std::tan(glm::radians(light.outerConeDeg));
            glm::vec3 previous{};
            for (int k = 0; k <= 24; ++k) {
                const float a = 6.2831853f * static_cast<float>(k) / 24.0f;
                const glm::vec3 rim = light.position + axis * reach + radius * (std::cos(a) * side + std::sin(a) * other);
                if (k % 6 == 0) line(light.position, rim);
                if (k > 0) line(previous, rim);
                previous = rim;
            }
        } else if (light.type == LightType::Point) {
            for (const glm::vec3 d : {glm::vec3(0.3f, 0, 0), glm::vec3(0, 0.3f, 0), glm::vec3(0, 0, 0.3f)}) line(light.position - d, light.position + d);
        } else {
            const glm::vec3 target = lastShown.camera.target;
            line(target - glm::normalize(light.direction) * 3.0f, target);
        }
        for (const LightFrustum& f : renderer.lightFrustums(lastShown))
            if (f.light == selectedLight) drawFrustum(background, clip, windowSize, f.clipFromWorld, frustumColour);
    }
}

} // namespace shadowlab::viewer
