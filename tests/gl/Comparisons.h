#pragma once
// What the technique tests share: a scene from JSON text, one scene against
// the ray-traced reference on a fresh renderer, and the misclassified share
// away from the 1-pixel edge band.
#include "GLTestContext.h"

#include <shadowlab/Compare.h>
#include <shadowlab/SceneFile.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab::test {

// A scene from JSON text with `--set`-style overrides, relative paths from
// the source tree (its errors name the file "test-scene.json").
inline Scene sceneOf(const std::string& json, const std::vector<std::string>& overrides = {}) {
    return parseScene(json, "test-scene.json", SHADOWLAB_SOURCE_DIR, overrides);
}

inline Comparison compareScene(const Scene& scene, int width = 960, int height = 540, int softSamples = 256) {
    Renderer renderer(glContext());
    renderer.upload(scene);
    CompareOptions options;
    options.width = width;
    options.height = height;
    options.softSamples = softSamples;
    return compareWithReference(renderer, scene, options);
}

// The scene files in scenes/, sorted: the scenes of one light each that
// the accuracy and performance bars name. many-lights.json (64 lights from
// a lightGrid, their maps in the shadow atlas) has its own tests
// (LightListGLTest, ShadowAtlasGLTest).
inline std::vector<std::filesystem::path> bundledScenes() {
    std::vector<std::filesystem::path> out;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes"))
        if (entry.path().extension() == ".json" && entry.path().filename() != "many-lights.json") out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

inline double awayFromEdges(const LightComparison& l) { return l.falseLitAwayFromEdges + l.falseShadowAwayFromEdges; }

} // namespace shadowlab::test
