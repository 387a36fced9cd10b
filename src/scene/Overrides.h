#pragma once
// `--set` overrides: JSON paths like `lights[0].intensity` applied to a
// parsed scene document before it is read (see docs/scene-format.md).
// Private to the scene loader.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shadowlab::overrides {

/// "null", "a boolean", "a string", "an array", "an object" or "a number", for messages.
const char* typeName(const nlohmann::json& j);

struct Override {
    std::string flag;  ///< "--set a.b=1", for messages
    std::string path;  ///< canonical JSON path
};

/// Applies `key=value` overrides to the document; returns them for error
/// attribution. Throws shadowlab::Error naming the flag.
std::vector<Override> applyOverrides(nlohmann::json& doc, const std::vector<std::string>& overrides);

} // namespace shadowlab::overrides
