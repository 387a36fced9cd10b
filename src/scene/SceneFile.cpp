// JSON scene files (SceneFile.h): every key, unit and default is in
// docs/scene-format.md. The text is parsed, overridden by `--set` and checked
// here, then read part by part (SceneParts.h), each value through a Reader
// that knows its JSON path (SceneJson.h).
#include <shadowlab/SceneFile.h>

#include "scene/GltfScene.h"
#include "scene/Overrides.h"
#include "scene/SceneParts.h"

#include <shadowlab/Text.h>

#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>

namespace shadowlab {

using nlohmann::json;
namespace fs = std::filesystem;
using overrides::applyOverrides, overrides::typeName;
using scenefile::ParseContext, scenefile::Reader, scenefile::SceneBuilder;
using scenefile::readCamera, scenefile::readLight, scenefile::loadTexture;

namespace {

/// Every string and key must be valid UTF-8 (results.json and the messages
/// are UTF-8); walked with an explicit stack, depth is bounded anyway.
void checkUtf8(const ParseContext& ctx, const json& doc) {
    std::vector<std::pair<const json*, std::string>> stack{{&doc, ""}};
    const auto join = [](const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; };
    while (!stack.empty()) {
        auto [node, path] = std::move(stack.back());
        stack.pop_back();
        if (node->is_string()) {
            if (text::invalidUtf8At(node->get_ref<const std::string&>()) != std::string::npos)
                ctx.fail(path, "invalid UTF-8 in the string '" + node->get<std::string>() + "'");
        } else if (node->is_object()) {
            for (const auto& [key, value] : node->items()) {
                if (text::invalidUtf8At(key) != std::string::npos) ctx.fail(join(path, key), "invalid UTF-8 in this key");
                stack.emplace_back(&value, join(path, key));
            }
        } else if (node->is_array()) {
            for (std::size_t i = 0; i < node->size(); ++i) stack.emplace_back(&(*node)[i], path + "[" + std::to_string(i) + "]");
        }
    }
}

// The document of `jsonText` with `overrides` written into it, checked:
// depth, JSON syntax, a top-level object, the overrides' paths, UTF-8.
json parseDocument(ParseContext& ctx, const std::string& jsonText, const std::string& sourceName,
                   const std::vector<std::string>& overrides) {
    // nlohmann::json copies and destroys recursively: refuse deep nesting first.
    if (text::jsonDepth(jsonText) > text::kMaxJsonDepth)
        throw Error(text::escapeControl(sourceName + ": JSON nested deeper than " + std::to_string(text::kMaxJsonDepth) + " levels"));
    json doc;
    try {
        doc = json::parse(jsonText);
    } catch (const json::exception& e) {
        // nlohmann's messages start with "[json.exception.parse_error.101] ";
        // a number too large for a double (1e999) is out_of_range.406.
        std::string what = e.what();
        const auto pos = what.find("] ");
        what = pos == std::string::npos ? what : what.substr(pos + 2);
        if (e.id == 406) {
            what += " (numbers must be finite)";
            // The parser gives no place for it: the number's first occurrence in the text.
            const std::size_t open = what.find('\''), close = open == std::string::npos ? open : what.find('\'', open + 1);
            const std::size_t at = close == std::string::npos ? close : jsonText.find(what.substr(open + 1, close - open - 1));
            if (at != std::string::npos) {
                const std::size_t line = 1 + static_cast<std::size_t>(std::count(jsonText.begin(), jsonText.begin() + static_cast<long>(at), '\n'));
                const std::size_t lineStart = jsonText.rfind('\n', at == 0 ? 0 : at - 1);
                const std::size_t column = at - (lineStart == std::string::npos || at == 0 ? 0 : lineStart + 1) + 1;
                what += " at line " + std::to_string(line) + ", column " + std::to_string(column);
            }
        }
        throw Error(text::escapeControl(sourceName + ": invalid JSON: " + what));
    }
    if (!doc.is_object()) throw Error(sourceName + ": expected a JSON object at the top level, got " + typeName(doc));
    // A glTF's lights and camera, included by name, before --set addresses them.
    expandGltfIncludes(doc, sourceName, ctx.baseDir, ctx.notes);
    try {
        ctx.overrides = applyOverrides(doc, overrides);
    } catch (const Error& e) {
        throw Error(text::escapeControl(e.what())); // the flag quotes the user's text
    }
    checkUtf8(ctx, doc);
    return doc;
}

const std::vector<const char*> kTopLevelKeys{"name", "camera", "ambient", "background", "materials", "lights", "lightGrid", "shadowAtlas", "nodes"};

// A scene's text parsed and overridden, and its top level checked.
struct Document {
    ParseContext ctx;
    json doc;
    Document(const std::string& jsonText, const std::string& sourceName, const fs::path& baseDir, const std::vector<std::string>& overrides)
        : ctx{sourceName, baseDir, {}, {}}, doc(parseDocument(ctx, jsonText, sourceName, overrides)) {}
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;
    Reader root() const {
        const Reader r(ctx, doc, "");
        r.checkKeys(kTopLevelKeys);
        return r;
    }
};

// The deepest of `keys` under `r` that the document has (where a value came from, a file's or --set's).
Reader deepest(const Reader& r, const char* const* key, const char* const* end) {
    if (key == end || !r.value().is_object() || !r.has(*key)) return r;
    return deepest(r.child(*key), key + 1, end);
}
Reader deepest(const Reader& r, std::initializer_list<const char*> keys) { return deepest(r, keys.begin(), keys.end()); }

// An orthographic camera (camera.orthoHeight) with a technique that needs a
// perspective one: shadow volumes (their far caps at infinity) and cascades
// (slices of a perspective view), refused by the light's path.
void checkOrthographic(const Reader& root, const Scene& scene) {
    if (scene.camera.orthoHeight <= 0.0f || !root.has("lights")) return;
    for (std::size_t i = 0; i < scene.lights.size() && i < root.child("lights").value().size(); ++i) {
        const Light& light = scene.lights[i];
        const Reader at = root.child("lights").element(i);
        if (light.shadow.technique == "volume")
            deepest(at, {"shadow", "technique"}).failUnsupported("\"volume\" needs a perspective camera (its volumes' far caps lie at infinity); camera.orthoHeight is set");
        if (light.shadow.technique == "map" && light.shadow.get<MapOptions>().cascades > 1)
            deepest(at, {"shadow", "map", "cascades"}).failUnsupported("cascades split a perspective view; camera.orthoHeight is set: use cascades 1");
    }
}

// The `lights` array into scene.lights; with `projectors`, each projector's
// image is loaded into scene.textures (else projectorTexture stays -1).
void readLights(const Reader& root, Scene& scene, const ParseContext& ctx, bool projectors) {
    if (!root.has("lights")) return;
    const Reader lights = root.child("lights");
    lights.requireArray();
    if (lights.value().size() > kMaxLights)
        lights.fail("expected at most " + std::to_string(kMaxLights) + " lights, got " + std::to_string(lights.value().size()) +
                    " (render time grows with every light)");
    for (std::size_t i = 0; i < lights.value().size(); ++i) {
        const Reader l = lights.element(i);
        l.requireObject();
        scene.lights.push_back(readLight(l));
        if (projectors && l.has("projector")) {  // the slide: an image file, relative to the scene
            const Reader t = l.child("projector");
            scene.textures.push_back(loadTexture(t, ctx.baseDir / t.string()));
            scene.textureSources.push_back(ctx.source + ": " + t.path() + " (" + (ctx.baseDir / t.string()).string() + ")");
            scene.lights.back().projectorTexture = static_cast<int>(scene.textures.size()) - 1;
        }
    }
}

// `lightGrid`'s generated lights after those of `lights`.
void readGeneratedLights(const Reader& root, Scene& scene) {
    if (!root.has("lightGrid")) return;
    for (Light& light : scenefile::readLightGrid(root.child("lightGrid"), scene.lights.size())) scene.lights.push_back(std::move(light));
}

} // namespace

Scene parseScene(const std::string& jsonText, const std::string& sourceName, const fs::path& baseDir,
                 const std::vector<std::string>& overrides) {
    const Document d(jsonText, sourceName, baseDir, overrides);
    const ParseContext& ctx = d.ctx;
    const Reader root = d.root();
    Scene scene;
    scene.name = root.string("name", fs::path(sourceName).stem().string());
    scene.notes = ctx.notes;
    if (root.has("camera")) readCamera(root.child("camera"), scene.camera);
    scene.ambient = root.color("ambient", scene.ambient);
    scene.background = root.color("background", scene.background);
    SceneBuilder builder(scene, ctx);
    if (root.has("materials")) builder.readMaterials(root.child("materials"));
    readLights(root, scene, ctx, true);
    readGeneratedLights(root, scene);
    if (root.has("shadowAtlas")) scene.shadowAtlas = scenefile::readShadowAtlas(root.child("shadowAtlas"));
    if (root.has("nodes")) builder.readNodes(root.child("nodes"), -1);
    builder.checkFinite();
    checkOrthographic(root, scene);
    return scene;
}

std::vector<Light> parseSceneLights(const std::string& jsonText, const std::string& sourceName, const fs::path& baseDir,
                                    const std::vector<std::string>& overrides) {
    const Document d(jsonText, sourceName, baseDir, overrides);
    Scene scene;
    readLights(d.root(), scene, d.ctx, false);
    readGeneratedLights(d.root(), scene);
    return std::move(scene.lights);
}

Scene loadSceneFile(const fs::path& path, const std::vector<std::string>& overrides) { return loadSceneFile(path, overrides, SceneFileOptions{}); }

Scene loadSceneFile(const fs::path& path, const std::vector<std::string>& overrides, const SceneFileOptions& options) {
    const std::string name = path.string();
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::none) throw Error(name + ": " + ec.message());  // a name too long, a loop of links
    if (!fs::exists(status)) throw Error(name + ": file not found");
    if (!fs::is_regular_file(status)) throw Error(name + ": not a regular file");
    if (isGltfPath(path)) {
        // A glTF file as a whole scene: its document, then loaded as a scene file's.
        std::vector<std::string> notes;
        const json document = gltfSceneDocument(path, GltfSceneOptions{std::max(options.gltfCamera, 0), true}, notes);
        Scene scene = parseScene(document.dump(), name, path.parent_path(), overrides);
        scene.notes.insert(scene.notes.begin(), notes.begin(), notes.end());
        return scene;
    }
    if (options.gltfCamera >= 0)
        throw Error(name + ": a camera index is for glTF files; a scene file includes a glTF's camera with \"camera\": {\"gltf\": FILE, \"index\": N}");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(name + ": cannot open for reading");
    std::stringstream text;
    text << in.rdbuf();
    return parseScene(text.str(), name, path.parent_path(), overrides);
}

std::string withValueSource(const std::string& message, const std::string& sourceName, const std::vector<std::string>& overrides) {
    return withValueSource(message, sourceName, overrides, {});
}

bool overridePathsOverlap(const std::string& a, const std::string& b) { return overrides::pathsOverlap(a, b); }
bool overridePathsEqual(const std::string& a, const std::string& b) { return overrides::pathsEqual(a, b); }

std::optional<std::pair<std::size_t, std::size_t>> overrideDiscarding(const std::vector<std::string>& overrides) {
    auto key = [&](std::size_t i) { return overrides[i].substr(0, overrides[i].find('=')); };
    for (std::size_t i = 1; i < overrides.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (overrides::pathHolds(key(i), key(j))) return std::pair{i, j};
    return std::nullopt;
}

std::string withValueSource(const std::string& message, const std::string& sourceName, const std::vector<std::string>& overrides,
                            const std::vector<std::string>& labels) {
    const std::size_t colon = message.find(": ");
    if (colon == std::string::npos) return message;
    const std::string path = message.substr(0, colon);
    static const char* const roots[] = {"lights[", "lightGrid", "shadowAtlas", "nodes[", "camera", "materials", "ambient", "background"};
    const bool scenePath = path.find(' ') == std::string::npos;
    bool rooted = false;
    for (const char* r : roots) rooted = rooted || path.rfind(r, 0) == 0;
    if (!scenePath || !rooted) return message;
    const std::vector<overrides::Override> described = overrides::describeOverrides(overrides, labels);
    if (const overrides::Override* o = overrides::overrideAt(described, path)) return o->flag + ": " + message;
    return sourceName.empty() ? message : sourceName + ": " + message;
}

std::string sceneJsonWithOverrides(const std::string& jsonText, const std::string& sourceName, const std::vector<std::string>& overrides) {
    // Checked the way a load checks it first (and the result loads again).
    parseScene(jsonText, sourceName, fs::current_path(), overrides);
    json doc = json::parse(jsonText);
    applyOverrides(doc, overrides);
    return doc.dump(2) + "\n";
}

const std::string& defaultSceneJson() {
    // The lecture's first scene: a torus floating above a ground plane under
    // a directional light, seen from above and to the side.
    static const std::string text = R"({
  "name": "default",
  "camera": { "position": [4.5, 4.0, 6.5], "target": [0, 0.6, 0], "fovY": 45 },
  "ambient": [0.15, 0.15, 0.15],
  "materials": {
    "ground": { "baseColor": [0.55, 0.55, 0.52] },
    "gold": { "baseColor": [0.85, 0.62, 0.2], "specular": [0.6, 0.55, 0.4], "shininess": 48 }
  },
  "lights": [
    { "name": "sun", "type": "directional", "direction": [-0.4, -1.0, -0.3], "intensity": 1.0 }
  ],
  "nodes": [
    { "name": "ground", "shape": { "type": "plane", "size": [12, 12] }, "material": "ground" },
    { "name": "torus", "shape": { "type": "torus", "majorRadius": 1.0, "minorRadius": 0.35 },
      "material": "gold", "translation": [0, 1.4, 0], "rotation": [25, 0, 0] }
  ]
})";
    return text;
}

Scene defaultScene(const std::vector<std::string>& overrides) {
    return parseScene(defaultSceneJson(), "<default scene>", fs::current_path(), overrides);
}

} // namespace shadowlab
