// A glTF file opened as a whole scene (scene/GltfScene.h, loadSceneFile):
// its KHR_lights_punctual lights and cameras mapped as docs/scene-format.md
// says, notes where the file is silent, one line naming the JSON path for
// a bad light or camera.
#include "scene/GltfScene.h"

#include <shadowlab/Error.h>
#include <shadowlab/GltfExport.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/Techniques.h>
#include <shadowlab/SceneFile.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <random>

using namespace shadowlab;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// One triangle (0,0,0), (1,0,0), (0,1,0): 9 floats and 3 uint16 indices, inline.
json triangleModel() {
    return json::parse(R"({
      "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"name": "tri", "mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=", "byteLength": 44}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})");
}

// The model with a sun straight down (node 1: -90 degrees about X turns -Z
// to -Y), a spot 2 m above the triangle's bounds' centre looking down, and
// a perspective camera at (0, 0, 5) looking down -Z.
json litModel() {
    json m = triangleModel();
    m["extensions"]["KHR_lights_punctual"]["lights"] = json::parse(R"([
      {"name": "sun", "type": "directional", "intensity": 3},
      {"type": "spot", "color": [1, 0.5, 0.25], "intensity": 24, "range": 9, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}}])");
    const double h = std::sqrt(0.5);
    m["nodes"].push_back({{"name", "sun node"}, {"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    m["nodes"].push_back({{"name", "lamp"}, {"translation", {0.5, 0.5, 2.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    m["nodes"].push_back({{"name", "eye"}, {"translation", {0, 0, 5}}, {"camera", 0}});
    m["cameras"] = json::parse(R"([{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.05, "zfar": 50}}])");
    m["scenes"][0]["nodes"] = {0, 1, 2, 3};
    return m;
}

class GltfSceneTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::random_device rd;
        dir_ = fs::temp_directory_path() / ("shadowlab-gltfscene-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
                                            std::to_string(rd()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    fs::path write(const json& model, const std::string& name = "model.gltf") const {
        const fs::path p = dir_ / name;
        std::ofstream(p) << model.dump();
        return p;
    }
    // The one-line error loading `model` gives.
    std::string errorOf(const json& model) const {
        try {
            loadSceneFile(write(model));
        } catch (const Error& e) {
            return e.what();
        }
        return "(no error)";
    }
    fs::path dir_;
};

} // namespace

TEST_F(GltfSceneTest, LightsAndTheCameraComeFromTheFile) {
    const Scene scene = loadSceneFile(write(litModel()));
    ASSERT_EQ(scene.lights.size(), 2u);
    const Light& sun = scene.lights[0];
    EXPECT_EQ(sun.name, "sun");
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_NEAR(sun.direction.y, -1.0f, 1e-5f);  // the node's -Z, turned down
    const Light& spot = scene.lights[1];
    EXPECT_EQ(spot.name, "lamp");  // an unnamed light takes its node's name
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_NEAR(spot.position.z, 2.0f, 1e-6f);
    EXPECT_NEAR(spot.direction.z, -1.0f, 1e-6f);
    EXPECT_NEAR(spot.innerConeDeg, 0.2f * 180.0f / 3.14159265f, 1e-4f);
    EXPECT_NEAR(spot.outerConeDeg, 0.5f * 180.0f / 3.14159265f, 1e-4f);
    EXPECT_FLOAT_EQ(spot.range, 9.0f);
    EXPECT_FLOAT_EQ(spot.color.g, 0.5f);
    // Illuminance at the bounds' centre (0.5, 0.5, 0): the sun 3 lux, the
    // spot 24 cd over 2^2 m^2 = 6 lux, the brightest: intensities 0.5 and 1.
    EXPECT_NEAR(sun.intensity, 0.5f, 1e-6f);
    EXPECT_NEAR(spot.intensity, 1.0f, 1e-6f);
    EXPECT_NEAR(scene.camera.position.z, 5.0f, 1e-6f);
    EXPECT_LT(scene.camera.target.z, scene.camera.position.z);  // looking down -Z
    EXPECT_NEAR(scene.camera.fovYDeg, 0.5f * 180.0f / 3.14159265f, 1e-4f);
    EXPECT_FLOAT_EQ(scene.camera.farPlane, 50.0f);
    EXPECT_TRUE(scene.notes.empty());
    EXPECT_EQ(scene.meshes.size(), 1u);
}

TEST_F(GltfSceneTest, OverridesNameTheSceneTheFileBecame) {
    const Scene scene = loadSceneFile(write(litModel()), {"lights[1].intensity=0.25", "lights[0].shadow.technique=volume", "camera.fovY=60"});
    EXPECT_FLOAT_EQ(scene.lights[1].intensity, 0.25f);
    EXPECT_EQ(scene.lights[0].shadow.technique, "volume");
    EXPECT_FLOAT_EQ(scene.camera.fovYDeg, 60.0f);
}

TEST_F(GltfSceneTest, AFileWithNoLightOrCameraGetsDefaultsAndSaysSo) {
    const Scene scene = loadSceneFile(write(triangleModel(), "bare.gltf"));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    ASSERT_EQ(scene.notes.size(), 2u);
    EXPECT_NE(scene.notes[0].find("no KHR_lights_punctual light"), std::string::npos) << scene.notes[0];
    EXPECT_NE(scene.notes[1].find("no camera"), std::string::npos) << scene.notes[1];
    // The framing camera looks at the bounds' centre from outside them.
    EXPECT_NEAR(scene.camera.target.x, 0.5f, 1e-6f);
    EXPECT_GT(glm::length(scene.camera.position - scene.camera.target), 1.0f);
}

TEST_F(GltfSceneTest, ACameraWithNoFarPlaneGetsOnePastTheBounds) {
    json m = litModel();
    m["cameras"][0]["perspective"].erase("zfar");
    const Scene scene = loadSceneFile(write(m));
    EXPECT_GT(scene.camera.farPlane, 5.0f);  // past the triangle, 5 m away
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("cameras[0] has no zfar"), std::string::npos) << scene.notes[0];
}

TEST_F(GltfSceneTest, BadLightsAndCamerasNameTheirPath) {
    const std::string lights = "extensions.KHR_lights_punctual.lights[1]";
    const std::vector<std::pair<std::function<void(json&)>, std::string>> cases{
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["type"] = "area"; }, lights + ".type: \"area\" is not"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["intensity"] = -1; }, lights + ".intensity: must not be negative"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["range"] = 0; }, lights + ".range: must be greater than 0"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["range"] = -2; }, lights + ".range: must be greater than 0"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["extras"]["shadowlab"] = 3; }, lights + ".extras.shadowlab: expected an object"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["extras"]["shadowlab"]["shadow"]["technique"] = "nope"; },
         "lights[1].shadow.technique"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["outerConeAngle"] = 1.6; }, lights + ".spot.outerConeAngle"},
        {[](json& m) { m["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 0.6; }, lights + ".spot.innerConeAngle"},
        {[](json& m) { m["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 7; }, "nodes[2].extensions.KHR_lights_punctual.light: 7 is not one of"},
        {[](json& m) { m["nodes"][3]["camera"] = 3; }, "nodes[3].camera: 3 is not one of"},
        {[](json& m) { m["cameras"][0]["perspective"]["yfov"] = 0; }, "cameras[0].perspective.yfov"},
        {[](json& m) { m["cameras"][0]["perspective"]["zfar"] = 0.01; }, "cameras[0].perspective.zfar: must be greater than znear"},
    };
    for (const auto& [patch, expected] : cases) {
        json m = litModel();
        patch(m);
        const std::string message = errorOf(m);
        EXPECT_NE(message.find("model.gltf: " + expected), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
}

// A scene written by writeGltfScene (GltfExport.h) comes back whole, as
// .gltf and as .glb: its camera, its lights with their shadow settings,
// its materials' Blinn-Phong terms, the nodes that cast no shadow, the
// scene's ambient and background (room-point: a bulb that casts none, a
// cube map with options of its own, set here).
TEST_F(GltfSceneTest, AnExportedSceneComesBackWhole) {
    const fs::path source = fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "room-point.json";
    const Scene scene = loadSceneFile(source, {"lights[0].shadow.map.filter=\"poisson\"", "lights[0].shadow.map.samples=24", "ambient=[0.1,0.2,0.3]",
                                               "lights[0].intensity=0.7", "lights[0].size=0.05"});
    for (const char* name : {"room.gltf", "room.glb"}) {
        SCOPED_TRACE(name);
        const fs::path file = dir_ / name;
        EXPECT_TRUE(writeGltfScene(scene, file).empty());
        const Scene back = loadSceneFile(file);
        EXPECT_TRUE(back.notes.empty()) << back.notes.front();
        EXPECT_EQ(back.name, scene.name);
        EXPECT_EQ(back.ambient, scene.ambient);
        EXPECT_EQ(back.background, scene.background);
        EXPECT_EQ(back.camera.position, scene.camera.position);
        EXPECT_EQ(back.camera.target, scene.camera.target);
        EXPECT_EQ(back.camera.up, scene.camera.up);
        EXPECT_FLOAT_EQ(back.camera.fovYDeg, scene.camera.fovYDeg);
        EXPECT_EQ(back.camera.nearPlane, scene.camera.nearPlane);
        EXPECT_EQ(back.camera.farPlane, scene.camera.farPlane);
        ASSERT_EQ(back.lights.size(), scene.lights.size());
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            const Light &a = scene.lights[l], &b = back.lights[l];
            EXPECT_EQ(b.type, a.type);
            EXPECT_EQ(b.position, a.position);
            EXPECT_FLOAT_EQ(b.intensity, a.intensity);
            EXPECT_FLOAT_EQ(b.size, a.size);
            EXPECT_EQ(b.shadow.technique, a.shadow.technique);
            const OptionTable& table = mapOptionTable();
            for (const OptionField& f : table.fields)
                EXPECT_EQ(table.valueText(f, b.shadow.get<MapOptions>()), table.valueText(f, a.shadow.get<MapOptions>())) << f.key;
        }
        // Every draw item keeps its material and its shadow flags.
        const std::vector<DrawItem> items = scene.drawItems(), backItems = back.drawItems();
        ASSERT_EQ(backItems.size(), items.size());
        int nonCasters = 0;
        for (std::size_t i = 0; i < items.size(); ++i) {
            EXPECT_EQ(backItems[i].castsShadows, items[i].castsShadows) << i;
            EXPECT_EQ(backItems[i].receivesShadows, items[i].receivesShadows) << i;
            nonCasters += items[i].castsShadows ? 0 : 1;
            const Material d;
            const Material& a = items[i].material >= 0 ? scene.materials[static_cast<std::size_t>(items[i].material)] : d;
            const Material& b = backItems[i].material >= 0 ? back.materials[static_cast<std::size_t>(backItems[i].material)] : d;
            EXPECT_EQ(b.baseColor, a.baseColor) << i;
            EXPECT_EQ(b.specular, a.specular) << i;
            EXPECT_EQ(b.ambient, a.ambient) << i;
            EXPECT_FLOAT_EQ(b.shininess, a.shininess) << i;
        }
        EXPECT_GT(nonCasters, 0) << "room-point's bulb casts no shadow";
    }
}

TEST_F(GltfSceneTest, ExportRefusesANameThatIsNotGltf) {
    try {
        writeGltfScene(Scene{}, dir_ / "scene.obj");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("scene.obj: expected a name ending in .gltf or .glb"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir_ / "scene.obj"));
}

// --camera N (SceneFileOptions::gltfCamera): the file's second camera, in
// node order; past the last, or for a scene file, one line saying so.
TEST_F(GltfSceneTest, ACameraIsChosenByItsIndex) {
    json m = litModel();
    m["nodes"].push_back({{"name", "second eye"}, {"translation", {0, 7, 0}}, {"camera", 0}});
    m["scenes"][0]["nodes"].push_back(4);
    const fs::path file = write(m);
    EXPECT_NEAR(loadSceneFile(file, {}, SceneFileOptions{1}).camera.position.y, 7.0f, 1e-6f);
    EXPECT_NEAR(loadSceneFile(file, {}, SceneFileOptions{0}).camera.position.z, 5.0f, 1e-6f);
    try {
        loadSceneFile(file, {}, SceneFileOptions{2});
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("model.gltf: cameras: camera 2: the scene places 2 camera(s)"), std::string::npos) << e.what();
    }
    std::ofstream(dir_ / "scene.json") << R"({"nodes": []})";
    EXPECT_THROW(loadSceneFile(dir_ / "scene.json", {}, SceneFileOptions{0}), Error);
}

// A scene file includes a glTF's lights ({"gltf": FILE} in `lights`) and
// camera ({"gltf": FILE, "index": N}), before --set addresses them; bad
// includes name the scene file, the JSON path and the glTF's own error.
TEST_F(GltfSceneTest, ASceneFileIncludesAGltfsLightsAndCamera) {
    write(litModel());
    std::ofstream(dir_ / "scene.json") << R"({
      "camera": {"gltf": "model.gltf", "index": 0},
      "lights": [{"type": "point", "position": [0, 3, 0]}, {"gltf": "model.gltf"}],
      "nodes": [{"mesh": "model.gltf"}]})";
    const Scene scene = loadSceneFile(dir_ / "scene.json", {"lights[2].shadow.technique=volume"});
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].name, "sun");
    EXPECT_EQ(scene.lights[2].type, LightType::Spot);
    EXPECT_EQ(scene.lights[2].shadow.technique, "volume");
    EXPECT_NEAR(scene.camera.position.z, 5.0f, 1e-6f);
    const std::vector<std::pair<std::string, std::string>> cases{
        {R"({"lights": [{"gltf": "missing.gltf"}]})", "scene.json: lights[0].gltf: "},
        {R"({"lights": [{"gltf": "bare.gltf"}]})", "scene.json: lights[0].gltf: bare.gltf has no KHR_lights_punctual light"},
        {R"({"lights": [{"gltf": "model.gltf", "intensity": 2}]})", "scene.json: lights[0].intensity: unknown key beside \"gltf\""},
        {R"({"camera": {"gltf": "bare.gltf"}})", "scene.json: camera.gltf: bare.gltf places no camera"},
        {R"({"camera": {"gltf": "model.gltf", "index": -1}})", "scene.json: camera.index: expected an integer from 0"},
        {R"({"camera": {"gltf": "model.gltf", "index": 4}})", "scene.json: camera.gltf: "},
        {R"({"camera": {"gltf": "scene.json"}})", "scene.json: camera.gltf: scene.json: expected a .gltf or .glb file"},
    };
    write(triangleModel(), "bare.gltf");
    for (const auto& [text, expected] : cases) {
        std::ofstream(dir_ / "scene.json") << text;
        try {
            loadSceneFile(dir_ / "scene.json");
            ADD_FAILURE() << "no error: " << text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
        }
    }
}

// Orthographic cameras: ymag is half the view's height (Camera::orthoHeight);
// a znear of 0 becomes a small positive near plane, with a note; bad values
// name their path. A scene with one refuses volumes and cascades by path.
TEST_F(GltfSceneTest, OrthographicCamerasKeepTheirHeight) {
    json m = litModel();
    m["cameras"][0] = json::parse(R"({"type": "orthographic", "orthographic": {"xmag": 3, "ymag": 2, "znear": 0, "zfar": 40}})");
    const Scene scene = loadSceneFile(write(m));
    EXPECT_FLOAT_EQ(scene.camera.orthoHeight, 4.0f);
    EXPECT_FLOAT_EQ(scene.camera.farPlane, 40.0f);
    EXPECT_GT(scene.camera.nearPlane, 0.0f);
    ASSERT_EQ(scene.notes.size(), 1u);
    EXPECT_NE(scene.notes[0].find("cameras[0] has znear 0"), std::string::npos) << scene.notes[0];
    const glm::mat4 clip = scene.camera.clipFromView(1.5f);
    EXPECT_FLOAT_EQ(clip[3][3], 1.0f) << "orthographic: w stays 1";
    EXPECT_FLOAT_EQ(clip[1][1], 0.5f) << "2 / height";
    // Written and read back, the height stays.
    const fs::path again = dir_ / "again.gltf";
    writeGltfScene(scene, again);
    EXPECT_FLOAT_EQ(loadSceneFile(again).camera.orthoHeight, 4.0f);
    const std::vector<std::pair<std::string, std::string>> cases{
        {R"({"xmag": 1, "ymag": 0, "znear": 0.1, "zfar": 9})", "cameras[0].orthographic.ymag: must be greater than 0"},
        {R"({"xmag": 1, "ymag": 1, "znear": -1, "zfar": 9})", "cameras[0].orthographic.znear: must be 0 or more"},
        {R"({"xmag": 1, "ymag": 1, "znear": 2, "zfar": 1})", "cameras[0].orthographic.zfar: must be greater than znear"},
    };
    for (const auto& [lens, expected] : cases) {
        m["cameras"][0]["orthographic"] = json::parse(lens);
        const std::string message = errorOf(m);
        EXPECT_NE(message.find("model.gltf: " + expected), std::string::npos) << message;
    }
    std::ofstream(dir_ / "scene.json") << R"({"camera": {"orthoHeight": 6}, "lights": [{"type": "directional"}]})";
    EXPECT_FLOAT_EQ(loadSceneFile(dir_ / "scene.json").camera.orthoHeight, 6.0f);
    for (const std::string set : {"lights[0].shadow.technique=volume", "lights[0].shadow.map.cascades=2"}) {
        try {
            loadSceneFile(dir_ / "scene.json", {set});
            ADD_FAILURE() << "no error: " << set;
        } catch (const UnsupportedError& e) {
            EXPECT_NE(std::string(e.what()).find("perspective"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("--set " + set), std::string::npos) << e.what();
        }
    }
}
