#pragma once
/// @file Scene.h
/// The scene model: meshes, materials, a node hierarchy, one camera, lights.
///
/// Units: lengths in scene units (treated as metres in the docs), angles in
/// degrees in the scene file and in these structs, colours linear RGB.
/// World space is right-handed with +Y up (as glTF).
#include <shadowlab/Export.h>
#include <shadowlab/Image.h>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <any>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab {

/// Triangle mesh in object space. `normals` and `uvs` are per vertex and have
/// the size of `positions` (uvs may be empty). Indices are counter-clockwise
/// front-facing triangles.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;

    std::size_t triangleCount() const { return indices.size() / 3; }
};

/// How a material's alpha (Material::alpha times the base-colour texture's
/// alpha) decides where the surface is, as glTF's alphaMode.
enum class AlphaMode {
    Opaque, ///< "opaque": alpha ignored (default)
    Mask,   ///< "mask": the surface is absent where alpha < alphaCutoff, for the camera, every shadow technique's map and the reference
    Blend,  ///< "blend": glTF's translucent surfaces: the camera draws them last, farthest first, blended by alpha over what is behind; as casters they let light through coloured, mix(white, base colour, alpha) (technique map and the reference)
};

/// Blinn-Phong material as in the lecture material (ambient, diffuse,
/// specular, shininess), with a base colour that tints ambient and diffuse.
/// Lit colour = globalAmbient*ambient*base
///            + sum_lights visibility * light * (diffuse*base*max(N.L,0)
///                                               + specular*max(N.H,0)^shininess)
struct Material {
    std::string name;
    glm::vec3 baseColor{0.8f};   ///< linear RGB, default 0.8 grey
    int baseColorTexture = -1;   ///< index into Scene::textures (sRGB), -1 none
    glm::vec3 ambient{1.0f};     ///< ambient reflectance, multiplies baseColor; default 1
    glm::vec3 diffuse{1.0f};     ///< diffuse reflectance, multiplies baseColor; default 1
    glm::vec3 specular{0.2f};    ///< specular reflectance (not tinted); default 0.2
    float shininess = 32.0f;     ///< Blinn-Phong exponent, > 0; default 32
    float alpha = 1.0f;          ///< the base colour's alpha factor, 0..1; default 1
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;    ///< mask: alpha below this is a hole, 0..1; default 0.5 (glTF's)
    /// Whether alpha decides where the surface is (mask, blend).
    bool alphaTested() const { return alphaMode != AlphaMode::Opaque; }
};

/// Per-light shadow settings (the scene file's `lights[i].shadow` block):
/// which technique decides the light's visibility term, and one options
/// block per technique (`lights[i].shadow.<technique>`). A scene may carry
/// blocks for several techniques, so switching `technique` (for example with
/// `bench --vary lights[0].shadow.technique=a,b`) keeps each one's settings.
/// The registered techniques and their options: Techniques.h.
struct ShadowSettings {
    std::string technique = "map"; ///< a registered technique's name; default "map" (a shadow map with its defaults; "none": no shadows)
    /// Options blocks by technique name, each holding that technique's
    /// options struct (a technique with no block here uses its defaults).
    std::map<std::string, std::any> options;

    /// The options of technique `T::kTechnique` (T is its options struct):
    /// the scene's block, or the defaults.
    template <class T>
    const T& get() const {
        static const T defaults{};
        const auto it = options.find(T::kTechnique);
        const T* stored = it == options.end() ? nullptr : std::any_cast<T>(&it->second);
        return stored ? *stored : defaults;
    }
    /// The options of technique `T::kTechnique` to change (created with defaults).
    template <class T>
    T& edit() {
        std::any& a = options[T::kTechnique];
        if (!std::any_cast<T>(&a)) a = T{};
        return *std::any_cast<T>(&a);
    }
};

enum class LightType { Directional, Spot, Point };

/// How a spot or point light moves over time (the scene file's
/// `lights[i].path`). Time is in seconds since the start of the animation
/// (RenderOptions::timeSeconds, `render --time`). Only the position moves:
/// a spot light keeps its direction. Evaluate it with lightAtTime() or
/// sceneAtTime(); the Renderer itself draws Light::position as it is.
struct SHADOWLAB_API LightPath {
    enum class Type {
        /// position(t) = Light::position + amplitude * sin(angularFrequency * t + phase),
        /// per component: a closed-form oscillation around the light's position.
        Sine,
        /// Piecewise-linear between world-space keys: `positions[i]` at `times[i]`;
        /// before the first time the first position, after the last the last
        /// (or, with `loop`, wrapped into [times.front(), times.back())).
        Keyframes,
    };
    Type type = Type::Sine;
    // Sine.
    glm::vec3 amplitude{0.0f};     ///< sine: scene units per axis, default 0
    double angularFrequency = 1.0; ///< sine: radians per second, finite; default 1
    double phase = 0.0;            ///< sine: radians, finite; default 0
    // Keyframes.
    std::vector<double> times;     ///< keyframes: seconds, finite, strictly increasing, at least one
    std::vector<glm::vec3> positions; ///< keyframes: world space, one per time (replaces Light::position)
    bool loop = false;             ///< keyframes: repeat with period times.back() - times.front(); default false

    /// The position at `seconds` (finite) for a light whose Light::position
    /// is `base` (used by Sine; Keyframes are world space).
    glm::vec3 positionAt(const glm::vec3& base, double seconds) const;
};

/// A light. Fields that do not apply to a type are ignored for it.
struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 color{1.0f};             ///< linear RGB, default white
    float intensity = 1.0f;            ///< multiplies color, >= 0, default 1
    glm::vec3 position{0.0f};          ///< world space; spot and point; with a sine `path`, its centre; a keyframe path replaces it when evaluated (as a glTF animation replaces a node's translation)
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; ///< world space, unit length, the way light travels; directional and spot
    float range = 0.0f;                ///< spot/point: distance beyond which the light has no effect; 0 = unlimited. No other falloff.
    float innerConeDeg = 20.0f;        ///< spot: half-angle of full intensity, degrees, default 20
    float outerConeDeg = 30.0f;        ///< spot: half-angle where light reaches zero, degrees, default 30, >= inner, < 90
    float size = 0.0f;                 ///< soft reference only: radius (point/spot, scene units) or angular diameter (directional, degrees); 0 = hard
    /// Spot only: index into Scene::textures of an image projected along the
    /// cone (Wolberg's slide projector), multiplying the light's colour;
    /// the image fills the square around the outer cone, its top towards the
    /// light camera's up (+Y, or +X for a vertical spot). -1: none (default).
    int projectorTexture = -1;
    /// Spot and point: how the position moves over time; none (default) = static.
    /// Evaluated by lightAtTime() / sceneAtTime().
    std::optional<LightPath> path;
    ShadowSettings shadow;
};

/// `light` at `seconds` (finite; seconds since the start of the animation):
/// its position evaluated along its path, and the path removed, so the result
/// is a static light (evaluating it again changes nothing). A light without
/// a path is returned unchanged. A spot light keeps its direction.
SHADOWLAB_API Light lightAtTime(const Light& light, double seconds);

/// How the camera moves over time (the scene file's `camera.path`): the eye
/// and the point looked at, each piecewise-linear between world-space keys,
/// with the same times, clamping and looping as a light's keyframe path
/// (LightPath::Type::Keyframes). Up, field of view, near and far stay as the
/// Camera has them. Evaluate it with cameraAtTime() or sceneAtTime().
struct SHADOWLAB_API CameraPath {
    std::vector<double> times;        ///< seconds, finite, strictly increasing, at least one
    std::vector<glm::vec3> positions; ///< world-space eye, one per time (replaces Camera::position)
    std::vector<glm::vec3> targets;   ///< world-space point looked at, one per time (replaces Camera::target)
    bool loop = false;                ///< repeat with period times.back() - times.front(); default false

    /// The eye (first) and the point looked at (second) at `seconds` (finite).
    std::pair<glm::vec3, glm::vec3> poseAt(double seconds) const;
};

/// Perspective camera.
struct SHADOWLAB_API Camera {
    glm::vec3 position{0.0f, 4.0f, 10.0f}; ///< world space; a `path` replaces it when evaluated
    glm::vec3 target{0.0f};                ///< world-space point looked at; a `path` replaces it when evaluated
    glm::vec3 up{0.0f, 1.0f, 0.0f};        ///< world-space up hint
    float fovYDeg = 45.0f;                 ///< vertical field of view, degrees, (0,180); perspective only
    /// > 0: an orthographic view this many scene units high (glTF's 2 ymag),
    /// as wide as the frame's aspect makes it; 0 (default): perspective
    /// with fovYDeg. Volumes and cascades need a perspective camera.
    float orthoHeight = 0.0f;
    float nearPlane = 0.1f;                ///< > 0
    float farPlane = 100.0f;               ///< > near
    /// How position and target move over time; none (default) = static.
    /// Evaluated by cameraAtTime() / sceneAtTime(); the Renderer draws
    /// position and target as they are.
    std::optional<CameraPath> path;

    glm::mat4 viewFromWorld() const;
    glm::mat4 clipFromView(float aspect) const;
    /// The same perspective with the far plane at infinity (the limit of
    /// clipFromView as farPlane -> inf; depth 1 is reached only at infinity),
    /// for shadow volumes whose far caps must never be clipped.
    glm::mat4 clipFromViewInfiniteFar(float aspect) const;  ///< orthographic: clipFromView
};

/// `camera` at `seconds` (finite; seconds since the start of the animation):
/// position and target evaluated along its path, and the path removed, so
/// the result is a static camera. A camera without a path is returned unchanged.
SHADOWLAB_API Camera cameraAtTime(const Camera& camera, double seconds);

/// A node of the hierarchy. Transform = translation * rotation * scale,
/// relative to the parent.
struct SHADOWLAB_API Node {
    std::string name;
    int parent = -1;            ///< index into Scene::nodes, -1 for a root
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    int mesh = -1;              ///< index into Scene::meshes, -1 for none
    int material = -1;          ///< index into Scene::materials, -1 = default material
    bool castsShadows = true;   ///< default true
    bool receivesShadows = true;///< default true

    glm::mat4 parentFromLocal() const;
};

/// One mesh instance to draw, with its world transform resolved.
struct DrawItem {
    int mesh = -1;
    int material = -1;
    int node = -1;
    glm::mat4 worldFromObject{1.0f};
    bool castsShadows = true;
    bool receivesShadows = true;
};

/// The shadow atlas that lights with `shadow.map.atlas` share (the scene
/// file's `shadowAtlas`): one depth texture whose square tiles hold their
/// maps (a spot's one, a point light's six faces), each tile sized every
/// frame from how large the light's reach is on screen.
struct ShadowAtlasSettings {
    int size = 8192;              ///< texels per side of the atlas (depth32f: 256 MiB at 8192), 256..16384 and at most the GPU's limit; default 8192
    float texelsPerPixel = 1.0f;  ///< a tile's side: the extent on screen, pixels, of what it sees of the light's reach (a spot: its reach; a cube face: its part of it), times this, rounded up to a power of two; 0.0625..16, default 1
    int minTile = 32;             ///< the least tile side, texels (a power of two, 8..maxTile); default 32
    int maxTile = 1024;           ///< the largest tile side, texels (a power of two, minTile..size); default 1024
    /// The most texels the tiles take together, per pixel of the frame
    /// (the largest tiles are halved until they fit, as when they exceed
    /// the atlas; never below minTile): the shadow passes' cost then stops
    /// growing with the lights. 0: the atlas's size alone; 0..4096, default 32
    float budgetPerPixel = 32.0f;
    /// With RenderOptions::cacheShadowMaps: at most this many tiles whose
    /// light or casters changed are drawn again per frame, the longest
    /// undrawn first (the rest keep their last map); tiles new to their
    /// place in the atlas are always drawn. 0: every changed tile; default 0
    int updateBudget = 0;
};

struct SHADOWLAB_API Scene {
    std::string name;
    Camera camera;
    glm::vec3 ambient{0.15f};       ///< global ambient light, linear RGB, default 0.15
    glm::vec3 background{0.02f, 0.02f, 0.03f}; ///< clear colour, linear RGB
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<ImageRGBA8> textures; ///< base-colour textures, sRGB-encoded
    std::vector<std::string> textureSources; ///< per texture (when loaded from a file): file and JSON path, for messages
    std::vector<Node> nodes;          ///< parents come before their children
    std::vector<Light> lights;
    ShadowAtlasSettings shadowAtlas;  ///< for the lights whose map is in the atlas (MapOptions::atlas)
    /// What loading chose where the file was silent, one line each (a glTF
    /// file with no light gets the default sun, with no camera one that
    /// frames it): for the caller to show.
    std::vector<std::string> notes;

    /// Every node with a mesh, with world transforms resolved (parents first).
    std::vector<DrawItem> drawItems() const;
    /// World-space axis-aligned bounds of all drawn geometry ({+inf},{-inf} if none).
    std::pair<glm::vec3, glm::vec3> worldBounds() const;
};

/// `scene` at `seconds` (finite): every light replaced by lightAtTime(light,
/// seconds) and the camera by cameraAtTime(camera, seconds). Copies the
/// scene (meshes included); to step a scene through many frames, update a
/// copy's lights with lightAtTime() and its camera with cameraAtTime() instead.
SHADOWLAB_API Scene sceneAtTime(const Scene& scene, double seconds);

/// The up vector of a light's own camera looking along `axis` (unit): +Y,
/// or +X when the axis is within about 8 degrees of vertical. Shadow maps,
/// a spot's projected image and cameraFromLight all use it.
SHADOWLAB_API glm::vec3 lightCameraUp(const glm::vec3& axis);

/// The light's own view as a camera (Ganovelli et al. exercise 8.6.1-1): a spot
/// light looks along its axis with a field of view of twice its outer cone;
/// a directional light looks along its direction from outside the scene's
/// bounds, with a field of view just containing them. Near and far enclose
/// the scene. Throws shadowlab::Error for a point light (it has six views).
SHADOWLAB_API Camera cameraFromLight(const Scene& scene, const Light& light);

/// The scene file's name of a light type: "directional", "spot", "point".
SHADOWLAB_API const char* toString(LightType t);

} // namespace shadowlab
