// bench: the runs its arguments expand into (BenchParts.h): --vary
// parsed, every combination of the varied values, and every scene with each
// combination, parsed once.
#include "BenchParts.h"

#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <map>

namespace shadowlab::bench {

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

namespace {

// A --vary value as the JSON it stands for (a bare word is a string, as --set takes it).
nlohmann::json asJson(const std::string& value) {
    nlohmann::json j = nlohmann::json::parse(value, nullptr, false);
    return j.is_discarded() ? nlohmann::json(value) : j;
}

} // namespace

std::vector<BenchRun> loadRuns(const BenchOptions& args, nlohmann::json* skipped) {
    std::vector<Variation> variations;
    for (std::size_t i = 0; i < args.vary.size(); ++i) {
        variations.push_back(parseVariation(args.vary[i]));
        // Two --vary of one key (or of a key and what holds it) would make
        // every combination run at the last one's value.
        for (std::size_t j = 0; j < i; ++j)
            if (overridePathsOverlap(variations[j].key, variations[i].key))
                throw Error("--vary " + args.vary[i] + ": " + variations[i].key + " is already varied by --vary " + args.vary[j] +
                            (overridePathsEqual(variations[j].key, variations[i].key) ? " (give all its values in one --vary)" : " (one holds the other)"));
        // More values than runs allowed: refused before anything else is
        // done with them (20,000 values were compared pair by pair first,
        // a minute and more).
        if (variations[i].values.size() > kMaxBenchRuns)
            throw Error("--vary " + variations[i].key + "=...: " + std::to_string(variations[i].values.size()) + " values make more than " +
                        std::to_string(kMaxBenchRuns) + " runs (the limit); vary fewer settings at a time");
        // A value twice (as JSON: 1 and 1.0 are one value) would run the same
        // combination twice under two labels. Each value parsed once, looked
        // up by its JSON (numbers by their double's digits: 1 and 1.0 are one).
        std::map<std::string, std::size_t> seen;
        for (std::size_t a = 0; a < variations[i].values.size(); ++a) {
            const nlohmann::json j = asJson(variations[i].values[a]);
            std::string key = j.dump();
            if (j.is_number()) {
                char digits[40];
                std::snprintf(digits, sizeof digits, "%.17g", j.get<double>());
                key = digits;
            }
            const auto [at, fresh] = seen.emplace(key, a);
            if (!fresh) {
                const std::string& before = variations[i].values[at->second];
                throw Error("--vary " + args.vary[i] + ": the value " + variations[i].values[a] +
                            (variations[i].values[a] == before ? "" : " (" + before + ")") + " is given twice");
            }
        }
        // A --set of the same key would be replaced by every run's value without a word.
        for (const std::string& set : args.overrides)
            if (overridePathsOverlap(set.substr(0, set.find('=')), variations[i].key))
                throw Error("--vary " + args.vary[i] + ": " + variations[i].key + " is also set by --set " + set +
                            " (a varied key takes its values from --vary alone)");
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
            if (file.empty() && args.gltfCamera >= 0)
                throw Error("--camera " + std::to_string(args.gltfCamera) + ": needs a glTF file (the default scene has one camera)");
            try {
                runs.push_back({file, combo, file.empty() ? defaultScene(overrides) : loadSceneFile(file, overrides, SceneFileOptions{args.gltfCamera})});
            } catch (const Error& e) {
                // A varied value is applied like --set; name the flag the user wrote,
                // and the scene and combination the check failed in.
                std::string message = e.what();
                for (const std::string& c : combo)
                    if (message.rfind("--set " + c + ":", 0) == 0) message = "--vary " + c + message.substr(6 + c.size());
                if (args.skipUnsupported && skipped && dynamic_cast<const UnsupportedError*>(&e)) {
                    skipped->push_back({{"sceneFile", file}, {"vary", combo}, {"reason", message}});
                    continue;
                }
                std::string where = file.empty() ? std::string("the default scene") : file;
                for (const std::string& c : combo) where += ", --vary " + c;
                if (dynamic_cast<const UnsupportedError*>(&e) && !combo.empty()) where += "; --skip-unsupported leaves such runs out";
                throw Error(message + " (bench: " + where + ")");
            }
        }
    return runs;
}

} // namespace shadowlab::bench
