// shadowlab bench: the runs its arguments expand into (BenchParts.h): --vary
// parsed, every combination of the varied values, and every scene with each
// combination, parsed once.
#include "BenchParts.h"

#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

namespace shadowlab::tool {

Variation parseVariation(const std::string& text) {
    const std::string flag = "--vary " + text;
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) throw Error(flag + ": expected key=value1,value2,...");
    Variation v{text.substr(0, eq), {}};
    std::string current;
    int depth = 0;
    bool quoted = false;
    for (char c : text.substr(eq + 1)) {
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ']' || c == '}')) --depth;
        if (c == ',' && depth == 0 && !quoted) {
            v.values.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    v.values.push_back(current);
    for (const std::string& value : v.values)
        if (value.empty()) throw Error(flag + ": empty value in the list");
    return v;
}

std::vector<std::vector<std::string>> combinations(const std::vector<Variation>& variations) {
    std::vector<std::vector<std::string>> out{{}};
    for (const Variation& v : variations) {
        std::vector<std::vector<std::string>> next;
        for (const auto& partial : out)
            for (const std::string& value : v.values) {
                auto c = partial;
                c.push_back(v.key + "=" + value);
                next.push_back(std::move(c));
            }
        out = std::move(next);
    }
    return out;
}

std::size_t countRuns(std::size_t sceneCount, const std::vector<Variation>& variations) {
    std::size_t runs = sceneCount;
    std::string product = std::to_string(sceneCount) + " scene" + (sceneCount == 1 ? "" : "s");
    for (const Variation& v : variations) product += " x " + std::to_string(v.values.size());
    for (const Variation& v : variations) {
        // runs * size > limit, tested by division so that it cannot overflow.
        if (!v.values.empty() && runs > kMaxBenchRuns / v.values.size())
            throw Error("--vary: " + product + " values make more than " + std::to_string(kMaxBenchRuns) +
                        " runs (the limit); vary fewer settings at a time");
        runs *= v.values.size();
    }
    return runs;
}

std::vector<BenchRun> loadRuns(const BenchArgs& args) {
    std::vector<Variation> variations;
    for (std::size_t i = 0; i < args.vary.size(); ++i) {
        variations.push_back(parseVariation(args.vary[i]));
        // Two --vary of one key would make every combination run at the last one's value.
        for (std::size_t j = 0; j < i; ++j)
            if (variations[j].key == variations[i].key)
                throw Error("--vary " + args.vary[i] + ": " + variations[i].key + " is already varied by --vary " + args.vary[j] +
                            " (give all its values in one --vary)");
    }
    std::vector<std::string> scenes = args.scenes;
    if (scenes.empty()) scenes.push_back("");
    const std::size_t count = countRuns(scenes.size(), variations); // before building them: 10^7 would fill memory
    const auto combos = combinations(variations);
    std::vector<BenchRun> runs;
    runs.reserve(count);
    for (const std::string& file : scenes)
        for (const auto& combo : combos) {
            std::vector<std::string> overrides = args.overrides;
            overrides.insert(overrides.end(), combo.begin(), combo.end());
            try {
                runs.push_back({file, combo, file.empty() ? defaultScene(overrides) : loadSceneFile(file, overrides)});
            } catch (const Error& e) {
                // A varied value is applied like --set; name the flag the user wrote.
                const std::string message = e.what();
                for (const std::string& c : combo)
                    if (message.rfind("--set " + c + ":", 0) == 0) throw Error("--vary " + c + message.substr(6 + c.size()));
                throw;
            }
        }
    return runs;
}

} // namespace shadowlab::tool
