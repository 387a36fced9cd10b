// The viewer's panel (Dear ImGui), at a fixed place on the left (it
// collapses to its title bar): frame and pass times, the buttons and
// switches, the comparison with the reference, and per light its technique
// with every option from the technique's table (those that do not apply to
// the light greyed out, with why; those its preset set marked) and its
// position. Each change is an override line. The debug images have a
// window of their own (ViewerMaps.cpp).
#include "ViewerSession.h"

#include <shadowlab/Error.h>

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <sstream>

namespace shadowlab::viewer {

namespace {

constexpr float kPanelWidth = 340.0f;  ///< the panel's fixed place: x in [0, kPanelWidth)

} // namespace

void ViewerSession::drawPanel(int height, bool& screenshotKey) {
    // The panel, at a fixed place on the left.
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, static_cast<float>(height)));
    if (collapsePanel >= 0) ImGui::SetNextWindowCollapsed(collapsePanel == 1, ImGuiCond_Always);
    collapsePanel = -1;
    const bool open = ImGui::Begin("shadowlab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    noteWindow("shadowlab");
    if (!open) {  // collapsed to its title bar
        ImGui::End();
        return;
    }
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
    // A pass that kept the last frame's map (nothing it depends on changed) says so.
    const auto cached = [&](const std::string& pass) {
        for (const auto& [name, value] : stats.counters)
            if (name == pass + ".cached" && value > 0.0) return true;
        return false;
    };
    for (const PassTiming& p : stats.passes) {
        if (summed && p.name.rfind("shadow[", 0) == 0) continue;
        if (cached(p.name))
            ImGui::Text("  %-22s cached", p.name.c_str());
        else
            ImGui::Text("  %-22s %6.2f ms", p.name.c_str(), p.ms);
    }
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
                if (ImGui::Selectable(t.name.c_str(), t.name == light.shadow.technique)) apply(at + ".shadow.technique", jsonQuoted(t.name));
            ImGui::EndCombo();
        }
        drawOptions(light, static_cast<int>(l), at);
        ImGui::RadioButton("selected (shift + drag moves it)", &selectedLight, static_cast<int>(l));
        bool fromThis = viewFromLight == static_cast<int>(l);
        if (ImGui::Checkbox("view from this light", &fromThis)) viewFromLight = fromThis ? static_cast<int>(l) : -1;
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

// A light's technique's options, from its table: the values in effect (a
// preset's applied), those the preset set marked, those that do nothing
// for this light greyed out with the reason in their tooltip.
void ViewerSession::drawOptions(const Light& light, int index, const std::string& at) {
    const TechniqueInfo* technique = findTechnique(light.shadow.technique);
    const OptionTable* table = technique ? technique->options : nullptr;
    if (!table) return;
    const auto stored = light.shadow.options.find(table->block);
    const std::any current = stored != light.shadow.options.end() ? stored->second : table->makeDefault();
    const std::vector<std::string> fromPreset = presetKeys(light);
    for (const OptionField& f : table->fields) {
        const std::string key = at + ".shadow." + table->block + "." + f.key;
        const std::string unused = optionUnused(light, f.key);
        const bool preset = std::find(fromPreset.begin(), fromPreset.end(), f.key) != fromPreset.end();
        shownOptions.push_back({index, f.key, unused, preset});
        ImGui::BeginDisabled(!unused.empty());
        drawOption(f, current, key, preset ? f.key + " (preset)###" + f.key : f.key);
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s%s%s%s%s%s%s", unused.empty() ? "" : "not used: ", unused.c_str(), unused.empty() ? "" : ". ", f.doc.c_str(),
                              f.unit.empty() ? "" : "; ", f.unit.c_str(), preset ? " (set by the preset)" : "");
    }
}

// One option, as the control of its kind labelled `label`; `key` is its override path.
void ViewerSession::drawOption(const OptionField& f, const std::any& current, const std::string& key, const std::string& label) {
    switch (f.kind) {
    case OptionKind::Number: {
        float v = static_cast<float>(f.get(current));
        if (ImGui::SliderFloat(label.c_str(), &v, static_cast<float>(f.minimum), static_cast<float>(f.maximum), "%.4g")) {
            std::ostringstream s;
            s << v;
            apply(key, s.str());
        }
        break;
    }
    case OptionKind::Integer: {
        int v = static_cast<int>(f.get(current));
        if (ImGui::InputInt(label.c_str(), &v, 1, 100, ImGuiInputTextFlags_EnterReturnsTrue))
            apply(key, std::to_string(std::clamp(v, static_cast<int>(f.minimum), static_cast<int>(f.maximum))));
        break;
    }
    case OptionKind::Boolean: {
        bool v = f.get(current) != 0.0;
        if (ImGui::Checkbox(label.c_str(), &v)) apply(key, v ? "true" : "false");
        break;
    }
    case OptionKind::Choice: {
        const auto index = static_cast<std::size_t>(f.get(current));
        if (ImGui::BeginCombo(label.c_str(), index < f.choices.size() ? f.choices[index].c_str() : "?")) {
            for (std::size_t c = 0; c < f.choices.size(); ++c)
                if (ImGui::Selectable(f.choices[c].c_str(), c == index)) apply(key, jsonQuoted(f.choices[c]));
            ImGui::EndCombo();
        }
        break;
    }
    case OptionKind::Text: {
        char buffer[256] = {};
        const std::string v = f.getText(current);
        v.copy(buffer, sizeof buffer - 1);
        if (ImGui::InputText(label.c_str(), buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue)) apply(key, jsonQuoted(buffer));
        break;
    }
    }
}

} // namespace shadowlab::viewer
