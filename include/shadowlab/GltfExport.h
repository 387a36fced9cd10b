#pragma once
/// @file GltfExport.h
/// A scene written as one glTF 2.0 file (`shadowlab export`,
/// scripts/export-gltf.sh): its nodes, meshes and materials, its camera and
/// its lights (KHR_lights_punctual), which every command opens again as a
/// whole scene (docs/scene-format.md, "glTF files as scenes").
///
/// What glTF has no field for rides in `extras.shadowlab`, which other
/// tools keep and ignore: a material's Blinn-Phong terms (ambient, diffuse,
/// specular, shininess), a light's shadowlab keys (intensity, size, shadow),
/// a node's castsShadows and receivesShadows, and the scene's ambient,
/// background and shadowAtlas. A file written here
/// therefore renders as the scene it came from; another tool's file gets
/// the documented defaults and light mapping.
#include <shadowlab/Export.h>
#include <shadowlab/Scene.h>

#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

/// Writes `scene` to `file`: .gltf, JSON with its buffer embedded as a
/// base64 data URI; .glb, binary glTF with the buffer as its BIN chunk.
/// Base-colour textures go beside it as PNG files named <stem>-texture<i>.png,
/// a spot's projected image as <stem>-projector<i>.png. Returns one line for each thing glTF cannot
/// hold and was left out (a light's or the camera's animation path: their
/// pose at time 0 is written). The file
/// is written whole or not at all. Throws shadowlab::Error naming `file`
/// when it cannot be written or the name does not end in .gltf or .glb.
SHADOWLAB_API std::vector<std::string> writeGltfScene(const Scene& scene, const std::filesystem::path& file);

} // namespace shadowlab
