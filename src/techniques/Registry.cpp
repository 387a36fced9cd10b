// The registry: adding a technique adds one line to builtIn() below (and
// one to the catalog's, techniques/Catalog.cpp, for its options).
#include "techniques/Registry.h"

#include "gl/ShaderSource.h"
#include "techniques/Disc.h"
#include "techniques/None.h"
#include "techniques/Planar.h"
#include "techniques/Volume.h"
#include "techniques/map/Map.h"

#include <shadowlab/Error.h>

#include <deque>
#include <mutex>

namespace shadowlab {

namespace {

std::deque<TechniqueEntry> builtIn() {
    return {
        noneTechnique(),
        mapTechnique(),
        planarTechnique(),
        volumeTechnique(),
        discTechnique(),
    };
}

struct Registry {
    std::mutex mutex;
    std::deque<TechniqueEntry> entries = builtIn();
};

Registry& registry() {
    static Registry r;
    return r;
}

} // namespace

const TechniqueEntry* findTechniqueEntry(std::string_view name) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    for (const TechniqueEntry& e : r.entries)
        if (e.name == name) return &e;
    return nullptr;
}

void registerTechnique(TechniqueKind kind, std::string shaderFile, std::function<std::unique_ptr<Technique>()> create) {
    TechniqueEntry entry{kind.name, std::move(shaderFile), std::move(create)};
    if (!entry.create || entry.shaderFile.empty()) throw Error("registerTechnique: '" + entry.name + "' needs a factory and a shader file");
    if (!gl::shaderFile(entry.shaderFile))
        throw Error("registerTechnique: '" + entry.name + "': no shader file '" + entry.shaderFile + "' (embed it or gl::addShaderFile)");
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    addTechniqueKind(std::move(kind));  // checks the name
    r.entries.push_back(std::move(entry));
}

} // namespace shadowlab
