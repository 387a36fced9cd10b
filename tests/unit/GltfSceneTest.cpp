// A glTF file opened as a whole scene (scene/GltfScene.h, loadSceneFile):
// its KHR_lights_punctual lights and cameras mapped as docs/scene-format.md
// says, notes where the file is silent, one line naming the JSON path for
// a bad light or camera.
#include "scene/GltfScene.h"

#include <shadowlab/Error.h>
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
