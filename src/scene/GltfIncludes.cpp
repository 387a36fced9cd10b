// A scene document's glTF includes (GltfScene.h, expandGltfIncludes): a
// light {"gltf": FILE} stands for FILE's lights, a camera {"gltf": FILE,
// "index": N} for its camera N (docs/scene-format.md).
#include "scene/GltfScene.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <algorithm>
#include <string>

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Include `value` ({"gltf": FILE, ...}) of a scene document at `at`: FILE's
// document with `options`.
json includedDocument(const json& value, const std::vector<std::string>& keys, const std::string& source, const std::string& at,
                      const fs::path& baseDir, const GltfSceneOptions& options, std::vector<std::string>& notes) {
    const auto fail = [&](const std::string& what) { throw Error(text::escapeControl(source + ": " + at + what)); };
    for (const auto& [key, v] : value.items())
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) fail("." + key + ": unknown key beside \"gltf\"");
    if (!value["gltf"].is_string() || value["gltf"].get<std::string>().empty()) fail(".gltf: expected the name of a .gltf or .glb file");
    const fs::path file = baseDir / value["gltf"].get<std::string>();
    if (!isGltfPath(file)) fail(".gltf: " + value["gltf"].get<std::string>() + ": expected a .gltf or .glb file");
    try {
        return gltfSceneDocument(file, options, notes);
    } catch (const Error& e) {
        fail(".gltf: " + std::string(e.what()));
    }
    return nullptr;
}

bool isInclude(const json& value) { return value.is_object() && value.contains("gltf"); }

} // namespace

void expandGltfIncludes(json& doc, const std::string& source, const fs::path& baseDir, std::vector<std::string>& notes) {
    if (const auto lights = doc.find("lights"); lights != doc.end() && lights->is_array() && std::any_of(lights->begin(), lights->end(), isInclude)) {
        json expanded = json::array();
        for (std::size_t i = 0; i < lights->size(); ++i) {
            const json& light = (*lights)[i];
            if (!isInclude(light)) {
                expanded.push_back(light);
                continue;
            }
            const std::string at = "lights[" + std::to_string(i) + "]";
            const json included = includedDocument(light, {"gltf"}, source, at, baseDir, GltfSceneOptions{0, false}, notes);
            if (included["lights"].empty()) throw Error(text::escapeControl(source + ": " + at + ".gltf: " + light["gltf"].get<std::string>() + " has no KHR_lights_punctual light in its scene"));
            for (const json& l : included["lights"]) expanded.push_back(l);
        }
        *lights = std::move(expanded);
    }
    if (const auto camera = doc.find("camera"); camera != doc.end() && isInclude(*camera)) {
        int index = 0;
        if (camera->contains("index")) {
            const json& n = (*camera)["index"];
            if (!n.is_number_integer() || n.get<long long>() < 0 || n.get<long long>() > 65535)
                throw Error(text::escapeControl(source + ": camera.index: expected an integer from 0, got " + n.dump()));
            index = n.get<int>();
        }
        json included = includedDocument(*camera, {"gltf", "index"}, source, "camera", baseDir, GltfSceneOptions{index, false}, notes);
        if (included["camera"].is_null()) throw Error(text::escapeControl(source + ": camera.gltf: " + (*camera)["gltf"].get<std::string>() + " places no camera in its scene"));
        *camera = std::move(included["camera"]);
    }
}

} // namespace shadowlab
