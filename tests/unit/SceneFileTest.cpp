// Scene files: values, defaults, hierarchy, --set overrides and every error
// path. Errors must be one line naming the file (or flag) and the JSON path.
#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/SceneFile.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

const char* kMinimal = R"({
  "camera": { "position": [0, 2, 5], "target": [0, 0, 0] },
  "materials": { "m": { "baseColor": [0.5, 0.25, 0.125] } },
  "lights": [
    { "type": "directional", "direction": [0, -2, 0] },
    { "type": "point", "position": [1, 2, 3], "range": 10 }
  ],
  "nodes": [
    { "name": "parent", "translation": [1, 0, 0], "children": [
      { "name": "child", "shape": { "type": "box", "size": [1, 1, 1] }, "material": "m", "translation": [0, 2, 0] } ] }
  ]
})";

// Parses `text` as "scene.json"; returns the error message ("" if none).
std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
        parseScene(text, "scene.json", fs::temp_directory_path(), overrides);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// A scene with one light whose body is `light`.
std::string withLight(const std::string& light) { return R"({"lights": [)" + light + "]}"; }
std::string withNode(const std::string& node) { return R"({"nodes": [)" + node + "]}"; }

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("shadowlab-scenetest-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(path);
    }
    ~TempDir() { std::error_code ec; fs::remove_all(path, ec); }
    fs::path write(const std::string& name, const std::string& content) const {
        std::ofstream(path / name, std::ios::binary) << content;
        return path / name;
    }
};

} // namespace

TEST(SceneFile, ReadsValuesAndDefaults) {
    const Scene s = parseScene(kMinimal, "scene.json", ".");
    EXPECT_EQ(s.camera.position, glm::vec3(0, 2, 5));
    EXPECT_FLOAT_EQ(s.camera.fovYDeg, 45.0f);  // documented default
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_NEAR(glm::length(s.lights[0].direction), 1.0f, 1e-6f);  // normalised
    EXPECT_EQ(s.lights[0].shadow.technique, "map");  // documented default: shadows on
    EXPECT_EQ(s.lights[1].type, LightType::Point);
    EXPECT_FLOAT_EQ(s.lights[1].range, 10.0f);
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].baseColor, glm::vec3(0.5f, 0.25f, 0.125f));
    EXPECT_FLOAT_EQ(s.materials[0].shininess, 32.0f);
}

TEST(SceneFile, ChildTransformsComposeWithParents) {
    const Scene s = parseScene(kMinimal, "scene.json", ".");
    const auto items = s.drawItems();
    ASSERT_EQ(items.size(), 1u);
    const glm::vec3 origin = glm::vec3(items[0].worldFromObject * glm::vec4(0, 0, 0, 1));
    EXPECT_NEAR(glm::distance(origin, glm::vec3(1, 2, 0)), 0.0f, 1e-6f);
    const auto [lo, hi] = s.worldBounds();
    EXPECT_NEAR(glm::distance(lo, glm::vec3(0.5f, 1.5f, -0.5f)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(hi, glm::vec3(1.5f, 2.5f, 0.5f)), 0.0f, 1e-5f);
}

TEST(SceneFile, RotationIsEulerDegreesXThenYThenZ) {
    const Scene s = parseScene(withNode(R"({"shape": {"type": "box"}, "rotation": [90, 0, 0]})"), "scene.json", ".");
    // A 90 degree turn about X takes +Y to +Z.
    const glm::vec3 y = glm::vec3(s.drawItems()[0].worldFromObject * glm::vec4(0, 1, 0, 0));
    EXPECT_NEAR(glm::distance(y, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(SceneFile, OverridesSetValuesByJsonPath) {
    // Every value set differs from what the file (or the default) has, and each is checked.
    const Scene s = parseScene(kMinimal, "scene.json", ".",
                               {"lights[1].intensity=2.5", "camera.fovY=60", "materials.m.baseColor=[1,0,0]",
                                "lights[0].type=spot", "lights[0].position=[0,5,0]", "nodes[0].children[0].castsShadows=false"});
    EXPECT_FLOAT_EQ(s.lights[1].intensity, 2.5f);  // file: default 1
    EXPECT_FLOAT_EQ(s.camera.fovYDeg, 60.0f);      // default 45
    EXPECT_EQ(s.materials[0].baseColor, glm::vec3(1, 0, 0));  // file: [0.5, 0.25, 0.125]
    EXPECT_EQ(s.lights[0].type, LightType::Spot);  // file: directional (a bare word is a string)
    EXPECT_EQ(s.lights[0].position, glm::vec3(0, 5, 0));
    ASSERT_EQ(s.drawItems().size(), 1u);
    EXPECT_FALSE(s.drawItems()[0].castsShadows);   // default true
}

TEST(SceneFile, OfTwoOverridesOfOnePathTheLaterWins) {
    // The library applies overrides in order, the earlier value replaced
    // before the scene is checked (the CLI refuses two --set of one path,
    // cli/errors.sh set-twice; the Python module's with_overrides replaces
    // a key's earlier line).
    EXPECT_FLOAT_EQ(parseScene(kMinimal, "scene.json", ".", {"lights[1].intensity=bright", "lights[1].intensity=2.5"}).lights[1].intensity, 2.5f);
    EXPECT_FLOAT_EQ(parseScene(kMinimal, "scene.json", ".", {"lights[1].intensity=3", "lights[1].intensity=2.5"}).lights[1].intensity, 2.5f);
}

TEST(SceneFile, DefaultSceneHasATorusAPlaneAndALight) {
    const Scene s = defaultScene();
    EXPECT_EQ(s.drawItems().size(), 2u);
    EXPECT_EQ(s.lights.size(), 1u);
    EXPECT_FLOAT_EQ(defaultScene({"lights[0].intensity=3"}).lights[0].intensity, 3.0f);
}

TEST(SceneFile, EveryShapeTypeParses) {
    for (const char* shape : {R"({"type":"plane","size":[2,3]})", R"({"type":"box","size":[1,2,3]})",
                              R"({"type":"sphere","radius":0.5})", R"({"type":"torus","majorRadius":1,"minorRadius":0.2})",
                              R"({"type":"cylinder"})", R"({"type":"cone","segments":8})",
                              R"({"type":"pyramid","baseWidth":2,"height":1})"}) {
        SCOPED_TRACE(shape);
        const Scene s = parseScene(withNode(std::string(R"({"shape":)") + shape + "}"), "scene.json", ".");
        ASSERT_EQ(s.meshes.size(), 1u);
        EXPECT_GT(s.meshes[0].triangleCount(), 0u);
    }
}

// The shapes of one scene make at most 2^24 triangles in all: nine of the
// finest spheres (2 x 1024 x 1023 triangles each) are one too many, and
// the ninth is refused by its path (a few kB of JSON asked for 70 GB
// through 400 of them): eight make 16,760,832 triangles.
TEST(SceneFile, TheShapesOfASceneHaveATriangleBudget) {
    std::string nodes;
    for (int i = 0; i < 9; ++i) nodes += std::string(i ? "," : "") + R"({"shape": {"type": "sphere", "segments": 1024, "rings": 1024}})";
    const std::string error = errorOf(R"({"nodes": [)" + nodes + "]}");
    EXPECT_EQ(error, "scene.json: nodes[8].shape: this shape makes 2095104 triangles, past what a scene may hold in all "
                     "(16777216 triangles of shapes and mesh files; 16384 left): fewer segments");
}

// --- Errors: one line, file or flag, JSON path, what was expected ------------

struct ErrorCase {
    const char* name;
    std::string text;
    std::vector<std::string> overrides;
    std::string expected;  // the message must contain this
};
void PrintTo(const ErrorCase& c, std::ostream* os) { *os << c.name; }

class SceneFileErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneFileErrors, NameFilePathAndExpectation) {
    const ErrorCase& c = GetParam();
    const std::string message = errorOf(c.text, c.overrides);
    ASSERT_FALSE(message.empty()) << "no error for " << c.name;
    EXPECT_NE(message.find(c.expected), std::string::npos) << "message: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    if (c.overrides.empty()) EXPECT_EQ(message.rfind("scene.json: ", 0), 0u) << message;
    else EXPECT_EQ(message.rfind("--set ", 0), 0u) << message;
}

INSTANTIATE_TEST_SUITE_P(
    All, SceneFileErrors,
    ::testing::Values(
        ErrorCase{"InvalidJson", "{ \"nodes\": [ }", {}, "invalid JSON: parse error at line 1"},
        ErrorCase{"TopLevelArray", "[1, 2]", {}, "expected a JSON object at the top level"},
        ErrorCase{"UnknownTopKey", R"({"lihgts": []})", {}, "lihgts: unknown key"},
        ErrorCase{"UnknownNestedKey", withLight(R"({"type":"point","position":[0,1,0],"colour":[1,1,1]})"), {}, "lights[0].colour: unknown key"},
        ErrorCase{"DirectionTwoNumbers", R"({"lights": [{"type":"directional"}, {"type":"directional","direction":[1,2]}]})", {},
                  "scene.json: lights[1].direction: expected 3 numbers, got 2"},
        ErrorCase{"ZeroDirection", withLight(R"({"type":"directional","direction":[0,0,0]})"), {}, "lights[0].direction: expected a non-zero direction"},
        ErrorCase{"DirectionNotArray", withLight(R"({"type":"directional","direction":"down"})"), {}, "lights[0].direction: expected 3 numbers, got a string"},
        ErrorCase{"InfiniteNumber", withLight(R"({"type":"directional","intensity":1e999})"), {}, "invalid JSON: number overflow parsing '1e999' (numbers must be finite) at line 1, column 47"},
        ErrorCase{"NegativeIntensity", withLight(R"({"type":"directional","intensity":-1})"), {}, "lights[0].intensity: expected a number >= 0, got -1"},
        ErrorCase{"UnknownLightType", withLight(R"({"type":"area"})"), {}, "lights[0].type: expected directional, spot or point, got 'area'"},
        ErrorCase{"MissingLightType", withLight(R"({"direction":[0,-1,0]})"), {}, "lights[0]: missing key 'type'"},
        ErrorCase{"PointWithoutPosition", withLight(R"({"type":"point"})"), {}, "lights[0]: missing key 'position'"},
        ErrorCase{"ConeOrder", withLight(R"({"type":"spot","position":[0,1,0],"innerCone":40,"outerCone":30})"), {}, "lights[0].innerCone: expected innerCone <= outerCone"},
        ErrorCase{"ConeTooWide", withLight(R"({"type":"spot","position":[0,1,0],"outerCone":95})"), {}, "lights[0].outerCone: expected degrees in (0, 90)"},
        ErrorCase{"UnknownTechnique", withLight(R"({"type":"directional","shadow":{"technique":"magic"}})"), {}, "lights[0].shadow.technique: unknown technique 'magic'"},
        ErrorCase{"CascadesOnASpot", withLight(R"({"type":"spot","position":[0,3,0],"shadow":{"technique":"map","map":{"cascades":4}}})"), {},
                  "lights[0].shadow.map.cascades: map: cascades are for directional lights"},
        ErrorCase{"CascadeSplitsCount", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"cascades":3,"cascadeSplits":"5"}}})"), {},
                  "lights[0].shadow.map.cascadeSplits: map: cascadeSplits \"5\": expected 2 distance(s) for 3 cascades, got 1"},
        ErrorCase{"CascadeSplitsOrder", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"cascades":3,"cascadeSplits":"9, 4"}}})"), {},
                  "map: cascadeSplits \"9, 4\": expected increasing distances > 0"},
        ErrorCase{"CascadeSplitsText", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"cascades":2,"cascadeSplits":"near\nfar"}}})"), {},
                  "map: cascadeSplits \"near\\nfar\": expected increasing distances > 0"},
        ErrorCase{"CascadeSplitsWithoutCascades", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"cascadeSplits":"5"}}})"), {},
                  "map: cascadeSplits is given but cascades is 1"},
        ErrorCase{"CascadesWithAPreset", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"cascades":2,"preset":"learnopengl"}}})"), {},
                  "lights[0].shadow.map.cascades: map: cascades do not combine with a preset"},
        ErrorCase{"SdsmWithAPreset", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"fit":"sdsm","preset":"lecture"}}})"), {},
                  "lights[0].shadow.map.fit: map: fit \"sdsm\" does not combine with a preset"},
        ErrorCase{"MapSizeUnderSixteen", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"size":8}}})"), {},
                  "lights[0].shadow.map.size: map: size: expected 0 (follow the frame) or 16..16384 texels, got 8"},
        ErrorCase{"MomentsOnAPointLight", withLight(R"({"type":"point","position":[0,3,0],"shadow":{"technique":"map","map":{"representation":"vsm"}}})"), {},
                  "map: representation \"vsm\", \"evsm2\", \"evsm4\" and \"msm\" are for 2D maps"},
        ErrorCase{"MomentsWithRgba8", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"representation":"msm","format":"rgba8"}}})"), {},
                  "lights[0].shadow.map.format: map: format \"rgba8\": moment maps have their own format (momentFormat)"},
        ErrorCase{"MomentsWithAFilter", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"representation":"evsm4","filter":"pcss"}}})"), {},
                  "lights[0].shadow.map.filter: map: filter \"pcss\": a moment map is filtered by its blur and bilinear lookups; filter must be \"hardware\""},
        ErrorCase{"UnknownRepresentation", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"representation":"esm"}}})"), {},
                  "lights[0].shadow.map.representation: expected one of \"depth\", \"vsm\", \"evsm2\", \"evsm4\", \"msm\", got \"esm\""},
        ErrorCase{"UnknownAlphaMode", R"({"materials":{"m":{"alphaMode":"cutout"}}})", {}, "materials.m.alphaMode: expected \"opaque\", \"mask\" or \"blend\", got \"cutout\""},
        ErrorCase{"AlphaCutoffRange", R"({"materials":{"m":{"alphaCutoff":1.5}}})", {}, "materials.m.alphaCutoff: expected a number in 0..1, got 1.5"},
        ErrorCase{"AlphaRange", R"({"materials":{"m":{"alpha":-0.1}}})", {}, "materials.m.alpha: expected a number in 0..1, got -0.1"},
        ErrorCase{"CascadesTooMany", withLight(R"({"type":"directional","shadow":{"technique":"map","map":{"cascades":9}}})"), {},
                  "lights[0].shadow.map.cascades: expected an integer in 1..8, got 9"},
        ErrorCase{"NegativeBoxSize", withNode(R"({"shape":{"type":"box","size":[1,-2,1]}})"), {}, "nodes[0].shape.size: expected 3 numbers > 0"},
        ErrorCase{"NegativeRadius", withNode(R"({"shape":{"type":"sphere","radius":-1}})"), {}, "nodes[0].shape.radius: expected a number > 0, got -1"},
        ErrorCase{"PlaneSizeCount", withNode(R"({"shape":{"type":"plane","size":[1,2,3]}})"), {}, "nodes[0].shape.size: expected 2 numbers [width, depth], got 3"},
        ErrorCase{"TorusRadii", withNode(R"({"shape":{"type":"torus","majorRadius":0.2,"minorRadius":0.5}})"), {}, "nodes[0].shape: expected minorRadius < majorRadius"},
        ErrorCase{"TooFewSegments", withNode(R"({"shape":{"type":"sphere","segments":2}})"), {}, "nodes[0].shape.segments: expected an integer in 3..1024, got 2"},
        ErrorCase{"TooManySegments", withNode(R"({"shape":{"type":"torus","majorSegments":1000000000}})"), {}, "nodes[0].shape.majorSegments: expected an integer in 3..1024"},
        ErrorCase{"UnknownShape", withNode(R"({"shape":{"type":"teapot"}})"), {}, "nodes[0].shape.type: unknown shape 'teapot'"},
        ErrorCase{"UnknownMaterial", withNode(R"({"shape":{"type":"box"},"material":"gold"})"), {}, "nodes[0].material: unknown material 'gold'"},
        ErrorCase{"ZeroScale", withNode(R"({"shape":{"type":"box"},"scale":0})"), {}, "nodes[0].scale: expected a number > 0"},
        ErrorCase{"NestedChildError", withNode(R"({"children":[{"children":[{"shape":{"type":"box","size":[1,1]}}]}]})"), {}, "nodes[0].children[0].children[0].shape.size: expected 3 numbers, got 2"},
        ErrorCase{"ShapeAndMesh", withNode(R"({"shape":{"type":"box"},"mesh":"a.obj"})"), {}, "nodes[0]: a node has either 'shape' or 'mesh'"},
        ErrorCase{"MissingMeshFile", withNode(R"({"mesh":"does-not-exist.obj"})"), {}, "nodes[0].mesh: "},
        ErrorCase{"MissingTexture", R"({"materials":{"m":{"baseColorTexture":"nope.png"}}})", {}, "materials.m.baseColorTexture: texture file not found"},
        ErrorCase{"NegativeColor", R"({"ambient":[0.1,-0.1,0]})", {}, "ambient: expected 3 numbers >= 0"},
        ErrorCase{"FarBeforeNear", R"({"camera":{"near":5,"far":1}})", {}, "camera.far: expected far > near"},
        ErrorCase{"FovTooWide", R"({"camera":{"fovY":180}})", {}, "camera.fovY: expected degrees in (0, 180)"},
        ErrorCase{"CameraLooksAtItself", R"({"camera":{"position":[1,1,1],"target":[1,1,1]}})", {}, "camera: camera position and target coincide"},
        ErrorCase{"NodesNotArray", R"({"nodes":{}})", {}, "nodes: expected an array, got an object"},
        ErrorCase{"BooleanExpected", withNode(R"({"shape":{"type":"box"},"castsShadows":"yes"})"), {}, "nodes[0].castsShadows: expected true or false"},
        // --set: the flag is named, with the path and what was wrong.
        ErrorCase{"SetBadValue", kMinimal, {"lights[0].intensity=abc"}, "--set lights[0].intensity=abc: lights[0].intensity: expected a number, got a string"},
        ErrorCase{"SetNaN", kMinimal, {"lights[0].intensity=nan"}, "--set lights[0].intensity=nan: lights[0].intensity: expected a number"},
        ErrorCase{"SetIndexOutOfRange", kMinimal, {"lights[5].intensity=1"}, "--set lights[5].intensity=1: index 5 out of range ('lights' has 2 elements)"},
        ErrorCase{"SetUnknownKey", kMinimal, {"lights[0].intensty=1"}, "--set lights[0].intensty=1: lights[0].intensty: unknown key"},
        ErrorCase{"SetNoEquals", kMinimal, {"lights[0].intensity"}, "--set lights[0].intensity: expected key=value"},
        ErrorCase{"SetBadPath", kMinimal, {"lights[x].intensity=1"}, "--set lights[x].intensity=1: bad JSON path 'lights[x].intensity': expected an index"},
        ErrorCase{"SetThroughNumber", kMinimal, {"camera.fovY.x=1"}, "--set camera.fovY.x=1: camera.fovY: expected a number, got an object"},
        ErrorCase{"SetThroughExistingNumber", R"({"camera":{"fovY":40}})", {"camera.fovY.x=1"}, "--set camera.fovY.x=1: 'camera.fovY' is a number, not an object"},
        ErrorCase{"SetDirectionZero", kMinimal, {"lights[0].direction=[0,0,0]"}, "--set lights[0].direction=[0,0,0]: lights[0].direction: expected a non-zero direction"}),
    [](const ::testing::TestParamInfo<ErrorCase>& p) { return std::string(p.param.name); });

TEST(SceneFile, MissingFileIsAnError) {
    try {
        loadSceneFile("/nonexistent/scene.json");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/scene.json: file not found");
    }
}

TEST(SceneFile, MeshPathsAreRelativeToTheSceneFile) {
    TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const fs::path scene = dir.write("scene.json", withNode(R"({"mesh":"tri.obj","translation":[0,0,1]})"));
    const Scene s = loadSceneFile(scene);
    ASSERT_EQ(s.drawItems().size(), 1u);
    EXPECT_EQ(s.meshes.at(0).triangleCount(), 1u);
}

// Nodes naming one mesh file share its meshes (issue 59: 300 nodes naming
// one 69k-triangle OBJ made 300 copies, 6.6 GB), the same file however its
// path is spelled; each node still draws it where it stands.
TEST(SceneFile, NodesNamingOneMeshFileShareItsMeshes) {
    TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const fs::path scene = dir.write("scene.json", R"({"nodes": [{"mesh": "tri.obj"}, {"mesh": "tri.obj", "translation": [2, 0, 0]},
                                                                  {"mesh": "./tri.obj", "translation": [4, 0, 0]}]})");
    const Scene s = loadSceneFile(scene);
    ASSERT_EQ(s.meshes.size(), 1u);
    const std::vector<DrawItem> items = s.drawItems();
    ASSERT_EQ(items.size(), 3u);
    for (const DrawItem& item : items) EXPECT_EQ(item.mesh, 0);
    EXPECT_FLOAT_EQ(items[2].worldFromObject[3].x, 4.0f);
}

// Mesh files count against the scene's triangles with its shapes: a mesh
// file past what is left is one line naming the node and the file.
TEST(SceneFile, MeshFilesCountAgainstTheScenesTriangles) {
    TempDir dir;
    // A fan of 20,000 triangles, after eight of the finest spheres (2 x 1024 x
    // 1023 triangles each), which leave 16,384 of the 2^24.
    std::string fan = "v 0 0 0\n";
    for (int i = 0; i <= 20000; ++i) fan += "v " + std::to_string(std::cos(i * 1e-4)) + " " + std::to_string(std::sin(i * 1e-4)) + " 0\n";
    for (int i = 0; i < 20000; ++i) fan += "f 1 " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
    dir.write("fan.obj", fan);
    std::string nodes;
    for (int i = 0; i < 8; ++i) nodes += R"({"shape": {"type": "sphere", "segments": 1024, "rings": 1024}},)";
    const fs::path scene = dir.write("scene.json", R"({"nodes": [)" + nodes + R"({"mesh": "fan.obj"}]})");
    try {
        loadSceneFile(scene);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("nodes[8].mesh: "), std::string::npos) << m;
        EXPECT_NE(m.find("fan.obj: 20000 triangles, past what a scene may hold in all (16777216 triangles of shapes and mesh files; 16384 left)"),
                  std::string::npos) << m;
    }
}

TEST(SceneFile, GlbThatIsNotGltfNamesTheFileAndPath) {
    TempDir dir;
    dir.write("model.glb", "this is not a binary glTF file at all");
    const fs::path scene = dir.write("scene.json", withNode(R"({"mesh":"model.glb"})"));
    try {
        loadSceneFile(scene);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("scene.json: nodes[0].mesh: "), std::string::npos) << m;
        EXPECT_NE(m.find("model.glb"), std::string::npos) << m;
        EXPECT_NE(m.find("glTF"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

TEST(SceneFile, EveryBundledSceneParses) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const Scene s = loadSceneFile(entry.path());
        EXPECT_FALSE(s.lights.empty());
        EXPECT_FALSE(s.drawItems().empty());
        ++count;
    }
    EXPECT_GE(count, 8);  // the eight lecture scenes of the foundation issue
}

// The viewer's light-only path: parseSceneLights reads the lights exactly as
// parseScene does, overrides and errors included, and reads nothing else
// (a node that would fail is not looked at).
TEST(SceneFile, LightsAloneReadAsTheWholeScene) {
    const std::vector<std::string> overrides{"lights[1].position=[4,5,6]", "lights[0].shadow.map.size=512"};
    const Scene whole = parseScene(kMinimal, "scene.json", ".", overrides);
    const std::vector<Light> lights = parseSceneLights(kMinimal, "scene.json", ".", overrides);
    ASSERT_EQ(lights.size(), whole.lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        EXPECT_EQ(lights[i].type, whole.lights[i].type);
        EXPECT_EQ(lights[i].position, whole.lights[i].position);
        EXPECT_EQ(lights[i].direction, whole.lights[i].direction);
        EXPECT_EQ(lights[i].shadow.technique, whole.lights[i].shadow.technique);
        EXPECT_EQ(lights[i].shadow.get<MapOptions>().size, whole.lights[i].shadow.get<MapOptions>().size);
    }
    EXPECT_EQ(lights[1].position, glm::vec3(4, 5, 6));
    EXPECT_EQ(lights[0].shadow.get<MapOptions>().size, 512);
    // A mesh file that does not exist: parseScene fails on it, the lights alone do not.
    const std::vector<std::string> missingMesh{"nodes[0].mesh=\"no-such-file.obj\""};
    EXPECT_THROW(parseScene(kMinimal, "scene.json", ".", missingMesh), Error);
    EXPECT_EQ(parseSceneLights(kMinimal, "scene.json", ".", missingMesh).size(), 2u);
    // A bad light value is the same one-line error either way.
    const std::vector<std::string> bad{"lights[0].shadow.map.size=3"};
    std::string a, b;
    try { parseScene(kMinimal, "scene.json", ".", bad); } catch (const Error& e) { a = e.what(); }
    try { parseSceneLights(kMinimal, "scene.json", ".", bad); } catch (const Error& e) { b = e.what(); }
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
}
