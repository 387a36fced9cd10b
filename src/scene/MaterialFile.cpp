// The `materials` of a scene file, by name (nodes refer to them), and the
// image files they and spot lights' projectors read as textures.
#include "scene/SceneParts.h"

#include "scene/MeshFile.h"

#include <shadowlab/Text.h>

#include <stb_image.h>

#include <cstdint>
#include <system_error>
#include <utility>

namespace shadowlab::scenefile {

namespace fs = std::filesystem;

ImageRGBA8 loadTexture(const Reader& r, const fs::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (status.type() == fs::file_type::none) r.fail("texture " + name + ": " + ec.message());
    if (!fs::exists(status)) r.fail("texture file not found: " + name);
    if (!fs::is_regular_file(status)) r.fail("texture " + name + " is not a regular file");
    int w = 0, h = 0, channels = 0;
    // The header first: a small PNG may declare a size that cannot be allocated.
    if (stbi_info(name.c_str(), &w, &h, &channels) &&
        (w > kMaxImageSide || h > kMaxImageSide || static_cast<std::size_t>(w) * static_cast<std::size_t>(h) > kMaxImagePixels))
        r.fail(name + ": " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " + std::to_string(kMaxImageSide) +
               " pixels per side and " + std::to_string(kMaxImagePixels) + " pixels");
    stbi_uc* data = stbi_load(name.c_str(), &w, &h, &channels, 4);
    if (!data) r.fail(name + ": not a readable image (" + std::string(stbi_failure_reason()) + ")");
    ImageRGBA8 image{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 4)};
    stbi_image_free(data);
    return image;
}

void SceneBuilder::readMaterials(const Reader& r) {
    r.requireObject();
    for (const auto& [name, _] : r.value().items()) {
        const Reader m = r.child(name);
        m.checkKeys({"baseColor", "baseColorTexture", "ambient", "diffuse", "specular", "shininess", "alpha", "alphaMode", "alphaCutoff"});
        Material mat;
        mat.name = name;
        mat.baseColor = m.color("baseColor", mat.baseColor);
        mat.ambient = m.color("ambient", mat.ambient);
        mat.diffuse = m.color("diffuse", mat.diffuse);
        mat.specular = m.color("specular", mat.specular);
        mat.shininess = m.positive("shininess", mat.shininess);
        for (const auto& [key, field] : {std::pair<const char*, float*>{"alpha", &mat.alpha}, {"alphaCutoff", &mat.alphaCutoff}})
            if (m.has(key)) {
                const float v = m.child(key).number();
                if (!(v >= 0.0f && v <= 1.0f)) m.child(key).fail("expected a number in 0..1, got " + Reader::fmt(v));
                *field = v;
            }
        if (m.has("alphaMode")) {
            const Reader a = m.child("alphaMode");
            const std::string mode = a.string();
            if (mode == "opaque") mat.alphaMode = AlphaMode::Opaque;
            else if (mode == "mask") mat.alphaMode = AlphaMode::Mask;
            else if (mode == "blend") mat.alphaMode = AlphaMode::Blend;
            else a.fail("expected \"opaque\", \"mask\" or \"blend\", got \"" + text::escapeControl(mode) + "\"");
        }
        if (m.has("baseColorTexture")) {
            const Reader t = m.child("baseColorTexture");
            scene_.textures.push_back(loadTexture(t, ctx_.baseDir / t.string()));
            scene_.textureSources.push_back(ctx_.source + ": " + t.path() + " (" + (ctx_.baseDir / t.string()).string() + ")");
            mat.baseColorTexture = static_cast<int>(scene_.textures.size()) - 1;
        }
        materialIndex_[name] = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(std::move(mat));
    }
}

int SceneBuilder::material(const Reader& r) const {
    const std::string name = r.string();
    const auto it = materialIndex_.find(name);
    if (it == materialIndex_.end()) {
        std::string list;
        for (const auto& [n, _] : materialIndex_) list += (list.empty() ? "" : ", ") + n;
        r.fail("unknown material '" + name + "' (defined: " + (list.empty() ? "none" : list) + ")");
    }
    return it->second;
}

} // namespace shadowlab::scenefile
