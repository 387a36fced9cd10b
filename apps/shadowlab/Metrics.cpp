#include "Metrics.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <fstream>
#include <system_error>

namespace shadowlab::tool {

nlohmann::json lightRecord(const Light& light, const LightComparison& c,
                           const std::map<std::string, std::string>& images) {
    nlohmann::json record{{"name", c.name},
                          {"type", toString(light.type)},
                          {"technique", light.shadow.technique},
                          {"soft", c.soft},
                          {"receiverPixels", c.receiverPixels},
                          {"referenceShadowedPixels", c.referenceShadowedPixels},
                          {"edgePixels", c.edgePixels},
                          {"falseShadow", c.falseShadow},
                          {"falseLit", c.falseLit},
                          {"falseShadowAwayFromEdges", c.falseShadowAwayFromEdges},
                          {"falseLitAwayFromEdges", c.falseLitAwayFromEdges},
                          {"meanAbsError", c.meanAbsError},
                          {"rmse", c.rmse},
                          {"umbraPixels", c.umbraPixels},
                          {"leakedInUmbra", c.leakedInUmbra},
                          {"referencePenumbraPixels", c.referencePenumbraPixels},
                          {"techniquePenumbraPixels", c.techniquePenumbraPixels},
                          {"penumbraRatio", c.penumbraRatio()},
                          {"coloured", c.coloured},
                          {"rmseRgb", {c.rmseRgb[0], c.rmseRgb[1], c.rmseRgb[2]}}};
    if (c.texelFootprintP50 >= 0.0) {
        record["texelFootprintP50"] = c.texelFootprintP50;
        record["texelFootprintP95"] = c.texelFootprintP95;
        record["texelFootprintMax"] = c.texelFootprintMax;
    }
    for (const auto& [key, path] : images) record[key] = path;
    return record;
}

void writeJsonAtomically(const std::filesystem::path& path, const nlohmann::json& value) {
    writeFileAtomically(path, value.dump(2) + "\n");
}

} // namespace shadowlab::tool
