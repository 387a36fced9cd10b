// The viewer's "shadow maps" window (Dear ImGui), over the frame's right
// side and on screen whenever the maps are shown: the shadow atlas (which
// its lights share), then each light's debug images (its map or cube
// cross, its cascades coloured), the selected light's first. And what the
// script's "layout FILE" writes: the windows' rectangles and the options
// the panel showed.
#include "ViewerSession.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace shadowlab::viewer {

namespace {

constexpr float kMapsWidth = 300.0f;  ///< the window's width, pixels
constexpr float kMargin = 8.0f;

} // namespace

std::string jsonQuoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
            out += escaped;
            continue;
        }
        out += c;
    }
    return out + "\"";
}

// The current window's screen rectangle, for layoutJson.
void ViewerSession::noteWindow(const char* name) {
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    shownWindows.emplace_back(name, glm::vec4(at.x, at.y, size.x, size.y));
}

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

std::string ViewerSession::layoutJson() const {
    std::string out = "{\n  \"windows\": [";
    for (std::size_t i = 0; i < shownWindows.size(); ++i) {
        const glm::vec4& r = shownWindows[i].second;
        char rect[160];
        std::snprintf(rect, sizeof rect, "\"x\": %.0f, \"y\": %.0f, \"width\": %.0f, \"height\": %.0f", r.x, r.y, r.z, r.w);
        out += std::string(i ? "," : "") + "\n    {\"name\": " + jsonQuoted(shownWindows[i].first) + ", " + rect + "}";
    }
    out += "\n  ],\n  \"options\": [";
    for (std::size_t i = 0; i < shownOptions.size(); ++i) {
        const ShownOption& o = shownOptions[i];
        out += std::string(i ? "," : "") + "\n    {\"light\": " + std::to_string(o.light) + ", \"key\": " + jsonQuoted(o.key) +
               ", \"enabled\": " + (o.unused.empty() ? "true" : "false") + ", \"unused\": " + jsonQuoted(o.unused) +
               ", \"preset\": " + (o.preset ? "true" : "false") + "}";
    }
    return out + "\n  ]\n}\n";
}

} // namespace shadowlab::viewer
