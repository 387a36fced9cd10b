#include "Bench.h"
#include "Metrics.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include "core/Text.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <unistd.h>

namespace shadowlab::tool {

namespace fs = std::filesystem;
using nlohmann::json;

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

StagingDirectory::StagingDirectory(fs::path target) : target_(std::move(target)) {
    staging_ = target_;
    staging_ += ".partial-" + std::to_string(getpid());
    std::error_code ec;
    fs::remove_all(staging_, ec);
    fs::create_directories(staging_, ec);
    if (ec) throw Error(staging_.string() + ": cannot create directory (" + ec.message() + ")");
}

StagingDirectory::~StagingDirectory() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

void StagingDirectory::commit() {
    std::error_code ec;
    if (!fs::exists(target_)) {
        fs::rename(staging_, target_, ec);
        if (ec) throw Error(target_.string() + ": cannot move the results into place (" + ec.message() + ")");
    } else {
        for (const fs::directory_entry& entry : fs::directory_iterator(staging_)) {
            const fs::path destination = target_ / entry.path().filename();
            fs::remove_all(destination, ec);
            fs::rename(entry.path(), destination, ec);
            if (ec) throw Error(destination.string() + ": cannot move into place (" + ec.message() + ")");
        }
        fs::remove_all(staging_, ec);
    }
    committed_ = true;
}

namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

json stats(std::vector<double> values) {
    if (values.empty()) return json{{"median", 0.0}, {"min", 0.0}, {"max", 0.0}};
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return json{{"median", median(values)}, {"min", *lo}, {"max", *hi}};
}

// One line per step when stderr is not a terminal, an updating bar when it is.
class Progress {
public:
    explicit Progress(std::size_t total) : total_(total), tty_(isatty(STDERR_FILENO)) {}
    void step(std::size_t done, const std::string& what) {
        const int width = 30;
        const int filled = static_cast<int>(width * done / std::max<std::size_t>(total_, 1));
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.resize(width, '.');
        std::fprintf(stderr, "%s[%s] %zu/%zu %s%s", tty_ ? "\r\033[K" : "", bar.c_str(), done, total_, text::escapeControl(what).c_str(),
                     tty_ ? "" : "\n");
        if (tty_ && done == total_) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    std::size_t total_;
    bool tty_;
};

// A file-name part from a label, at most kMaxSlug characters: a 300-character
// scene name must not make a name past the file system's 255-byte limit.
std::string slug(const std::string& label) {
    constexpr std::size_t kMaxSlug = 80;
    std::string out;
    for (char c : label.substr(0, kMaxSlug)) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' ? c : '_';
    return out;
}

// `scene`, a copy of `loaded` (its techniques may have been changed), with
// its lights and camera where their paths are at `seconds`; the meshes are
// not copied again.
void moveToTime(Scene& scene, const Scene& loaded, double seconds) {
    for (std::size_t l = 0; l < scene.lights.size(); ++l) scene.lights[l].position = lightAtTime(loaded.lights[l], seconds).position;
    scene.camera = cameraAtTime(loaded.camera, seconds);
}

// Temporal stability (--flips), per light over consecutive frames: the share
// of receiver pixels (receivers in both frames) whose technique class (lit:
// visibility >= the threshold) changes while the reference's class there does
// not, away from the edges: in both frames every receiver among the pixel's
// 8 neighbours has its technique class and its reference class. A shadow
// edge that slides by less than a pixel as the view moves is motion, not
// flicker; one that jumps by more (a texel grid sliding under the world)
// flips whole blocks of pixels. Where the truth changes (a light that moved,
// an edge that crossed the pixel) the change is right and is counted apart,
// as a reference change.
class FlipCounter {
public:
    explicit FlipCounter(float litThreshold) : threshold_(litThreshold) {}

    // One frame: its comparison and each light's technique visibility, read
    // back with the comparison's technique frame.
    void add(const Comparison& c, const std::vector<std::vector<float>>& techniqueVisibility) {
        const auto referenceThreshold = static_cast<double>(threshold_) * 65535.0;
        std::vector<Classes> frame(c.lights.size());
        for (std::size_t l = 0; l < c.lights.size(); ++l) {
            const LightComparison& light = c.lights[l];
            const std::size_t n = light.reach.pixels.size();
            Classes& k = frame[l];
            k.width = light.reach.width;
            k.receiver.resize(n);
            k.techniqueLit.resize(n);
            k.referenceLit.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                k.receiver[i] = light.reach.pixels[i] != 0;
                k.techniqueLit[i] = techniqueVisibility[l][i] >= threshold_;
                k.referenceLit[i] = light.referenceVisibility.pixels[i] >= referenceThreshold;
            }
        }
        if (!previous_.empty()) {
            flips_.resize(frame.size());
            referenceChanges_.resize(frame.size());
            for (std::size_t l = 0; l < frame.size(); ++l) {
                const Classes &a = previous_[l], &b = frame[l];
                std::size_t receivers = 0, flips = 0, changes = 0;
                for (std::size_t i = 0; i < b.receiver.size(); ++i) {
                    if (!a.receiver[i] || !b.receiver[i]) continue;
                    ++receivers;
                    const bool truthChanged = a.referenceLit[i] != b.referenceLit[i];
                    changes += truthChanged;
                    flips += !truthChanged && a.techniqueLit[i] != b.techniqueLit[i] && a.interior(i) && b.interior(i);
                }
                const double denominator = static_cast<double>(std::max<std::size_t>(receivers, 1));
                flips_[l].push_back(static_cast<double>(flips) / denominator);
                referenceChanges_[l].push_back(static_cast<double>(changes) / denominator);
            }
        }
        previous_ = std::move(frame);
    }

    // Light l's `flips` and `referenceChanges`: median, maximum and every
    // pair's share, in frame order.
    void addTo(json& record, std::size_t l) const {
        const auto summary = [](const std::vector<double>& shares) {
            return json{{"median", median(shares)}, {"max", shares.empty() ? 0.0 : *std::max_element(shares.begin(), shares.end())},
                        {"perPair", shares}};
        };
        record["flips"] = summary(l < flips_.size() ? flips_[l] : std::vector<double>{});
        record["referenceChanges"] = summary(l < referenceChanges_.size() ? referenceChanges_[l] : std::vector<double>{});
    }

private:
    struct Classes {
        int width = 0;
        std::vector<std::uint8_t> receiver, techniqueLit, referenceLit;
        // Whether every receiver among pixel i's 8 neighbours has its classes.
        bool interior(std::size_t i) const {
            const int x = static_cast<int>(i % static_cast<std::size_t>(width)), y = static_cast<int>(i / static_cast<std::size_t>(width));
            const int height = static_cast<int>(receiver.size() / static_cast<std::size_t>(width));
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    const std::size_t j = static_cast<std::size_t>(ny) * static_cast<std::size_t>(width) + static_cast<std::size_t>(nx);
                    if (receiver[j] && (techniqueLit[j] != techniqueLit[i] || referenceLit[j] != referenceLit[i])) return false;
                }
            return true;
        }
    };
    float threshold_;
    std::vector<Classes> previous_;  ///< per light, the last frame's
    std::vector<std::vector<double>> flips_, referenceChanges_;  ///< per light, per pair of frames
};

} // namespace

json runBench(Context& context, const BenchArgs& args) {
    if (args.frames < 1) throw Error("--frames " + std::to_string(args.frames) + ": expected at least 1");
    if (args.warmup < 0) throw Error("--warmup " + std::to_string(args.warmup) + ": expected 0 or more");
    if (!std::isfinite(args.timeSeconds)) throw Error("--time: expected a finite number of seconds");
    if (!std::isfinite(args.fps) || !(args.fps > 0.0)) throw Error("--fps: expected a finite number of frames per second > 0");
    if (!std::isfinite(args.timeSeconds + (args.frames - 1) / args.fps))
        throw Error("--time, --fps: the last timed frame's time is not a finite number of seconds");
    if (args.flips && args.frames < 2)
        throw Error("--flips: needs at least 2 timed frames to compare (got --frames " + std::to_string(args.frames) + ")");
    std::vector<Variation> variations;
    for (const std::string& v : args.vary) variations.push_back(parseVariation(v));
    std::vector<std::string> scenes = args.scenes;
    if (scenes.empty()) scenes.push_back("");
    const std::size_t runs = countRuns(scenes.size(), variations); // before building them: 10^7 would fill memory
    const auto combos = combinations(variations);

    // Validate every scene and combination before the long run starts.
    for (const std::string& file : scenes)
        for (const auto& combo : combos) {
            std::vector<std::string> overrides = args.overrides;
            overrides.insert(overrides.end(), combo.begin(), combo.end());
            try {
                (void)(file.empty() ? defaultScene(overrides) : loadSceneFile(file, overrides));
            } catch (const Error& e) {
                // A varied value is applied like --set; name the flag the user wrote.
                const std::string message = e.what();
                for (const std::string& c : combo)
                    if (message.rfind("--set " + c + ":", 0) == 0) throw Error("--vary " + c + message.substr(6 + c.size()));
                throw;
            }
        }

    std::fprintf(stderr, "bench: %zu run%s\n", runs, runs == 1 ? "" : "s");
    fs::create_directories(args.output / "images");
    const std::size_t total = scenes.size() * combos.size();
    Progress progress(total);
    json records = json::array();
    std::size_t done = 0;
    for (const std::string& file : scenes) {
        for (const auto& combo : combos) {
            std::vector<std::string> overrides = args.overrides;
            overrides.insert(overrides.end(), combo.begin(), combo.end());
            const Scene loaded = file.empty() ? defaultScene(overrides) : loadSceneFile(file, overrides);
            // The scene at --time: the warm-up frames and the comparison.
            Scene scene = sceneAtTime(loaded, args.timeSeconds);
            std::string label = scene.name;
            for (const std::string& c : combo) label += " " + c;
            progress.step(done, label);

            Renderer renderer(context);
            renderer.upload(scene);
            // Interleaved: a frame as users get it (no per-pass clock) for
            // the frame time, then a frame with the pass clock for where the
            // time goes. On a software rasteriser the pass clock finishes
            // every pass, which costs the overlap a plain frame has.
            RenderOptions plain;
            plain.width = args.width;
            plain.height = args.height;
            plain.timeSeconds = args.timeSeconds;
            RenderOptions clocked = plain;
            clocked.clock = args.clock;
            clocked.measureFloors = true;
            // The same scene unshadowed: every technique's ratio rests on it.
            Scene unshadowed = scene;
            for (Light& light : unshadowed.lights) light.shadow.technique = "none";
            // And with every light at its technique's baseline (a map at its
            // plainest: one 2D map of the same size, depth, the hardware filter,
            // the lecture's technique), for cascades, PCSS and moment maps'
            // ratio to it; timed only where some light differs from it.
            Scene baseline = scene;
            bool timeBaseline = false;
            for (Light& light : baseline.lights) {
                ShadowBaseline b = shadowBaseline(light);
                timeBaseline = timeBaseline || b.differs;
                light.shadow = std::move(b.shadow);
            }
            for (int i = 0; i < args.warmup; ++i) {
                renderer.render(scene, plain);
                renderer.render(unshadowed, plain);
                if (timeBaseline) renderer.render(baseline, plain);
            }
            std::map<std::string, std::vector<double>> passTimes, counters;
            std::vector<double> frameTimes, unshadowedTimes, baselineTimes, passTotal;
            std::string clockName = "off";
            int baseLight = -1;
            // Timed frame i shows the animation at --time + i / --fps: the
            // lights and the camera are moved (outside the timed render())
            // and the three frames of a step see them at the same place.
            for (int i = 0; i < args.frames; ++i) {
                const double t = args.timeSeconds + i / args.fps;
                moveToTime(scene, loaded, t);
                moveToTime(unshadowed, loaded, t);
                plain.timeSeconds = clocked.timeSeconds = t;
                frameTimes.push_back(renderer.render(scene, plain).cpuMs);
                unshadowedTimes.push_back(renderer.render(unshadowed, plain).cpuMs);
                if (timeBaseline) {
                    moveToTime(baseline, loaded, t);
                    baselineTimes.push_back(renderer.render(baseline, plain).cpuMs);
                }
                const FrameStats frame = renderer.render(scene, clocked);
                double sum = 0.0;
                for (const PassTiming& p : frame.passes) {
                    passTimes[p.name].push_back(p.ms);
                    if (p.name.find('.') == std::string::npos) sum += p.ms;  // nested scopes are inside their pass
                }
                for (const auto& [name, value] : frame.counters) counters[name].push_back(value);
                passTotal.push_back(sum);
                clockName = frame.clock;
                baseLight = frame.baseLight;
            }

            // The accuracy numbers at --time, as `compare --time` gives them;
            // with --flips, a comparison at every timed frame's time too
            // (the first of them is the one at --time).
            CompareOptions compareOptions;
            compareOptions.width = args.width;
            compareOptions.height = args.height;
            compareOptions.softSamples = args.softSamples;
            FlipCounter flips(compareOptions.litThreshold);
            Comparison comparison;
            for (int i = 0; i < (args.flips ? args.frames : 1); ++i) {
                const double t = args.timeSeconds + i / args.fps;
                moveToTime(scene, loaded, t);
                compareOptions.timeSeconds = t;
                ComparisonJob job(renderer, scene, compareOptions);
                // The technique's visibility on the job's technique frame, the last one rendered.
                std::vector<std::vector<float>> techniqueVisibility;
                if (args.flips)
                    for (std::size_t l = 0; l < scene.lights.size(); ++l) techniqueVisibility.push_back(renderer.readVisibility(scene, l));
                job.trace();
                Comparison c = job.finish(renderer);
                if (args.flips) flips.add(c, techniqueVisibility);
                if (i == 0) comparison = std::move(c);
            }
            moveToTime(scene, loaded, args.timeSeconds);

            const std::string stem = std::to_string(records.size()) + "-" + slug(label);
            const fs::path images = args.output / "images";
            writePng(images / (stem + "-technique.png"), comparison.technique);
            writePng(images / (stem + "-reference.png"), comparison.reference);
            json lights = json::array();
            for (std::size_t l = 0; l < comparison.lights.size(); ++l) {
                const LightComparison& c = comparison.lights[l];
                const std::string errorName = stem + "-error-" + std::to_string(l) + ".png";
                writePng(images / errorName, c.errorImage);
                json record = lightRecord(scene.lights[l], c, {{"errorImage", "images/" + errorName}});
                // The shadow pass beside its floor (a bare depth-only draw of
                // the same casters into a target of the same size), which it
                // contains as a nested scope.
                const std::string pass = "shadow[" + std::to_string(l) + "]";
                if (passTimes.count(pass)) {
                    const double whole = median(passTimes[pass]);
                    const double floor = passTimes.count(pass + ".floor") ? median(passTimes[pass + ".floor"]) : 0.0;
                    record["shadowPassMs"] = whole - floor;
                    if (floor > 0.0) {
                        record["shadowFloorMs"] = floor;
                        record["shadowPassOverFloor"] = (whole - floor) / floor;
                    }
                }
                if (counters.count(pass + ".triangles")) record["shadowTriangles"] = median(counters[pass + ".triangles"]);
                // Every other number the technique reported for its shadow pass
                // (a cube's triangles per face) and for its light pass (a
                // stencil technique's CPU silhouettes), by name, medians.
                auto reportedUnder = [&](const std::string& prefix, const std::string& skip) {
                    json out = json::object();
                    for (const auto& [name, values] : counters)
                        if (name.rfind(prefix, 0) == 0 && name != skip) out[name.substr(prefix.size())] = median(values);
                    return out;
                };
                if (json r = reportedUnder(pass + ".", pass + ".triangles"); !r.empty()) record["shadowCounters"] = std::move(r);
                if (json r = reportedUnder("light[" + std::to_string(l) + "].", ""); !r.empty()) record["lightCounters"] = std::move(r);
                if (args.flips) flips.addTo(record, l);
                lights.push_back(std::move(record));
            }
            json passes = json::object();
            for (const auto& [name, times] : passTimes) passes[name] = stats(times);
            json settings = json::object();
            for (const std::string& c : combo) {
                const auto eq = c.find('=');
                settings[c.substr(0, eq)] = c.substr(eq + 1);
            }
            std::size_t triangles = 0;
            for (const DrawItem& item : scene.drawItems()) triangles += scene.meshes[static_cast<std::size_t>(item.mesh)].triangleCount();
            records.push_back({{"scene", scene.name},
                               {"sceneFile", file.empty() ? "<default>" : file},
                               {"settings", settings},
                               {"triangles", triangles},
                               {"frames", args.frames},
                               {"clock", clockName},
                               {"baseLight", baseLight},
                               {"passMs", passes},
                               {"passTotalMs", stats(passTotal)},
                               {"frameMs", stats(frameTimes)},
                               {"unshadowedFrameMs", stats(unshadowedTimes)},
                               {"frameOverUnshadowed", median(frameTimes) / std::max(median(unshadowedTimes), 1e-9)},
                               // over the technique's baseline (for a map, the hard map)
                               {"frameOverHardMap", timeBaseline ? median(frameTimes) / std::max(median(baselineTimes), 1e-9) : 1.0},
                               {"referenceMs", comparison.referenceMs},
                               {"lights", lights},
                               {"techniqueImage", "images/" + stem + "-technique.png"},
                               {"referenceImage", "images/" + stem + "-reference.png"}});
            ++done;
            progress.step(done, label);
        }
    }
    const GlInfo& info = context.info();
    return json{{"tool", "shadowlab bench"},
                {"renderer", info.renderer},
                {"glVersion", info.version},
                {"width", args.width},
                {"height", args.height},
                {"frames", args.frames},
                {"warmup", args.warmup},
                {"time", args.timeSeconds},
                {"fps", args.fps},
                {"flips", args.flips},
                {"softSamples", args.softSamples},
                {"overrides", args.overrides},
                {"vary", args.vary},
                {"results", records}};
}

} // namespace shadowlab::tool
