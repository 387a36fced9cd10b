#pragma once
// The technique registry: the GL half of each technique (its light-pass
// GLSL files and the factory of the Technique that draws), one
// TechniqueEntry per technique, in Registry.cpp. What the scene loader
// needs (names, options tables) is the catalog, techniques/Catalog.h.
#include "techniques/Catalog.h"
#include "techniques/Technique.h"

#include <string_view>
#include <vector>

namespace shadowlab {

/// The entry named `name`, or nullptr. Pointers stay valid for the program's life.
const TechniqueEntry* findTechniqueEntry(std::string_view name);
/// Adds a technique at run time (tests register test-only techniques): its
/// catalog row, and its GL half under the same name: the light-pass GLSL
/// file and the factory. Throws shadowlab::Error when the name is taken or
/// not an identifier, or there is no factory or no such shader file.
void registerTechnique(TechniqueKind kind, std::string shaderFile, std::function<std::unique_ptr<Technique>()> create);

} // namespace shadowlab
