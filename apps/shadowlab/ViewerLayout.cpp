// What the viewer showed, as the script's "layout FILE" writes it: each
// window's screen rectangle (noteWindow, called by the window that is
// drawn) and each option the panel listed, enabled or why not, and whether
// a preset set it. And JSON strings for it and for the panel's overrides.
#include "ViewerSession.h"

#include <imgui.h>

#include <cstdio>

namespace shadowlab::viewer {

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
