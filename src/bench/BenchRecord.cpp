// bench: the record a run leaves in results.json (BenchParts.h), its
// medians and ratios, and the names its technique, reference and error
// images get from BenchHooks::images.
#include "BenchParts.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <algorithm>
#include <cctype>
#include <optional>

namespace shadowlab::bench {

using nlohmann::json;

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

namespace {

json stats(std::vector<double> values) {
    if (values.empty()) return json{{"median", 0.0}, {"min", 0.0}, {"max", 0.0}};
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return json{{"median", median(values)}, {"min", *lo}, {"max", *hi}};
}

// A file-name part from a label, at most kMaxSlug characters: a 300-character
// scene name must not make a name past the file system's 255-byte limit.
std::string slug(const std::string& label) {
    constexpr std::size_t kMaxSlug = 80;
    std::string out;
    for (char c : label.substr(0, kMaxSlug)) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
    return out;
}

// Light l's shadow pass in `record`: the pass beside its floor (a bare
// depth-only draw of the same casters into a target of the same size),
// which it contains as a nested scope, its triangles, and every other
// number the technique reported for its shadow pass (a cube's triangles per
// face) and for its light pass (a stencil technique's CPU silhouettes), by
// name, medians.
void addPassNumbers(json& record, const TimedFrames& timed, std::size_t l) {
    const auto& passTimes = timed.passTimes;
    const auto& counters = timed.counters;
    const std::string pass = "shadow[" + std::to_string(l) + "]";
    auto medianOf = [&](const std::string& name) { return passTimes.count(name) ? median(passTimes.at(name)) : 0.0; };
    if (passTimes.count(pass)) {
        // The floors are drawn inside the pass's scope: the pass is the rest.
        const double whole = median(passTimes.at(pass));
        const double floor = medianOf(pass + ".floor");
        const double lookupFloors = medianOf(pass + ".lookupFloor");
        record["shadowPassMs"] = whole - floor - lookupFloors;
        if (floor > 0.0) {
            record["shadowFloorMs"] = floor;
            record["shadowPassOverFloor"] = (whole - floor - lookupFloors) / floor;
        }
        // The lookups' floor (2D maps and cubes): one nearest fetch a pixel, less the same draw without it.
        if (passTimes.count(pass + ".lookupFloor.fetch") && passTimes.count(pass + ".lookupFloor.bare"))
            record["lookupFloorMs"] = medianOf(pass + ".lookupFloor.fetch") - medianOf(pass + ".lookupFloor.bare");
    }
    if (counters.count(pass + ".triangles")) record["shadowTriangles"] = median(counters.at(pass + ".triangles"));
    // The lookup cost: the pass that lights with this light (the base pass
    // or its own) less the same pass of the unshadowed frame, where the
    // light is in the same pass there.
    const std::string lit = static_cast<int>(l) == timed.baseLight ? std::string("base") : "light[" + std::to_string(l) + "]";
    const bool samePass = (lit == "base") == (static_cast<int>(l) == timed.unshadowedBaseLight);
    // A base pass that kept a depth pre-pass (fit "sdsm") shades each pixel
    // once; the unshadowed one does not: the lookups are its time without it.
    const bool prepassed = lit == "base" && !timed.unprepassedBaseTimes.empty();
    if (samePass && passTimes.count(lit) && timed.unshadowedPassTimes.count(lit))
        record["lookupMs"] = (prepassed ? median(timed.unprepassedBaseTimes) : median(passTimes.at(lit))) -
                             median(timed.unshadowedPassTimes.at(lit));
    auto reportedUnder = [&](const std::string& prefix, const std::string& skip) {
        json out = json::object();
        for (const auto& [name, values] : counters)
            if (name.rfind(prefix, 0) == 0 && name != skip) out[name.substr(prefix.size())] = median(values);
        return out;
    };
    // The share of the frame the base pass ran this light's test in (RenderOptions::shadowRegions).
    if (lit == "base" && counters.count("base.shadowedShare")) record["shadowedShare"] = median(counters.at("base.shadowedShare"));
    if (json r = reportedUnder(pass + ".", pass + ".triangles"); !r.empty()) record["shadowCounters"] = std::move(r);
    if (json r = reportedUnder("light[" + std::to_string(l) + "].", ""); !r.empty()) record["lightCounters"] = std::move(r);
}

// The frame's floor (docs/metrics.md): the unshadowed frame plus each
// light's pass floor and lookup floor, what the frame would cost were every
// pass a bare depth draw and every lookup one nearest fetch a pixel; none
// where a light with a shadow pass has no floors (the atlas, volumes).
std::optional<double> floorFrame(const json& lights, double unshadowed) {
    double sum = unshadowed;
    bool any = false;
    for (const json& l : lights) {
        if (!l.contains("shadowPassMs")) continue;
        if (!l.contains("shadowFloorMs") || !l.contains("lookupFloorMs")) return std::nullopt;
        sum += l["shadowFloorMs"].get<double>() + std::max(l["lookupFloorMs"].get<double>(), 0.0);
        any = true;
    }
    return any ? std::optional<double>(sum) : std::nullopt;
}

// Fit "sdsm"'s cost in the frame (docs/metrics.md): its depth pre-pass and
// reductions, and what the base pass saves by keeping the pre-pass's depth
// (the same frame's base pass drawn without it, TimedFrames::
// unprepassedBaseTimes); none where no frame drew a pre-pass.
std::optional<json> sdsmCost(const Scene& scene, const TimedFrames& timed, double frame) {
    if (timed.unprepassedBaseTimes.empty() || !timed.passTimes.count("base")) return std::nullopt;
    auto summed = [&](const std::string& part) {
        double sum = 0.0;
        for (std::size_t l = 0; l < scene.lights.size(); ++l)
            if (const auto t = timed.passTimes.find("shadow[" + std::to_string(l) + "].sdsm." + part); t != timed.passTimes.end())
                sum += median(t->second);
        return sum;
    };
    const double prepass = summed("prepass"), reduce = summed("reduce");
    const double base = median(timed.passTimes.at("base")), without = median(timed.unprepassedBaseTimes);
    const double net = prepass + reduce - (without - base);
    return json{{"prepassMs", prepass},
                {"reduceMs", reduce},
                {"overFrame", (prepass + reduce) / std::max(frame, 1e-9)},
                {"baseMs", base},
                {"baseWithoutPrepassMs", without},
                {"baseSavedMs", without - base},
                {"netMs", net},
                {"netOverFrame", net / std::max(frame, 1e-9)}};
}

// Every light's record, with its error image's name where `names` gives one.
json lightRecords(const Scene& scene, const TimedFrames& timed, const Accuracy& accuracy, const BenchImageNames& names,
                  const BenchOptions& args) {
    json lights = json::array();
    for (std::size_t l = 0; l < accuracy.comparison.lights.size(); ++l) {
        json record = json::parse(lightMetricsJson(scene.lights[l], accuracy.comparison.lights[l]));  // compare's fields, in one place
        if (l < names.errors.size() && !names.errors[l].empty()) record["errorImage"] = names.errors[l];
        addPassNumbers(record, timed, l);
        if (args.flips) accuracy.flips.addTo(record, l);
        lights.push_back(std::move(record));
    }
    return lights;
}

} // namespace

json runRecord(const BenchRun& run, const Scene& scene, const TimedFrames& timed, const Accuracy& accuracy, std::size_t index,
               const std::string& label, const BenchOptions& args, const BenchHooks& hooks) {
    const BenchImageNames names = hooks.images ? hooks.images(index, std::to_string(index) + "-" + slug(label), accuracy.comparison) : BenchImageNames{};
    json lights = lightRecords(scene, timed, accuracy, names, args);
    json passes = json::object();
    for (const auto& [name, times] : timed.passTimes) passes[name] = stats(times);
    json settings = json::object();
    for (const std::string& c : run.combo) {
        const auto eq = c.find('=');
        settings[c.substr(0, eq)] = c.substr(eq + 1);
    }
    std::size_t triangles = 0;
    for (const DrawItem& item : scene.drawItems()) triangles += scene.meshes[static_cast<std::size_t>(item.mesh)].triangleCount();
    const double frame = median(timed.frameTimes);
    json extra = json::object();
    // The clustered light list's pass ("lights"), where the frame has one.
    if (timed.counters.count("lights.listed")) {
        json list = json::object();
        for (const char* name : {"listed", "tileEntries", "culled"}) list[name] = median(timed.counters.at(std::string("lights.") + name));
        extra["lightList"] = list;
    }
    if (timed.timedPerLight) {
        // The clustered light list's gain: the unshadowed frame against the same with a pass per light.
        extra["unshadowedPerLightFrameMs"] = stats(timed.unshadowedPerLightTimes);
        extra["unshadowedOverPerLight"] = median(timed.unshadowedTimes) / std::max(median(timed.unshadowedPerLightTimes), 1e-9);
    }
    // frameOverHardMap: over the technique's baseline (for a map, the hard map).
    json record = {{"scene", scene.name},
            {"sceneFile", run.file.empty() ? "<default>" : run.file},
            {"settings", settings},
            {"triangles", triangles},
            {"frames", args.frames},
            {"clock", timed.clock},
            {"baseLight", timed.baseLight},
            {"passMs", passes},
            {"passTotalMs", stats(timed.passTotal)},
            {"frameMs", stats(timed.frameTimes)},
            {"unshadowedFrameMs", stats(timed.unshadowedTimes)},
            {"cachedFrameMs", stats(timed.cachedTimes)},
            {"frameOverUnshadowed", frame / std::max(median(timed.unshadowedTimes), 1e-9)},
            {"frameOverHardMap", timed.timedBaseline ? frame / std::max(median(timed.baselineTimes), 1e-9) : 1.0},
            {"referenceMs", accuracy.comparison.referenceMs},
            {"lights", lights},
            {"notes", accuracy.comparison.techniqueFrame.notes}};
    if (!names.technique.empty()) record["techniqueImage"] = names.technique;
    if (!names.reference.empty()) record["referenceImage"] = names.reference;
    if (!timed.budgetedTimes.empty()) record["budgetedFrameMs"] = stats(timed.budgetedTimes);
    if (const auto floor = floorFrame(record["lights"], median(timed.unshadowedTimes))) {
        record["floorFrameMs"] = *floor;
        record["floorFrameOverUnshadowed"] = *floor / std::max(median(timed.unshadowedTimes), 1e-9);
    }
    if (auto sdsm = sdsmCost(scene, timed, frame)) record["sdsmCost"] = std::move(*sdsm);
    record.update(extra);
    return record;
}

} // namespace shadowlab::bench

namespace shadowlab {

BenchImageNames writeBenchImages(const std::filesystem::path& directory, const std::string& stem, const Comparison& c) {
    std::error_code ec;
    if (!std::filesystem::create_directories(directory / "images", ec) && ec)
        throw Error((directory / "images").string() + ": cannot create directory (" + ec.message() + ")");
    BenchImageNames names{"images/" + stem + "-technique.png", "images/" + stem + "-reference.png", {}};
    writePng(directory / names.technique, c.technique);
    writePng(directory / names.reference, c.reference);
    for (std::size_t l = 0; l < c.lights.size(); ++l) {
        names.errors.push_back("images/" + stem + "-error-" + std::to_string(l) + ".png");
        writePng(directory / names.errors.back(), c.lights[l].errorImage);
    }
    return names;
}

} // namespace shadowlab
