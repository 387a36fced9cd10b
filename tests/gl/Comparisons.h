#pragma once
// What the technique tests share: one scene against the ray-traced
// reference on a fresh renderer, and the misclassified share away from the
// 1-pixel edge band.
#include "GLTestContext.h"

#include <shadowlab/Compare.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace shadowlab::test {

inline Comparison compareScene(const Scene& scene, int width = 960, int height = 540, int softSamples = 256) {
    Renderer renderer(glContext());
    renderer.upload(scene);
    CompareOptions options;
    options.width = width;
    options.height = height;
    options.softSamples = softSamples;
    return compareWithReference(renderer, scene, options);
}

// The scene files in scenes/, sorted.
inline std::vector<std::filesystem::path> bundledScenes() {
    std::vector<std::filesystem::path> out;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes"))
        if (entry.path().extension() == ".json") out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

inline double awayFromEdges(const LightComparison& l) { return l.falseLitAwayFromEdges + l.falseShadowAwayFromEdges; }

} // namespace shadowlab::test
