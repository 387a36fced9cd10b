#include "Metrics.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <fstream>
#include <system_error>

namespace shadowlab::tool {

nlohmann::json lightRecord(const Light& light, const LightComparison& c,
                           const std::map<std::string, std::string>& images) {
    nlohmann::json record = nlohmann::json::parse(lightMetricsJson(light, c));  // the library's fields, in one place
    for (const auto& [key, path] : images) record[key] = path;
    return record;
}

void writeJsonAtomically(const std::filesystem::path& path, const nlohmann::json& value) {
    writeFileAtomically(path, value.dump(2) + "\n");
}

} // namespace shadowlab::tool
