// The animated camera (camera.path): eye and target along keyframes at known
// times, clamped and looped as a light's keyframes are, cameraAtTime /
// sceneAtTime, and every error path of the scene file's `camera.path` block
// (one line naming the file or flag and the JSON path).
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include "ErrorText.h"
#include "SceneErrorCase.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

// Positions are floats computed in double: a few ulps of the largest coordinate.
constexpr float kTolerance = 1e-5f;

Scene parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return parseScene(text, "scene.json", fs::temp_directory_path(), overrides);
}

// A scene whose camera (at [0, 2, 10], looking at the origin) has path `path`.
std::string cameraWithPath(const std::string& path, const std::string& extra = "") {
    return R"({"camera": {"position": [0, 2, 10], "target": [0, 0, 0], )" + extra + R"("path": )" + path + "}}";
}

// Keys along +X: eyes at x = 0, 2, 2 (y = 2), targets 10 units ahead in -Z, the last one turned to +X.
const char* kWalk = R"({"type": "keyframes", "times": [1, 2, 4],
    "positions": [[0, 2, 0], [2, 2, 0], [2, 2, 0]], "targets": [[0, 2, -10], [2, 2, -10], [12, 2, 0]]})";

void expectNear(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_NEAR(glm::distance(actual, expected), 0.0f, kTolerance)
        << "actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", " << expected.y << ", "
        << expected.z << ")";
}

void expectPose(const Camera& camera, const glm::vec3& position, const glm::vec3& target) {
    expectNear(camera.position, position);
    expectNear(camera.target, target);
}

} // namespace

TEST(CameraPath, ReadsKeysAndDefaults) {
    const Scene s = parse(cameraWithPath(kWalk));
    ASSERT_TRUE(s.camera.path.has_value());
    const CameraPath& p = *s.camera.path;
    EXPECT_EQ(p.times, (std::vector<double>{1.0, 2.0, 4.0}));  // in double, as written
    ASSERT_EQ(p.positions.size(), 3u);
    ASSERT_EQ(p.targets.size(), 3u);
    EXPECT_EQ(p.positions[1], glm::vec3(2, 2, 0));
    EXPECT_EQ(p.targets[2], glm::vec3(12, 2, 0));
    EXPECT_FALSE(p.loop);  // documented default
    // The static camera stays as written: it is what a scene used without a time shows.
    EXPECT_EQ(s.camera.position, glm::vec3(0, 2, 10));
    EXPECT_EQ(s.camera.target, glm::vec3(0, 0, 0));
    EXPECT_FALSE(parse(R"({"camera": {"position": [0, 2, 10]}})").camera.path.has_value());  // no path: static
}

TEST(CameraPath, InterpolatesEyeAndTargetLinearlyAndClamps) {
    const Scene s = parse(cameraWithPath(kWalk));
    expectPose(cameraAtTime(s.camera, 1.0), {0, 2, 0}, {0, 2, -10});      // on a key
    expectPose(cameraAtTime(s.camera, 1.25), {0.5f, 2, 0}, {0.5f, 2, -10});
    expectPose(cameraAtTime(s.camera, 3.0), {2, 2, 0}, {7, 2, -5});       // half way through the longer segment: only the target moves
    expectPose(cameraAtTime(s.camera, 4.0), {2, 2, 0}, {12, 2, 0});
    // Outside the keys' times: the first and the last key.
    expectPose(cameraAtTime(s.camera, -50.0), {0, 2, 0}, {0, 2, -10});
    expectPose(cameraAtTime(s.camera, 1e9), {2, 2, 0}, {12, 2, 0});
}

TEST(CameraPath, LoopsWithTheSamePeriodAsALightsKeyframes) {
    const Scene s = parse(R"({
      "camera": {"path": {"type": "keyframes", "times": [1, 2, 3], "positions": [[0, 1, 0], [4, 1, 0], [0, 1, 0]],
                          "targets": [[0, 0, -5], [4, 0, -5], [0, 0, -5]], "loop": true}},
      "lights": [{"type": "point", "position": [0, 0, 0],
                  "path": {"type": "keyframes", "times": [1, 2, 3], "positions": [[0, 1, 0], [4, 1, 0], [0, 1, 0]], "loop": true}}]})");
    ASSERT_TRUE(s.camera.path->loop);
    // Period 2 s: 3.5 is 1.5, 6 is 2, -2.5 is 1.5, and before the first key the loop wraps too.
    expectPose(cameraAtTime(s.camera, 3.5), {2, 1, 0}, {2, 0, -5});
    expectPose(cameraAtTime(s.camera, 6.0), {4, 1, 0}, {4, 0, -5});
    expectPose(cameraAtTime(s.camera, -2.5), {2, 1, 0}, {2, 0, -5});
    // The camera's eye and a light with the same keys agree at every time:
    // both go through one evaluation of keyframes.
    for (const double t : {-7.3, 0.0, 0.5, 1.0, 1.7, 2.0, 2.999, 3.0, 41.25, 1e6 + 0.3}) {
        SCOPED_TRACE(t);
        EXPECT_EQ(cameraAtTime(s.camera, t).position, lightAtTime(s.lights[0], t).position);
    }
    // One key: that pose, always.
    const Scene one = parse(cameraWithPath(R"({"type": "keyframes", "times": [5], "positions": [[1, 2, 3]], "targets": [[1, 2, 0]], "loop": true})"));
    expectPose(cameraAtTime(one.camera, -7.0), {1, 2, 3}, {1, 2, 0});
    expectPose(cameraAtTime(one.camera, 123.0), {1, 2, 3}, {1, 2, 0});
}

TEST(CameraPath, CameraAtTimeRemovesThePathAndKeepsTheRest) {
    const Scene s = parse(cameraWithPath(kWalk, R"("up": [0.1, 1, 0], "fovY": 30, "near": 0.5, "far": 400, )"));
    const Camera at = cameraAtTime(s.camera, 1.5);
    expectPose(at, {1, 2, 0}, {1, 2, -10});
    EXPECT_FALSE(at.path.has_value());
    EXPECT_EQ(at.up, s.camera.up);
    EXPECT_EQ(at.fovYDeg, 30.0f);
    EXPECT_EQ(at.nearPlane, 0.5f);
    EXPECT_EQ(at.farPlane, 400.0f);
    expectPose(cameraAtTime(at, 4.0), {1, 2, 0}, {1, 2, -10});  // static now: not moved again
    const Camera still = parse("{}").camera;
    expectPose(cameraAtTime(still, 3.0), still.position, still.target);  // no path: unchanged
}

TEST(CameraPath, SceneAtTimeMovesTheCameraWithTheLights) {
    const Scene s = parse(R"({"camera": {"path": )" + std::string(kWalk) + R"(},
      "lights": [{"type": "point", "position": [0, 3, 0], "path": {"type": "keyframes", "times": [0, 2], "positions": [[0, 3, 0], [4, 3, 0]]}}]})");
    const Scene at = sceneAtTime(s, 1.5);
    expectPose(at.camera, {1, 2, 0}, {1, 2, -10});
    expectNear(at.lights[0].position, {3, 3, 0});
    EXPECT_FALSE(at.camera.path.has_value());
    ASSERT_TRUE(s.camera.path.has_value());  // the original is untouched
    EXPECT_EQ(s.camera.position, Camera{}.position);
    // The view matrix follows: the eye at (1, 2, 0) maps to the view-space origin.
    const glm::vec4 eye = at.camera.viewFromWorld() * glm::vec4(1, 2, 0, 1);
    expectNear(glm::vec3(eye), {0, 0, 0});
}

TEST(CameraPath, OverridesReachIntoThePath) {
    const Scene s = parse(cameraWithPath(kWalk), {"camera.path.loop=true", "camera.path.targets[0]=[0,2,-20]"});
    EXPECT_TRUE(s.camera.path->loop);
    EXPECT_EQ(s.camera.path->targets[0], glm::vec3(0, 2, -20));
    // A whole path set on a camera that had none.
    const Scene added = parse("{}", {R"(camera.path={"type":"keyframes","times":[0,1],"positions":[[0,1,5],[0,1,6]],"targets":[[0,0,0],[0,0,0]]})"});
    expectPose(cameraAtTime(added.camera, 0.5), {0, 1, 5.5f}, {0, 0, 0});
}

TEST(CameraPath, NonFiniteTimesAndBrokenPathsThroughTheApiAreErrors) {
    Camera camera;
    camera.path = CameraPath{{0.0}, {{0, 1, 5}}, {{0, 0, 0}}, false};
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(errorOf([&] { cameraAtTime(camera, nan); }).find("cameraAtTime: the time must be a finite number of seconds"), std::string::npos);
    EXPECT_NE(errorOf([&] { camera.path->poseAt(inf); }).find("CameraPath::poseAt: the time must be"), std::string::npos);
    camera.path->targets.push_back({1, 0, 0});
    EXPECT_NE(errorOf([&] { cameraAtTime(camera, 0.5); }).find("as many targets as times (got 1 times, 2 targets)"), std::string::npos);
    camera.path = CameraPath{};
    EXPECT_NE(errorOf([&] { cameraAtTime(camera, 0.5); }).find("at least one key"), std::string::npos);
}

// --- Errors in the scene file: one line, file or flag, JSON path -------------

class CameraPathErrors : public ::testing::TestWithParam<SceneErrorCase> {};

TEST_P(CameraPathErrors, NameFilePathAndExpectation) { expectSceneError(GetParam()); }

namespace {
// A keyframe path with `times`, `positions` and `targets` as written.
std::string keys(const std::string& times, const std::string& positions, const std::string& targets, const std::string& extra = "") {
    return cameraWithPath(R"({"type": "keyframes", "times": )" + times + R"(, "positions": )" + positions + R"(, "targets": )" + targets +
                          extra + "}");
}
} // namespace

INSTANTIATE_TEST_SUITE_P(
    All, CameraPathErrors,
    ::testing::Values(
        SceneErrorCase{"NotAnObject", cameraWithPath("[0, 0, 3]"), {}, "scene.json: camera.path: expected an object, got an array"},
        SceneErrorCase{"MissingType", cameraWithPath(R"({"times": [0]})"), {}, "camera.path: missing key 'type' (keyframes)"},
        SceneErrorCase{"TypeNotAString", cameraWithPath(R"({"type": 1})"), {}, "camera.path.type: expected a string, got a number"},
        SceneErrorCase{"Sine", cameraWithPath(R"({"type": "sine", "amplitude": [1, 0, 0]})"), {},
                       "camera.path.type: unknown path type 'sine' (a camera path has keyframes only)"},
        SceneErrorCase{"UnknownKey", keys("[0]", "[[0,1,5]]", "[[0,0,0]]", R"(, "up": [0, 1, 0])"), {}, "camera.path.up: unknown key"},
        SceneErrorCase{"MissingTimes", cameraWithPath(R"({"type": "keyframes", "positions": [[0,1,5]], "targets": [[0,0,0]]})"), {},
                       "camera.path: missing key 'times' (seconds, strictly increasing)"},
        SceneErrorCase{"MissingPositions", cameraWithPath(R"({"type": "keyframes", "times": [0], "targets": [[0,0,0]]})"), {},
                       "camera.path: missing key 'positions' (one [x, y, z] per time)"},
        SceneErrorCase{"MissingTargets", cameraWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0,1,5]]})"), {},
                       "camera.path: missing key 'targets' (one [x, y, z] per time)"},
        SceneErrorCase{"TimesNotArray", keys("0", "[[0,1,5]]", "[[0,0,0]]"), {}, "camera.path.times: expected an array, got a number"},
        SceneErrorCase{"NoKeys", keys("[]", "[]", "[]"), {}, "camera.path.times: expected at least one time"},
        SceneErrorCase{"TimesEqual", keys("[0, 1, 1]", "[[0,1,5],[0,1,6],[0,1,7]]", "[[0,0,0],[0,0,0],[0,0,0]]"), {},
                       "camera.path.times[2]: expected times strictly increasing, got 1 after 1"},
        SceneErrorCase{"TimesDecreasing", keys("[2, 1]", "[[0,1,5],[0,1,6]]", "[[0,0,0],[0,0,0]]"), {},
                       "camera.path.times[1]: expected times strictly increasing, got 1 after 2"},
        SceneErrorCase{"TimeString", keys(R"(["0"])", "[[0,1,5]]", "[[0,0,0]]"), {}, "camera.path.times[0]: expected a number, got a string"},
        SceneErrorCase{"TimePastAFloat", keys("[0, 1e300]", "[[0,1,5],[0,1,6]]", "[[0,0,0],[0,0,0]]"), {},
                       "camera.path.times[1]: expected a finite number"},
        SceneErrorCase{"TimeInfinite", keys("[1e999]", "[[0,1,5]]", "[[0,0,0]]"), {},
                       "invalid JSON: number overflow parsing '1e999' (numbers must be finite)"},
        SceneErrorCase{"TargetsNotArray", keys("[0]", "[[0,1,5]]", "{}"), {}, "camera.path.targets: expected an array, got an object"},
        SceneErrorCase{"FewerPositions", keys("[0, 1]", "[[0,1,5]]", "[[0,0,0],[0,0,0]]"), {},
                       "camera.path.positions: expected one position per time (2), got 1"},
        SceneErrorCase{"MoreTargets", keys("[0]", "[[0,1,5]]", "[[0,0,0],[0,0,0]]"), {},
                       "camera.path.targets: expected one target per time (1), got 2"},
        SceneErrorCase{"TargetTwoNumbers", keys("[0, 1]", "[[0,1,5],[0,1,6]]", "[[0,0,0],[0,0]]"), {},
                       "camera.path.targets[1]: expected 3 numbers, got 2"},
        SceneErrorCase{"TargetNull", keys("[0]", "[[0,1,5]]", "[[0,null,0]]"), {}, "camera.path.targets[0][1]: expected a number, got null"},
        SceneErrorCase{"PositionPastAFloat", keys("[0]", "[[0,4e38,0]]", "[[0,0,0]]"), {}, "camera.path.positions[0][1]: expected a finite number"},
        SceneErrorCase{"LoopNotBoolean", keys("[0]", "[[0,1,5]]", "[[0,0,0]]", R"(, "loop": 1)"), {},
                       "camera.path.loop: expected true or false, got a number"},
        // Every key, and every point between two, must give the camera a view direction.
        SceneErrorCase{"KeyCoincides", keys("[0, 1]", "[[0,1,5],[0,1,6]]", "[[0,0,0],[0,1,6]]"), {},
                       "camera.path.targets[1]: key 1: camera position and target coincide"},
        SceneErrorCase{"KeyAlongUp", keys("[0, 1]", "[[0,1,5],[0,5,0]]", "[[0,0,0],[0,0,0]]"), {},
                       "camera.path.targets[1]: key 1: camera up is parallel to the view direction"},
        SceneErrorCase{"KeyAlongTiltedUp", cameraWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0,0,0]], "targets": [[1,0,1]]})",
                                                             R"("up": [1, 0, 1], )"),
                       {}, "camera.path.targets[0]: key 0: camera up is parallel to the view direction"},
        SceneErrorCase{"KeyTooFarApart", keys("[0]", "[[-2e19,0,0]]", "[[2e19,0,1]]"), {},
                       "camera.path.targets[0]: key 0: camera position and target are too far apart"},
        // Eye and target swap sides: half way they meet.
        SceneErrorCase{"PassesThroughTarget", keys("[0, 2]", "[[-1,1,0],[1,1,0]]", "[[1,1,0],[-1,1,0]]"), {},
                       "camera.path.targets[1]: between keys 0 and 1 the camera passes through its target (add a key in between)"},
        // Looking down at -Z then down at +Z: straight down half way.
        SceneErrorCase{"TurnsThroughUp", keys("[0, 1, 2]", "[[0,5,0],[0,5,0],[0,5,0]]", "[[0,0,-1],[0,0,-1],[0,0,1]]"), {},
                       "camera.path.targets[2]: between keys 1 and 2 the camera looks along camera up"},
        // --set: the flag is named, with the path and what was wrong.
        SceneErrorCase{"SetTargetsBad", cameraWithPath(kWalk), {"camera.path.targets=[[0,0]]"},
                       "--set camera.path.targets=[[0,0]]: camera.path.targets: expected one target per time (3), got 1"},
        SceneErrorCase{"SetTimesDecreasing", cameraWithPath(kWalk), {"camera.path.times=[3,2,1]"},
                       "--set camera.path.times=[3,2,1]: camera.path.times[1]: expected times strictly increasing, got 2 after 3"},
        SceneErrorCase{"SetTypeOnStaticCamera", "{}", {"camera.path.type=sine"},
                       "--set camera.path.type=sine: camera.path.type: unknown path type 'sine'"}),
    sceneErrorCaseName);
