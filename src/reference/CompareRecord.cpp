// A light's comparison as the JSON record that compare's metrics.json and
// bench's results.json write and the Python module returns (Compare.h:
// lightMetricsJson), and metrics.json around them (comparisonMetricsJson):
// one place for the fields' names.
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

std::string comparisonMetricsJson(const Scene& scene, const std::string& sceneFile, const CompareOptions& options, const Comparison& c,
                                  bool fileNames) {
    nlohmann::json lights = nlohmann::json::array();
    for (std::size_t i = 0; i < c.lights.size() && i < scene.lights.size(); ++i) {
        nlohmann::json record = nlohmann::json::parse(lightMetricsJson(scene.lights[i], c.lights[i]));
        if (fileNames) {
            const std::string n = std::to_string(i);
            record["errorImage"] = "error-" + n + ".png";
            record["visibilityImage"] = "visibility-" + n + ".png";
            record["techniqueVisibilityImage"] = "technique-visibility-" + n + ".png";
            record["reachImage"] = "reach-" + n + ".png";
        }
        lights.push_back(std::move(record));
    }
    nlohmann::json metrics{{"scene", scene.name},
                           {"sceneFile", sceneFile.empty() ? "<default>" : sceneFile},
                           {"width", options.width},
                           {"height", options.height},
                           {"softSamples", options.softSamples},
                           {"time", options.timeSeconds},
                           {"referenceMs", c.referenceMs},
                           {"lights", lights}};
    if (fileNames) {
        metrics["techniqueImage"] = "technique.png";
        metrics["referenceImage"] = "reference.png";
    }
    return metrics.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

} // namespace shadowlab
