// The registry: adding a technique adds one line to builtIn() below.
#include "techniques/Registry.h"

#include "gl/ShaderSource.h"
#include "techniques/Disc.h"
#include "techniques/map/Map.h"
#include "techniques/None.h"
#include "techniques/Planar.h"
#include "techniques/Volume.h"

#include <shadowlab/Error.h>
#include <shadowlab/Techniques.h>

#include <deque>
#include <mutex>

namespace shadowlab {

namespace {

std::vector<TechniqueEntry> builtIn() {
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
    std::vector<TechniqueEntry> entries = builtIn();
};

Registry& registry() {
    static Registry r;
    return r;
}

bool isIdentifier(std::string_view name) {
    if (name.empty()) return false;
    for (char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
    return true;
}

} // namespace

const std::vector<TechniqueEntry>& techniqueEntries() { return registry().entries; }

const TechniqueEntry* findTechniqueEntry(std::string_view name) {
    for (const TechniqueEntry& e : registry().entries)
        if (e.name == name) return &e;
    return nullptr;
}

void registerTechnique(TechniqueEntry entry) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (!isIdentifier(entry.name)) throw Error("registerTechnique: '" + entry.name + "' is not a name of letters, digits, '-' and '_'");
    if (entry.name == "technique") throw Error("registerTechnique: 'technique' is the key that selects one");
    for (const TechniqueEntry& e : r.entries)
        if (e.name == entry.name) throw Error("registerTechnique: '" + entry.name + "' is already registered");
    if (!entry.options || entry.options->block != entry.name)
        throw Error("registerTechnique: '" + entry.name + "' needs an options table whose block is its name");
    if (!entry.create || entry.shaderFile.empty()) throw Error("registerTechnique: '" + entry.name + "' needs a factory and a shader file");
    if (!gl::shaderFile(entry.shaderFile))
        throw Error("registerTechnique: '" + entry.name + "': no shader file '" + entry.shaderFile + "' (embed it or gl::addShaderFile)");
    r.entries.push_back(std::move(entry));
}

std::vector<TechniqueInfo> techniques() {
    std::vector<TechniqueInfo> out;
    for (const TechniqueEntry& e : techniqueEntries()) out.push_back({e.name, e.summary, e.options});
    return out;
}

const TechniqueInfo* findTechnique(std::string_view name) {
    // Infos are kept for the program's lifetime so that pointers stay valid.
    static std::mutex mutex;
    static std::deque<TechniqueInfo> infos;
    const TechniqueEntry* e = findTechniqueEntry(name);
    if (!e) return nullptr;
    std::lock_guard lock(mutex);
    for (const TechniqueInfo& i : infos)
        if (i.name == e->name) return &i;
    infos.push_back({e->name, e->summary, e->options});
    return &infos.back();
}

std::string techniquesMarkdown() {
    std::string out = "| `technique` | what |\n|---|---|\n";
    for (const TechniqueEntry& e : techniqueEntries()) out += "| `" + e.name + "` | " + e.summary + " |\n";
    for (const TechniqueEntry& e : techniqueEntries()) {
        out += "\n#### `lights[i].shadow." + e.name + "`\n\n";
        out += e.options->fields.empty() ? std::string("No options.\n") : e.options->markdown();
    }
    return out;
}

std::string unsupportedReason(std::string_view technique, const Light& light) {
    const TechniqueEntry* e = findTechniqueEntry(technique);
    if (!e) return "unknown technique '" + std::string(technique) + "'";
    return e->unsupported ? e->unsupported(light) : std::string();
}

ShadowBaseline shadowBaseline(const Light& light) {
    const TechniqueEntry* e = findTechniqueEntry(light.shadow.technique);
    return e && e->baseline ? e->baseline(light) : ShadowBaseline{light.shadow, false};
}

} // namespace shadowlab
