#pragma once
// The accuracy numbers of compareWithReference as JSON: one record per light,
// the same in `bench`'s results.json and `compare`'s metrics.json.
#include <shadowlab/Compare.h>
#include <shadowlab/Scene.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace shadowlab::tool {

/// One light's record: name, type, technique, soft, receiverPixels,
/// referenceShadowedPixels, edgePixels, falseShadow, falseLit,
/// falseShadowAwayFromEdges, falseLitAwayFromEdges, meanAbsError, rmse
/// (shares in [0, 1], as in LightComparison), then `images` (key -> path
/// relative to the JSON file, e.g. "errorImage").
nlohmann::json lightRecord(const Light& light, const LightComparison& comparison,
                           const std::map<std::string, std::string>& images);

/// Writes `value` (indented) to `path` through `path`.partial and a rename, so
/// a reader never sees half a file. Throws Error naming the path on failure.
void writeJsonAtomically(const std::filesystem::path& path, const nlohmann::json& value);

} // namespace shadowlab::tool
