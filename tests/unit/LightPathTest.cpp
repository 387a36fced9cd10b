// Animated lights (lights[i].path): positions along sine and keyframe paths
// at known times, sceneAtTime / lightAtTime, and every error path of the
// scene file's `path` block (one line naming the file or flag and the JSON path).
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
constexpr double kPi = 3.14159265358979323846;

Scene parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return parseScene(text, "scene.json", fs::temp_directory_path(), overrides);
}

// A scene whose only light is a point light at `position` with path `path`.
std::string pointWithPath(const std::string& path, const std::string& position = "[1, 2, 3]") {
    return R"({"lights": [{"type": "point", "position": )" + position + R"(, "path": )" + path + "}]}";
}

LightPath keyframes(std::vector<double> times, std::vector<glm::vec3> positions, bool loop) {
    LightPath p;
    p.type = LightPath::Type::Keyframes;
    p.times = std::move(times);
    p.positions = std::move(positions);
    p.loop = loop;
    return p;
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_NEAR(glm::distance(actual, expected), 0.0f, kTolerance)
        << "actual (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", " << expected.y << ", "
        << expected.z << ")";
}

} // namespace

TEST(LightPath, SineReadsValuesAndDefaults) {
    const Scene s = parse(pointWithPath(R"({"type": "sine", "amplitude": [0, 0, 3]})"));
    ASSERT_TRUE(s.lights[0].path.has_value());
    const LightPath& p = *s.lights[0].path;
    EXPECT_EQ(p.type, LightPath::Type::Sine);
    EXPECT_EQ(p.amplitude, glm::vec3(0, 0, 3));
    EXPECT_DOUBLE_EQ(p.angularFrequency, 1.0);  // documented default, rad/s
    EXPECT_DOUBLE_EQ(p.phase, 0.0);             // documented default, rad
    EXPECT_EQ(s.lights[0].position, glm::vec3(1, 2, 3));  // the centre, as written
    EXPECT_FALSE(parse(R"({"lights": [{"type": "point", "position": [0, 1, 0]}]})").lights[0].path.has_value());  // no path: static
}

TEST(LightPath, SineAtKnownTimes) {
    LightPath p;
    p.amplitude = {0, 0, 3};
    p.angularFrequency = 0.5;
    const glm::vec3 base(0, 2.5f, 0);
    // The lecture's light: z = sin(0.5 t) * 3.
    expectNear(p.positionAt(base, 0.0), base);
    expectNear(p.positionAt(base, kPi), base + glm::vec3(0, 0, 3));          // 0.5 * pi = pi / 2
    expectNear(p.positionAt(base, 2.0 * kPi), base);                         // pi
    expectNear(p.positionAt(base, 3.0 * kPi), base + glm::vec3(0, 0, -3));   // 3 pi / 2
    expectNear(p.positionAt(base, 1.0), base + glm::vec3(0, 0, 3.0f * static_cast<float>(std::sin(0.5))));
    // Phase and every axis.
    p.amplitude = {1, -2, 4};
    p.angularFrequency = 2.0;
    p.phase = kPi / 2;  // sin(2 t + pi/2) = cos(2 t)
    expectNear(p.positionAt(base, 0.0), base + glm::vec3(1, -2, 4));
    expectNear(p.positionAt(base, kPi / 2), base - glm::vec3(1, -2, 4));
    expectNear(p.positionAt(base, 0.3), base + glm::vec3(1, -2, 4) * static_cast<float>(std::cos(0.6)));
}

TEST(LightPath, KeyframesInterpolateLinearly) {
    const LightPath p = keyframes({1, 2, 4}, {{0, 0, 0}, {2, 0, 0}, {2, 4, 0}}, false);
    expectNear(p.positionAt({}, 1.0), {0, 0, 0});     // on a key
    expectNear(p.positionAt({}, 1.25), {0.5f, 0, 0});
    expectNear(p.positionAt({}, 2.0), {2, 0, 0});
    expectNear(p.positionAt({}, 3.0), {2, 2, 0});     // half way through the second, longer segment
    expectNear(p.positionAt({}, 4.0), {2, 4, 0});
    // The base position does not matter: keys are world space.
    expectNear(p.positionAt({9, 9, 9}, 3.0), {2, 2, 0});
}

TEST(LightPath, KeyframesClampOutsideTheirTimes) {
    const LightPath p = keyframes({1, 2}, {{0, 0, 0}, {2, 0, 0}}, false);
    expectNear(p.positionAt({}, 0.0), {0, 0, 0});
    expectNear(p.positionAt({}, -100.0), {0, 0, 0});
    expectNear(p.positionAt({}, 2.5), {2, 0, 0});
    expectNear(p.positionAt({}, 1e9), {2, 0, 0});
}

TEST(LightPath, KeyframesLoopWrapsWithTheirPeriod) {
    // Period 2 s (times 1..3); the key at 3 s is where the next period's first key takes over.
    const LightPath p = keyframes({1, 2, 3}, {{0, 0, 0}, {4, 0, 0}, {0, 0, 0}}, true);
    expectNear(p.positionAt({}, 1.5), {2, 0, 0});
    expectNear(p.positionAt({}, 3.5), {2, 0, 0});   // one period later
    expectNear(p.positionAt({}, 6.0), {4, 0, 0});   // 6 = 2 + 2 periods
    expectNear(p.positionAt({}, 0.5), {2, 0, 0});   // before the first key: wrapped too (0.5 + 2 = 2.5)
    expectNear(p.positionAt({}, -2.5), {2, 0, 0});  // -2.5 + 2 periods = 1.5
    expectNear(p.positionAt({}, 1001.25), {1, 0, 0});
    // A loop over one key is that key.
    const LightPath one = keyframes({5}, {{1, 2, 3}}, true);
    expectNear(one.positionAt({}, -7.0), {1, 2, 3});
    expectNear(one.positionAt({}, 123.0), {1, 2, 3});
}

TEST(LightPath, KeyframesParsedFromTheSceneFile) {
    const Scene s = parse(pointWithPath(R"({"type": "keyframes", "times": [0, 0.5], "positions": [[0, 1, 0], [1, 1, 0]], "loop": true})"));
    ASSERT_TRUE(s.lights[0].path.has_value());
    const LightPath& p = *s.lights[0].path;
    EXPECT_EQ(p.type, LightPath::Type::Keyframes);
    EXPECT_EQ(p.times, (std::vector<double>{0.0, 0.5}));  // in double, as written
    ASSERT_EQ(p.positions.size(), 2u);
    EXPECT_EQ(p.positions[1], glm::vec3(1, 1, 0));
    EXPECT_TRUE(p.loop);
    EXPECT_FALSE(parse(pointWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0, 1, 0]]})")).lights[0].path->loop);  // default
}

TEST(LightPath, LightAtTimeMovesOnlyThePositionAndRemovesThePath) {
    const Scene s = parse(R"({"lights": [
        {"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 1], "path": {"type": "sine", "amplitude": [2, 0, 0], "phase": 1.5707963267948966}},
        {"type": "directional", "direction": [1, -1, 0]},
        {"type": "point", "position": [5, 5, 5]}]})");
    const Light spot = lightAtTime(s.lights[0], 0.0);
    expectNear(spot.position, {2, 4, 0});
    EXPECT_EQ(spot.direction, s.lights[0].direction);  // a spot keeps its direction
    EXPECT_FALSE(spot.path.has_value());
    expectNear(lightAtTime(spot, 0.0).position, {2, 4, 0});  // static now: not moved twice
    const Scene at = sceneAtTime(s, kPi / 2);  // sin(pi/2 + pi/2) = 0
    expectNear(at.lights[0].position, {0, 4, 0});
    EXPECT_EQ(at.lights[1].direction, s.lights[1].direction);
    EXPECT_EQ(at.lights[2].position, glm::vec3(5, 5, 5));
    for (const Light& l : at.lights) EXPECT_FALSE(l.path.has_value());
    EXPECT_EQ(s.lights[0].position, glm::vec3(0, 4, 0));  // the original is untouched
}

TEST(LightPath, TheRoomFollowsTheLecturesPath) {
    const Scene s = loadSceneFile(fs::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "room-point.json");
    // Lawonn's lecture: lightPos.z = sin(t * 0.5) * 3, around the room's bulb at (0, 2.5, 0).
    for (const double t : {0.0, 0.7, 2.0, 9.0}) {
        SCOPED_TRACE(t);
        expectNear(sceneAtTime(s, t).lights[0].position, {0, 2.5f, 3.0f * static_cast<float>(std::sin(0.5 * t))});
    }
}

TEST(LightPath, OverridesReachIntoThePath) {
    const Scene s = parse(pointWithPath(R"({"type": "sine", "amplitude": [0, 0, 3]})"),
                          {"lights[0].path.amplitude=[1,0,0]", "lights[0].path.angularFrequency=2"});
    EXPECT_EQ(s.lights[0].path->amplitude, glm::vec3(1, 0, 0));
    EXPECT_DOUBLE_EQ(s.lights[0].path->angularFrequency, 2.0);
    // A whole path set on a light that had none.
    const Scene added = parse(R"({"lights": [{"type": "point", "position": [0, 1, 0]}]})",
                              {R"(lights[0].path={"type":"keyframes","times":[0,1],"positions":[[0,1,0],[0,2,0]]})"});
    expectNear(lightAtTime(added.lights[0], 0.5).position, {0, 1.5f, 0});
}

TEST(LightPath, NonFiniteTimesAndBrokenPathsThroughTheApiAreErrors) {
    LightPath p;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(errorOf([&] { p.positionAt({}, nan); }).find("finite"), std::string::npos);
    Light light;
    light.type = LightType::Point;
    light.path = p;
    EXPECT_NE(errorOf([&] { lightAtTime(light, inf); }).find("lightAtTime: the time must be a finite number of seconds"), std::string::npos);
    EXPECT_NE(errorOf([&] { sceneAtTime(Scene{}, -inf); }).find("sceneAtTime"), std::string::npos);
    const LightPath broken = keyframes({0, 1}, {{0, 0, 0}}, false);
    EXPECT_NE(errorOf([&] { broken.positionAt({}, 0.5); }).find("2 times, 1 positions"), std::string::npos);
}

// --- Errors in the scene file: one line, file or flag, JSON path -------------

class LightPathErrors : public ::testing::TestWithParam<SceneErrorCase> {};

TEST_P(LightPathErrors, NameFilePathAndExpectation) { expectSceneError(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    All, LightPathErrors,
    ::testing::Values(
        SceneErrorCase{"Directional", R"({"lights": [{"type": "directional", "path": {"type": "sine"}}]})", {},
                       "scene.json: lights[0].path: a directional light has no position to move"},
        SceneErrorCase{"NotAnObject", pointWithPath("[0, 0, 3]"), {}, "lights[0].path: expected an object, got an array"},
        SceneErrorCase{"MissingType", pointWithPath(R"({"amplitude": [0, 0, 3]})"), {}, "lights[0].path: missing key 'type' (sine or keyframes)"},
        SceneErrorCase{"TypeNotAString", pointWithPath(R"({"type": 3})"), {}, "lights[0].path.type: expected a string, got a number"},
        SceneErrorCase{"UnknownType", pointWithPath(R"({"type": "circle"})"), {}, "lights[0].path.type: unknown path type 'circle' (expected sine or keyframes)"},
        SceneErrorCase{"UnknownSineKey", pointWithPath(R"({"type": "sine", "frequency": 2})"), {}, "lights[0].path.frequency: unknown key"},
        SceneErrorCase{"KeyframeKeyOnSine", pointWithPath(R"({"type": "sine", "times": [0]})"), {}, "lights[0].path.times: unknown key"},
        SceneErrorCase{"AmplitudeTwoNumbers", pointWithPath(R"({"type": "sine", "amplitude": [0, 3]})"), {},
                       "lights[0].path.amplitude: expected 3 numbers, got 2"},
        SceneErrorCase{"AmplitudeString", pointWithPath(R"({"type": "sine", "amplitude": [0, "3", 0]})"), {},
                       "lights[0].path.amplitude[1]: expected a number, got a string"},
        SceneErrorCase{"AmplitudeOverflows", pointWithPath(R"({"type": "sine", "amplitude": [3e38, 0, 0]})", "[3e38, 0, 0]"), {},
                       "lights[0].path.amplitude: position + amplitude overflows a float"},
        SceneErrorCase{"InfiniteFrequency", pointWithPath(R"({"type": "sine", "angularFrequency": 1e999})"), {},
                       "invalid JSON: number overflow parsing '1e999' (numbers must be finite)"},
        SceneErrorCase{"FrequencyPastAFloat", pointWithPath(R"({"type": "sine", "angularFrequency": 1e300})"), {},
                       "lights[0].path.angularFrequency: expected a finite number"},
        SceneErrorCase{"NegativeFrequency", pointWithPath(R"({"type": "sine", "angularFrequency": -0.5})"), {},
                       "lights[0].path.angularFrequency: expected radians per second >= 0, got -0.5"},
        SceneErrorCase{"PhaseBoolean", pointWithPath(R"({"type": "sine", "phase": true})"), {}, "lights[0].path.phase: expected a number, got a boolean"},
        SceneErrorCase{"MissingTimes", pointWithPath(R"({"type": "keyframes", "positions": [[0, 0, 0]]})"), {},
                       "lights[0].path: missing key 'times'"},
        SceneErrorCase{"MissingPositions", pointWithPath(R"({"type": "keyframes", "times": [0]})"), {},
                       "lights[0].path: missing key 'positions'"},
        SceneErrorCase{"TimesNotArray", pointWithPath(R"({"type": "keyframes", "times": 0, "positions": [[0, 0, 0]]})"), {},
                       "lights[0].path.times: expected an array, got a number"},
        SceneErrorCase{"PositionsNotArray", pointWithPath(R"({"type": "keyframes", "times": [0], "positions": {}})"), {},
                       "lights[0].path.positions: expected an array, got an object"},
        SceneErrorCase{"NoKeys", pointWithPath(R"({"type": "keyframes", "times": [], "positions": []})"), {},
                       "lights[0].path.times: expected at least one time"},
        SceneErrorCase{"TimesEqual", pointWithPath(R"({"type": "keyframes", "times": [0, 1, 1], "positions": [[0,0,0],[1,0,0],[2,0,0]]})"), {},
                       "lights[0].path.times[2]: expected times strictly increasing, got 1 after 1"},
        SceneErrorCase{"TimesDecreasing", pointWithPath(R"({"type": "keyframes", "times": [2, 1], "positions": [[0,0,0],[1,0,0]]})"), {},
                       "lights[0].path.times[1]: expected times strictly increasing, got 1 after 2"},
        SceneErrorCase{"TimeString", pointWithPath(R"({"type": "keyframes", "times": ["0"], "positions": [[0,0,0]]})"), {},
                       "lights[0].path.times[0]: expected a number, got a string"},
        SceneErrorCase{"FewerPositions", pointWithPath(R"({"type": "keyframes", "times": [0, 1], "positions": [[0,0,0]]})"), {},
                       "lights[0].path.positions: expected one position per time (2), got 1"},
        SceneErrorCase{"MorePositions", pointWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0,0,0],[1,1,1]]})"), {},
                       "lights[0].path.positions: expected one position per time (1), got 2"},
        SceneErrorCase{"PositionTwoNumbers", pointWithPath(R"({"type": "keyframes", "times": [0, 1], "positions": [[0,0,0],[1,1]]})"), {},
                       "lights[0].path.positions[1]: expected 3 numbers, got 2"},
        SceneErrorCase{"PositionPastAFloat", pointWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0,4e38,0]]})"), {},
                       "lights[0].path.positions[0][1]: expected a finite number"},
        SceneErrorCase{"LoopNotBoolean", pointWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0,0,0]], "loop": "yes"})"), {},
                       "lights[0].path.loop: expected true or false, got a string"},
        SceneErrorCase{"UnknownKeyframeKey", pointWithPath(R"({"type": "keyframes", "times": [0], "positions": [[0,0,0]], "amplitude": [1,1,1]})"), {},
                       "lights[0].path.amplitude: unknown key"},
        // --set: the flag is named, with the path and what was wrong.
        SceneErrorCase{"SetAmplitudeBad", pointWithPath(R"({"type": "sine"})"), {"lights[0].path.amplitude=[0,0]"},
                       "--set lights[0].path.amplitude=[0,0]: lights[0].path.amplitude: expected 3 numbers, got 2"},
        SceneErrorCase{"SetFrequencyNaN", pointWithPath(R"({"type": "sine"})"), {"lights[0].path.angularFrequency=nan"},
                       "--set lights[0].path.angularFrequency=nan: lights[0].path.angularFrequency: expected a number, got a string"},
        SceneErrorCase{"SetPathOnDirectional", R"({"lights": [{"type": "directional"}]})", {"lights[0].path.type=sine"},
                       "--set lights[0].path.type=sine: lights[0].path: a directional light has no position to move"}),
    sceneErrorCaseName);
