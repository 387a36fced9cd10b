// The viewer's panel (Dear ImGui), at a fixed place on the left: frame and
// pass times, the buttons and switches, the comparison with the reference,
// and per light its technique with every option from the technique's table,
// its debug images and its position. Each change is an override line.
#include "ViewerSession.h"

#include <shadowlab/Error.h>

#include <imgui.h>

#include <cstdint>
#include <sstream>

namespace shadowlab::viewer {

namespace {

constexpr float kPanelWidth = 340.0f;  ///< the panel's fixed place: x in [0, kPanelWidth)

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

} // namespace

void ViewerSession::drawPanel(int height, bool& screenshotKey) {
    // The panel, at a fixed place on the left.
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, static_cast<float>(height)));
    ImGui::Begin("shadowlab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::TextUnformatted(scene.name.c_str());
    if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", error.c_str());
    ImGui::Text("%.1f ms a frame, t = %.2f s %s", frameTimes.empty() ? 0.0 : static_cast<double>(frameTimes.back()), seconds, playing ? "(playing)" : "");
    if (!frameTimes.empty()) {
        std::vector<float> values(frameTimes.begin(), frameTimes.end());
        ImGui::PlotLines("##frames", values.data(), static_cast<int>(values.size()), 0, "frame ms", 0.0f, 60.0f, ImVec2(kPanelWidth - 20.0f, 50.0f));
    }
    // The passes, a light's shadow passes summed into one line past a dozen
    // (a scene of many lights would push the rest off the panel).
    std::size_t shadowPasses = 0;
    double shadowMs = 0.0;
    for (const PassTiming& p : stats.passes)
        if (p.name.rfind("shadow[", 0) == 0) {
            ++shadowPasses;
            shadowMs += p.ms;
        }
    const bool summed = shadowPasses > 12;
    if (summed) ImGui::Text("  %-22s %6.2f ms", ("shadow[*] (" + std::to_string(shadowPasses) + " passes)").c_str(), shadowMs);
    for (const PassTiming& p : stats.passes)
        if (!summed || p.name.rfind("shadow[", 0) != 0) ImGui::Text("  %-22s %6.2f ms", p.name.c_str(), p.ms);
    if (ImGui::Button("reset camera (R)")) {
        orbit.from(scene.camera);
        cameraMoved = false;
    }
    ImGui::SameLine();
    if (ImGui::Button(playing ? "pause (space)" : "play (space)")) playing = !playing;
    if (ImGui::Button("screenshot (F12)")) screenshotKey = true;
    ImGui::Checkbox("show shadow maps", &showDebug);
    ImGui::SameLine();
    ImGui::Checkbox("show light", &showLight);
    ImGui::Checkbox("texel density", &showDensity);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The selected light's shadow-map texels per screen pixel over the picture: green about one, red blocky (a texel over many pixels), blue wasted; grey outside the map");
    ImGui::SameLine();
    if (ImGui::Button("compare (C)") && !tracing) {
        referenceAsked = true;
        referenceAskedAt = frame;
    }
    drawComparison();
    // The shadow atlas (technique map, atlas), which its lights share: shown
    // here once, each light's own tiles under the light.
    if (showDebug)
        for (std::size_t d = 0; d < debugImages.size() && d < debugTextures.size(); ++d)
            if (debugImages[d].kind == DebugImageKind::Atlas &&
                ImGui::CollapsingHeader("shadow atlas", ImGuiTreeNodeFlags_DefaultOpen)) {
                const float w = kPanelWidth - 30.0f;
                const float h = w * static_cast<float>(debugImages[d].image.height) / static_cast<float>(std::max(debugImages[d].image.width, 1));
                ImGui::TextUnformatted("each light's tiles outlined in a colour of its own");
                ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(debugTextures[d].id())), ImVec2(w, h));
            }
    ImGui::Text("GL objects: %ld", liveGlObjects());
    if (fromFile) {
        ImGui::SameLine();
        if (ImGui::Button("save scene")) {
            // Into the scene file itself: it is read again, now with the settings in it.
            try {
                save(args.scene);
                overrides.made.clear();
            } catch (const Error& e) {
                error = e.what();
            }
        }
    }
    const std::vector<TechniqueInfo> all = techniques();
    for (std::size_t l = 0; l < scene.lights.size(); ++l) drawLight(l, all);
    ImGui::End();
}

// The reference being traced, or the last comparison's numbers and error images.
void ViewerSession::drawComparison() {
    if (tracing) {
        ImGui::ProgressBar(static_cast<float>(tracing->job->progress()), ImVec2(kPanelWidth - 100.0f, 0.0f), "tracing the reference");
        ImGui::SameLine();
        if (ImGui::Button("cancel")) tracing.reset();
    } else if (referenceAsked) {
        ImGui::TextUnformatted("tracing the reference ...");
    }
    if (!referenceLines.empty()) {
        for (const std::string& line : referenceLines) ImGui::TextWrapped("%s", line.c_str());
        for (std::size_t r = 0; r < referenceTextures.size(); ++r) {
            const float w = kPanelWidth - 30.0f;
            const float h = w * static_cast<float>(referenceImages[r].height) / static_cast<float>(std::max(referenceImages[r].width, 1));
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(referenceTextures[r].id())), ImVec2(w, h));
        }
        if (ImGui::Button("hide comparison")) {
            referenceLines.clear();
            referenceImages.clear();
            freeReferenceTextures();
        }
    }
}

void ViewerSession::drawLight(std::size_t l, const std::vector<TechniqueInfo>& all) {
    const Light& light = scene.lights[l];
    const std::string at = "lights[" + std::to_string(l) + "]";
    ImGui::PushID(static_cast<int>(l));
    if (ImGui::CollapsingHeader((at + " " + light.name).c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        // Its technique, then every option of it from its table.
        if (ImGui::BeginCombo("technique", light.shadow.technique.c_str())) {
            for (const TechniqueInfo& t : all)
                if (ImGui::Selectable(t.name.c_str(), t.name == light.shadow.technique)) apply(at + ".shadow.technique", jsonString(t.name));
            ImGui::EndCombo();
        }
        drawOptions(light, at);
        ImGui::RadioButton("selected (shift + drag moves it)", &selectedLight, static_cast<int>(l));
        bool fromThis = viewFromLight == static_cast<int>(l);
        if (ImGui::Checkbox("view from this light", &fromThis)) viewFromLight = fromThis ? static_cast<int>(l) : -1;
        // Its debug images (a map, a cube's cross), refreshed every few frames.
        if (showDebug)
            for (std::size_t d = 0; d < debugImages.size() && d < debugTextures.size(); ++d)
                if (debugImages[d].light == static_cast<int>(l) &&
                    debugImages[d].kind != DebugImageKind::Atlas) {
                    const float w = kPanelWidth - 30.0f;
                    const float h = w * static_cast<float>(debugImages[d].image.height) / static_cast<float>(std::max(debugImages[d].image.width, 1));
                    ImGui::TextUnformatted(debugImages[d].name.c_str());
                    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(debugTextures[d].id())), ImVec2(w, h));
                }
        // Where the light is: point and spot lights move with the sliders.
        if (light.type != LightType::Directional) {
            glm::vec3 p = light.position;
            if (ImGui::DragFloat3("position", &p.x, 0.05f)) {
                std::ostringstream s;
                s << "[" << p.x << ", " << p.y << ", " << p.z << "]";
                apply(at + ".position", s.str());
            }
        }
    }
    ImGui::PopID();
}

// A light's technique's options, from its table.
void ViewerSession::drawOptions(const Light& light, const std::string& at) {
    const TechniqueInfo* technique = findTechnique(light.shadow.technique);
    const OptionTable* table = technique ? technique->options : nullptr;
    if (table) {
        const auto stored = light.shadow.options.find(table->block);
        const std::any current = stored != light.shadow.options.end() ? stored->second : table->makeDefault();
        for (const OptionField& f : table->fields) {
            const std::string key = at + ".shadow." + table->block + "." + f.key;
            drawOption(f, current, key);
        }
    }
}

// One option, as the control of its kind; `key` is its override path.
void ViewerSession::drawOption(const OptionField& f, const std::any& current, const std::string& key) {
    switch (f.kind) {
    case OptionKind::Number: {
        float v = static_cast<float>(f.get(current));
        if (ImGui::SliderFloat(f.key.c_str(), &v, static_cast<float>(f.minimum), static_cast<float>(f.maximum), "%.4g")) {
            std::ostringstream s;
            s << v;
            apply(key, s.str());
        }
        break;
    }
    case OptionKind::Integer: {
        int v = static_cast<int>(f.get(current));
        if (ImGui::InputInt(f.key.c_str(), &v, 1, 100, ImGuiInputTextFlags_EnterReturnsTrue))
            apply(key, std::to_string(std::clamp(v, static_cast<int>(f.minimum), static_cast<int>(f.maximum))));
        break;
    }
    case OptionKind::Boolean: {
        bool v = f.get(current) != 0.0;
        if (ImGui::Checkbox(f.key.c_str(), &v)) apply(key, v ? "true" : "false");
        break;
    }
    case OptionKind::Choice: {
        const auto index = static_cast<std::size_t>(f.get(current));
        if (ImGui::BeginCombo(f.key.c_str(), index < f.choices.size() ? f.choices[index].c_str() : "?")) {
            for (std::size_t c = 0; c < f.choices.size(); ++c)
                if (ImGui::Selectable(f.choices[c].c_str(), c == index)) apply(key, jsonString(f.choices[c]));
            ImGui::EndCombo();
        }
        break;
    }
    case OptionKind::Text: {
        char buffer[256] = {};
        const std::string v = f.getText(current);
        v.copy(buffer, sizeof buffer - 1);
        if (ImGui::InputText(f.key.c_str(), buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue)) apply(key, jsonString(buffer));
        break;
    }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s%s%s", f.doc.c_str(), f.unit.empty() ? "" : "; ", f.unit.c_str());
}

} // namespace shadowlab::viewer
