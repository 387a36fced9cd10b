#pragma once
// A glTF file (.gltf, .glb) opened as a whole scene: a scene document (the
// JSON a scene file holds) with one node naming the file as its mesh (its
// default scene's node hierarchy, meshes and materials, read by the mesh
// loader), its KHR_lights_punctual lights and one of its cameras, found in
// the file's JSON alone (GltfScene.cpp). Internal to scene.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

/// Whether `path` names a glTF file by its extension (.gltf, .glb).
bool isGltfPath(const std::filesystem::path& path);

struct GltfSceneOptions {
    int camera = 0; ///< which of the cameras the default scene places (in node order), from 0
    /// Whether a file with no light gets the default sun and one with no
    /// camera a framing one (each with a note); false: no light, and a null
    /// camera (a scene file including a glTF's lights or camera).
    bool defaults = true;
};

/// A scene document's glTF includes (docs/scene-format.md): each light
/// {"gltf": FILE} in `lights` replaced by FILE's lights, and a camera
/// {"gltf": FILE, "index": N} by FILE's camera N, FILE relative to
/// `baseDir`. Notes of what was chosen go to `notes`. Throws Error naming
/// `source`, the JSON path and the glTF file's own error.
void expandGltfIncludes(nlohmann::json& doc, const std::string& source, const std::filesystem::path& baseDir, std::vector<std::string>& notes);

/// The scene document of the glTF file `path`, and in `notes` one line for
/// each thing chosen for it (no light: the default sun; no camera: one that
/// frames the scene's bounds; no far plane: one from the bounds). Lights
/// map to shadowlab's as docs/scene-format.md ("glTF files as scenes")
/// says. Throws Error "FILE: JSON.PATH: ..." for a bad light, camera or
/// node reference.
nlohmann::json gltfSceneDocument(const std::filesystem::path& path, const GltfSceneOptions& options, std::vector<std::string>& notes);

} // namespace shadowlab
