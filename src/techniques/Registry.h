#pragma once
// The technique registry: one TechniqueEntry per technique, in Registry.cpp.
#include "techniques/Technique.h"

#include <string_view>
#include <vector>

namespace shadowlab {

/// Every registered technique, in registry order ("none" first).
const std::vector<TechniqueEntry>& techniqueEntries();
/// The entry named `name`, or nullptr.
const TechniqueEntry* findTechniqueEntry(std::string_view name);
/// Adds a technique at run time (tests register test-only techniques).
/// Throws shadowlab::Error when the name is taken or not an identifier.
void registerTechnique(TechniqueEntry entry);

} // namespace shadowlab
