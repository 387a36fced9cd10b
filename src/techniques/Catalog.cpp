// The catalog: adding a technique adds one line to builtIn() below (and
// one to the registry's, techniques/Registry.cpp, for its GL half).
#include "techniques/Catalog.h"

#include "techniques/Kinds.h"

#include <shadowlab/Error.h>

#include <deque>
#include <mutex>

namespace shadowlab {

namespace {

std::deque<TechniqueKind> builtIn() {
    return {
        noneKind(),
        mapKind(),
        planarKind(),
        volumeKind(),
        discKind(),
    };
}

// A deque: kinds added at run time leave the others where they are.
struct Catalog {
    std::mutex mutex;
    std::deque<TechniqueKind> kinds = builtIn();
};

Catalog& catalog() {
    static Catalog c;
    return c;
}

bool isIdentifier(std::string_view name) {
    if (name.empty()) return false;
    for (char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return false;
    return true;
}

} // namespace

const TechniqueKind* findTechniqueKind(std::string_view name) {
    Catalog& c = catalog();
    std::lock_guard lock(c.mutex);
    for (const TechniqueKind& k : c.kinds)
        if (k.name == name) return &k;
    return nullptr;
}

std::vector<const TechniqueKind*> techniqueKinds() {
    Catalog& c = catalog();
    std::lock_guard lock(c.mutex);
    std::vector<const TechniqueKind*> out;
    for (const TechniqueKind& k : c.kinds) out.push_back(&k);
    return out;
}

void addTechniqueKind(TechniqueKind kind) {
    Catalog& c = catalog();
    std::lock_guard lock(c.mutex);
    if (!isIdentifier(kind.name)) throw Error("registerTechnique: '" + kind.name + "' is not a name of letters, digits, '-' and '_'");
    if (kind.name == "technique") throw Error("registerTechnique: 'technique' is the key that selects one");
    for (const TechniqueKind& k : c.kinds)
        if (k.name == kind.name) throw Error("registerTechnique: '" + kind.name + "' is already registered");
    if (!kind.options || kind.options->block != kind.name)
        throw Error("registerTechnique: '" + kind.name + "' needs an options table whose block is its name");
    c.kinds.push_back(std::move(kind));
}

std::vector<TechniqueInfo> techniques() {
    std::vector<TechniqueInfo> out;
    for (const TechniqueKind* k : techniqueKinds()) out.push_back({k->name, k->summary, k->options});
    return out;
}

const TechniqueInfo* findTechnique(std::string_view name) {
    // Infos are kept for the program's lifetime so that pointers stay valid.
    static std::mutex mutex;
    static std::deque<TechniqueInfo> infos;
    const TechniqueKind* k = findTechniqueKind(name);
    if (!k) return nullptr;
    std::lock_guard lock(mutex);
    for (const TechniqueInfo& i : infos)
        if (i.name == k->name) return &i;
    infos.push_back({k->name, k->summary, k->options});
    return &infos.back();
}

std::string techniquesMarkdown() {
    const std::vector<const TechniqueKind*> kinds = techniqueKinds();
    std::string out = "| `technique` | what |\n|---|---|\n";
    for (const TechniqueKind* k : kinds) out += "| `" + k->name + "` | " + k->summary + " |\n";
    for (const TechniqueKind* k : kinds) {
        out += "\n#### `lights[i].shadow." + k->name + "`\n\n";
        out += k->options->fields.empty() ? std::string("No options.\n") : k->options->markdown();
    }
    return out;
}

std::string unsupportedReason(std::string_view technique, const Light& light) {
    const TechniqueKind* k = findTechniqueKind(technique);
    if (!k) return "unknown technique '" + std::string(technique) + "'";
    return k->unsupported ? k->unsupported(light) : std::string();
}

std::string optionUnused(const Light& light, std::string_view key) {
    const TechniqueKind* k = findTechniqueKind(light.shadow.technique);
    return k && k->unused ? k->unused(light, key) : std::string();
}

std::vector<std::string> presetKeys(const Light& light) {
    const TechniqueKind* k = findTechniqueKind(light.shadow.technique);
    return k && k->presetKeys ? k->presetKeys(light) : std::vector<std::string>();
}

ShadowBaseline shadowBaseline(const Light& light) {
    const TechniqueKind* k = findTechniqueKind(light.shadow.technique);
    return k && k->baseline ? k->baseline(light) : ShadowBaseline{light.shadow, false};
}

} // namespace shadowlab
