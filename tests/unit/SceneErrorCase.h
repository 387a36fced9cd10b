#pragma once
// A bad scene text and the error it must give, for the parameterised error
// tests of the scene file's blocks (light paths, camera paths): one line,
// naming the file, or the --set flag when the case has overrides.
#include <shadowlab/SceneFile.h>

#include "ErrorText.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

struct SceneErrorCase {
    const char* name;
    std::string text;                    ///< the scene file's text, read as "scene.json"
    std::vector<std::string> overrides;  ///< --set lines
    std::string expected;                ///< the message must contain this
};
inline void PrintTo(const SceneErrorCase& c, std::ostream* os) { *os << c.name; }
inline std::string sceneErrorCaseName(const ::testing::TestParamInfo<SceneErrorCase>& p) { return p.param.name; }

inline void expectSceneError(const SceneErrorCase& c) {
    const std::string message = errorOf([&] { shadowlab::parseScene(c.text, "scene.json", std::filesystem::temp_directory_path(), c.overrides); });
    EXPECT_NE(message.find(c.expected), std::string::npos) << "message: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    if (c.overrides.empty()) EXPECT_EQ(message.rfind("scene.json: ", 0), 0u) << message;
    else EXPECT_EQ(message.rfind("--set ", 0), 0u) << message;
}
