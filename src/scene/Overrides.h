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

/// The overrides as applyOverrides returns them, without a document to
/// apply them to: each `key=value`'s flag and canonical path (entries with
/// no valid key are left out: parsing the scene refuses them).
/// `labels`, when given, names each override in messages instead of
/// "--set KEY=VALUE" (a bench --vary value, a viewer script's line).
std::vector<Override> describeOverrides(const std::vector<std::string>& overrides, const std::vector<std::string>& labels = {});

/// Whether two paths are one, or one holds the other (lights[0].shadow
/// holds lights[0].shadow.technique), compared as canonical paths.
bool pathsOverlap(const std::string& a, const std::string& b);
/// Whether two paths are one (lights[00].size is lights[0].size).
bool pathsEqual(const std::string& a, const std::string& b);
/// Whether path `outer` is `inner` or holds it (lights[0].shadow holds
/// lights[00].shadow.technique), compared as canonical paths.
bool pathHolds(const std::string& outer, const std::string& inner);

/// The override a value at `path` came from: the last one that set it, a
/// part of it, or a block around it (setting camera.fovY.x turned fovY into
/// an object); nullptr when none did.
const Override* overrideAt(const std::vector<Override>& applied, const std::string& path);

} // namespace shadowlab::overrides
