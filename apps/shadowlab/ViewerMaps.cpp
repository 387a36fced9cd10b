// The viewer's "shadow maps" window (Dear ImGui), over the frame's right
// side and on screen whenever the maps are shown: each light's debug
// images (its map or cube cross, its cascades coloured), the selected
// light's first, then the shadow atlas its lights share.
#include "ViewerSession.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>

namespace shadowlab::viewer {

namespace {

constexpr float kMapsWidth = 300.0f;  ///< the window's width, pixels
constexpr float kMargin = 8.0f;

} // namespace

void ViewerSession::drawMapsWindow(int width, int height) {
    if (!showDebug) return;
    const float w = std::min(kMapsWidth, std::max(static_cast<float>(width) - 2.0f * kMargin, 120.0f));
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(width) - w - kMargin, kMargin), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, static_cast<float>(height) - 2.0f * kMargin), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("shadow maps", &showDebug, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize)) {
        noteWindow("shadow maps");
        ImGui::End();
        return;
    }
    noteWindow("shadow maps");
    const float imageWidth = w - 20.0f;
    const auto show = [&](const DebugImage& image, const ImageTexture& texture) {
        const float h = imageWidth * static_cast<float>(image.image.height) / static_cast<float>(std::max(image.image.width, 1));
        ImGui::TextUnformatted(image.name.c_str());
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture.id())), ImVec2(imageWidth, h));
    };
    const std::size_t n = std::min(debugImages.size(), debugTextures.size());
    if (n == 0) ImGui::TextWrapped("No images: the lights' techniques draw no map (technique map has them).");
    // The selected light's first, then the other lights' in order, then the atlas they share.
    std::vector<std::size_t> order;
    for (std::size_t d = 0; d < n; ++d)
        if (debugImages[d].light == selectedLight && debugImages[d].kind != DebugImageKind::Atlas) order.push_back(d);
    for (std::size_t d = 0; d < n; ++d)
        if (debugImages[d].light != selectedLight && debugImages[d].kind != DebugImageKind::Atlas) order.push_back(d);
    for (std::size_t d = 0; d < n; ++d)
        if (debugImages[d].kind == DebugImageKind::Atlas) order.push_back(d);
    for (std::size_t d : order) show(debugImages[d], debugTextures[d]);
    ImGui::End();
}

} // namespace shadowlab::viewer
