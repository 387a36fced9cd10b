// A light's comparison as the JSON record that compare's metrics.json and
// bench's results.json write and the Python module returns (Compare.h:
// lightMetricsJson): one place for the fields' names.
#include <shadowlab/Compare.h>

#include <nlohmann/json.hpp>

namespace shadowlab {

std::string lightMetricsJson(const Light& light, const LightComparison& c) {
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
    return record.dump();
}

} // namespace shadowlab
