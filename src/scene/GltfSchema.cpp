// glTF fields the loader would take silently with a wrong type (GltfSchema.h).
#include "scene/GltfSchema.h"

#include <shadowlab/Error.h>
#include <shadowlab/Text.h>

#include <nlohmann/json.hpp>

#include <cstddef>

namespace shadowlab {

namespace {

using nlohmann::json;

// Fails unless `value` is an array of `count` numbers.
void requireNumbers(const json& value, std::size_t count, const std::string& at) {
    if (!value.is_array() || value.size() != count)
        throw Error(at + ": expected " + std::to_string(count) + " numbers, got " + text::clipMiddle(value.dump(), 80));
    for (std::size_t i = 0; i < count; ++i)
        if (!value[i].is_number()) throw Error(at + "[" + std::to_string(i) + "]: expected a number, got " + text::clipMiddle(value[i].dump(), 80));
}

} // namespace

void checkGltfTypes(std::string_view text, const std::string& file) {
    const json root = json::parse(text.begin(), text.end(), nullptr, false);
    if (root.is_discarded() || !root.is_object()) return;
    // The glTF 2.0 header: a version this loader reads, no extension it
    // must understand and does not, a default scene that exists.
    if (const auto asset = root.find("asset"); asset != root.end() && asset->is_object())
        if (const auto version = asset->find("version"); version != asset->end()) {
            const std::string v = version->is_string() ? version->get<std::string>() : std::string();
            if (v.rfind("2.", 0) != 0 || v.size() < 3 || v.find_first_not_of("0123456789", 2) != std::string::npos)
                throw Error(file + ": asset.version: expected glTF 2.x (\"2.0\"), got " + text::clipMiddle(version->dump(), 80));
        }
    if (const auto required = root.find("extensionsRequired"); required != root.end() && required->is_array())
        for (const json& name : *required)
            throw Error(file + ": extensionsRequired: " + text::clipMiddle(name.dump(), 80) +
                        " is not supported (shadowlab reads core glTF 2.0 only; export the file without it)");
    if (const auto scene = root.find("scene"); scene != root.end()) {
        const auto scenes = root.find("scenes");
        const std::size_t count = scenes != root.end() && scenes->is_array() ? scenes->size() : 0;
        if (!scene->is_number_integer() || scene->get<long long>() < 0 || static_cast<std::size_t>(scene->get<long long>()) >= count)
            throw Error(file + ": scene: expected an index into scenes (0.." + (count ? std::to_string(count - 1) : std::string("none")) + "), got " +
                        text::clipMiddle(scene->dump(), 80));
    }
    if (const auto materials = root.find("materials"); materials != root.end() && materials->is_array()) {
        for (std::size_t i = 0; i < materials->size(); ++i) {
            const json& m = (*materials)[i];
            if (!m.is_object()) continue;
            const std::string at = file + ": materials[" + std::to_string(i) + "]";
            if (const auto mode = m.find("alphaMode"); mode != m.end() && !mode->is_string())
                throw Error(at + ".alphaMode: expected \"OPAQUE\", \"MASK\" or \"BLEND\", got " + text::clipMiddle(mode->dump(), 80));
            if (const auto cutoff = m.find("alphaCutoff"); cutoff != m.end() && !cutoff->is_number())
                throw Error(at + ".alphaCutoff: expected a number in 0..1, got " + text::clipMiddle(cutoff->dump(), 80));
            if (const auto pbr = m.find("pbrMetallicRoughness"); pbr != m.end() && pbr->is_object())
                if (const auto factor = pbr->find("baseColorFactor"); factor != pbr->end())
                    requireNumbers(*factor, 4, at + ".pbrMetallicRoughness.baseColorFactor");
        }
    }
    if (const auto nodes = root.find("nodes"); nodes != root.end() && nodes->is_array()) {
        const auto cameras = root.find("cameras");
        const std::size_t cameraCount = cameras != root.end() && cameras->is_array() ? cameras->size() : 0;
        for (std::size_t i = 0; i < nodes->size(); ++i) {
            const json& n = (*nodes)[i];
            if (!n.is_object()) continue;
            const std::string at = file + ": nodes[" + std::to_string(i) + "]";
            // A node's camera must exist (it loaded silently, pointing at nothing).
            if (const auto camera = n.find("camera"); camera != n.end())
                if (!camera->is_number_integer() || camera->get<long long>() < 0 || static_cast<std::size_t>(camera->get<long long>()) >= cameraCount)
                    throw Error(at + ".camera: expected an index into cameras (" + (cameraCount ? "0.." + std::to_string(cameraCount - 1) : std::string("none")) +
                                "), got " + text::clipMiddle(camera->dump(), 80));
            for (const auto& [key, count] : {std::pair{"matrix", 16u}, std::pair{"translation", 3u}, std::pair{"rotation", 4u}, std::pair{"scale", 3u}})
                if (const auto value = n.find(key); value != n.end()) requireNumbers(*value, count, at + "." + key);
        }
    }
}

} // namespace shadowlab
