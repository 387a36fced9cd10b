#pragma once
/// @file SceneFile.h
/// JSON scene files (format: docs/scene-format.md) and `--set` overrides.
#include <shadowlab/Export.h>
#include <shadowlab/Scene.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab {

/// At most this many lights in a scene (the `lights` array): every light
/// adds a lighting pass, so render time grows linearly with the count
/// (3,000 lights took 6.6 s per frame on llvmpipe).
constexpr std::size_t kMaxLights = 256;

/// Loads a scene file. Mesh and texture paths are relative to the file's
/// directory. `overrides` are `path=value` strings as given to `--set`
/// (e.g. `lights[0].intensity=2`, `camera.fovY=60`); the value is JSON, or a
/// plain string when it is not valid JSON. Throws shadowlab::Error with a
/// one-line message naming the file (or the `--set` flag), the JSON path of
/// the bad value and what was expected.
SHADOWLAB_API Scene loadSceneFile(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

/// How loadSceneFile opens a file beyond its overrides.
struct SceneFileOptions {
    /// A glTF file's camera: the index among the cameras its default scene
    /// places, in node order (`--camera N`); -1 (the default): the first.
    /// Given for a scene file, an error: a scene file includes a glTF's
    /// camera with "camera": {"gltf": FILE, "index": N}.
    int gltfCamera = -1;
};

/// loadSceneFile with `options`.
SHADOWLAB_API Scene loadSceneFile(const std::filesystem::path& path, const std::vector<std::string>& overrides, const SceneFileOptions& options);

/// Parses scene JSON text. `sourceName` names it in errors; `baseDir`
/// resolves relative mesh and texture paths.
SHADOWLAB_API Scene parseScene(const std::string& jsonText, const std::string& sourceName,
                               const std::filesystem::path& baseDir, const std::vector<std::string>& overrides = {});

/// The lights of scene JSON text with `overrides`, read and checked exactly
/// as parseScene reads them, without the camera, materials, nodes, meshes or
/// textures: for a tool that changes a light's settings (a technique's
/// option, a position) without reading and uploading the scene again. A
/// projector's image is not loaded (projectorTexture is -1: keep the one of
/// the scene parsed whole). Throws shadowlab::Error as parseScene does.
SHADOWLAB_API std::vector<Light> parseSceneLights(const std::string& jsonText, const std::string& sourceName,
                                                  const std::filesystem::path& baseDir, const std::vector<std::string>& overrides = {});

/// The built-in default scene (a torus floating over a ground plane, one
/// directional light): what `shadowlab render` draws without a scene file.
SHADOWLAB_API Scene defaultScene(const std::vector<std::string>& overrides = {});
/// The default scene's JSON text.
SHADOWLAB_API const std::string& defaultSceneJson();

/// `message` with where its value came from in front, for an error raised
/// after the scene was read (a map's memory budget, planar receivers that
/// are not planar): when it starts with a scene JSON path
/// (`lights[0].shadow.map.size: ...`), the `--set` of `overrides` that set
/// that value, a part of it or a block around it (as parse errors name it),
/// else `sourceName` (the scene file). Other messages come back unchanged.
SHADOWLAB_API std::string withValueSource(const std::string& message, const std::string& sourceName, const std::vector<std::string>& overrides);
/// The same with each override named by `labels[i]` (a bench `--vary`
/// value, a viewer script's line) instead of `--set KEY=VALUE`; an empty
/// `sourceName` leaves a message no override set unchanged.
SHADOWLAB_API std::string withValueSource(const std::string& message, const std::string& sourceName, const std::vector<std::string>& overrides,
                                          const std::vector<std::string>& labels);

/// Whether two override keys (`--set`/`--vary` paths) name one value, or
/// one holds the other (`lights[0].shadow` holds `lights[0].shadow.technique`;
/// `lights[00]` is `lights[0]`).
SHADOWLAB_API bool overridePathsOverlap(const std::string& a, const std::string& b);
/// Whether two override keys name one value (`lights[00].size` is `lights[0].size`).
SHADOWLAB_API bool overridePathsEqual(const std::string& a, const std::string& b);
/// The first override (`path=value` lines, applied in order) that throws
/// away a value an earlier one set: the same path again, or a path holding
/// the earlier one's (`lights[0].shadow.map={...}` after
/// `lights[0].shadow.map.size=7`), as {later, earlier} indices; nullopt
/// when every line keeps what the ones before it set (a path inside an
/// earlier one's refines it and is kept). A value given and then dropped
/// unread is a mistake the user should hear of.
SHADOWLAB_API std::optional<std::pair<std::size_t, std::size_t>> overrideDiscarding(const std::vector<std::string>& overrides);

/// Scene JSON text with `overrides` written into it (the `--set` lines, or
/// the viewer's settings), pretty-printed: it loads again as the scene those
/// overrides give. Throws shadowlab::Error as parseScene does.
SHADOWLAB_API std::string sceneJsonWithOverrides(const std::string& jsonText, const std::string& sourceName, const std::vector<std::string>& overrides);

} // namespace shadowlab
