#pragma once
// bench's parts (include/shadowlab/Bench.h), one responsibility a file, which runBench
// (Bench.cpp) calls in order: the runs its arguments expand into, each scene
// and combination parsed once (BenchRuns.cpp); a run's timed frames
// (BenchTiming.cpp); its accuracy against the reference and its temporal
// stability (BenchAccuracy.cpp); the record it leaves in results.json, with
// its images (BenchRecord.cpp).
#include <shadowlab/Bench.h>
#include <shadowlab/Compare.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/Scene.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace shadowlab::bench {

/// One --vary: a JSON path and its values (JSON text, split at top-level commas).
struct Variation {
    std::string key;
    std::vector<std::string> values;
};

/// Parses `key=v1,v2` (commas inside [] {} "" do not split). Throws Error naming the flag.
Variation parseVariation(const std::string& text);
/// Every combination of the variations' values as `key=value` overrides (cartesian product).
std::vector<std::vector<std::string>> combinations(const std::vector<Variation>& variations);
/// Number of runs `sceneCount` scenes and `variations` make (the product of
/// the value counts), computed without building them; throws Error naming
/// --vary and the limit when it exceeds kMaxBenchRuns (without overflowing).
std::size_t countRuns(std::size_t sceneCount, const std::vector<Variation>& variations);

/// One scene with one combination of the varied values.
struct BenchRun {
    std::string file;               ///< the scene file; empty for the built-in default scene
    std::vector<std::string> combo; ///< the combination as `key=value` overrides, after --set's
    Scene loaded;                   ///< the scene as parsed with them (paths not evaluated)
    bool skipped = false;           ///< left out while drawing (UnsupportedError with skipUnsupported)
};

/// Every scene with every combination of args.vary, scene by scene, each
/// parsed once, before anything is rendered: a bad value throws Error, one
/// that --vary gave naming that flag.
/// With args.skipUnsupported, the runs left out are added to `skipped`
/// (scene, combination, reason) instead.
std::vector<BenchRun> loadRuns(const BenchOptions& args, nlohmann::json* skipped = nullptr);

/// `scene`, a copy of `loaded` (its techniques may have been changed), with
/// its lights and camera where their paths are at `seconds`; the meshes are
/// not copied again.
void moveToTime(Scene& scene, const Scene& loaded, double seconds);

/// What a run's timed frames measured, per timed frame.
struct TimedFrames {
    std::map<std::string, std::vector<double>> passTimes, counters; ///< by pass (counter) name, from the clocked frames
    /// The unshadowed scene's passes, clocked the same way: a light pass's
    /// lookup cost is its time less the same pass here.
    std::map<std::string, std::vector<double>> unshadowedPassTimes;
    int unshadowedBaseLight = -1;
    std::vector<double> frameTimes;      ///< the plain frames' wall times, ms
    std::vector<double> unshadowedTimes; ///< the same scene with every technique "none"
    /// The unshadowed scene again with a pass per light (RenderOptions::
    /// groupLights off, the renderer before the clustered light list); timed
    /// only for three lights or more, where the list can group some.
    std::vector<double> unshadowedPerLightTimes;
    bool timedPerLight = false;
    /// The frame again right after a plain one, RenderOptions::cacheShadowMaps
    /// on: the maps whose inputs did not change are kept, not drawn.
    std::vector<double> cachedTimes;
    /// Where a clocked frame drew a depth pre-pass (fit "sdsm"), its base
    /// pass again in a clocked frame drawn at once with cacheShadowMaps,
    /// which keeps the maps and so draws no pre-pass: the base pass as it
    /// costs without the pre-pass's depth (its lookups against the same maps).
    std::vector<double> unprepassedBaseTimes;
    /// Scenes with a shadow atlas update budget (shadowAtlas.updateBudget):
    /// the frames in sequence on a renderer of their own, cacheShadowMaps
    /// on, so that at most that many changed tiles are drawn each frame.
    std::vector<double> budgetedTimes;
    /// The same scene with every light at its technique's baseline
    /// (shadowBaseline); timed only where some light differs from it.
    std::vector<double> baselineTimes;
    bool timedBaseline = false;
    std::vector<double> passTotal;       ///< the top-level passes summed
    std::string clock = "off";           ///< the clocked frames' clock
    int baseLight = -1;                  ///< FrameStats::baseLight
};

/// The warm-up frames at args.timeSeconds, then args.frames steps, step i at
/// args.timeSeconds + i / args.fps, each a plain frame, an unshadowed one, the
/// baseline's where timed and one with the pass clock. Leaves `scene` (a copy
/// of `loaded` at args.timeSeconds, uploaded to `renderer`) at the last step.
/// `budgeted`: a second renderer (the scene uploaded) for budgetedTimes, or
/// null. Calls hooks.checkpoint before each step.
TimedFrames timeFrames(Renderer& renderer, Scene& scene, const Scene& loaded, const BenchOptions& args, const BenchHooks& hooks,
                       Renderer* budgeted = nullptr);

/// Temporal stability (--flips), per light over consecutive frames: the share
/// of receiver pixels whose shadow changed although the truth there did not.
/// For a light that stayed put between the two frames (docs/metrics.md),
/// the shadow is compared at the same world points: the second frame's view
/// lit once through the first frame's maps and once through its own, so a
/// shadow edge that crawls because the maps' texel grid slid under the world
/// counts every pixel it crosses, edges included, while a grid that stays
/// put (stabilised cascades) counts nothing, however the view moves. For a
/// light that moved, whose shadow truly moves, the frames are compared pixel
/// by pixel away from the edges: a change counts where the reference's class
/// did not change and every receiver among the pixel's 8 neighbours has its
/// classes in both frames. Reference changes (the reference's class changed
/// at the pixel: true motion, on screen) are counted apart.
class FlipCounter {
public:
    explicit FlipCounter(float litThreshold) : threshold_(litThreshold) {}

    /// One frame: its comparison and each light's technique visibility, read
    /// back with the comparison's technique frame; from the second frame on,
    /// `throughPreviousMaps`: the same view lit through the previous frame's
    /// maps (read before this frame's were drawn), and `lightStayed`: per
    /// light, whether it is where it was in the previous frame.
    void add(const Comparison& c, const std::vector<std::vector<float>>& techniqueVisibility,
             const std::vector<std::vector<float>>& throughPreviousMaps = {}, const std::vector<bool>& lightStayed = {});

    /// Light l's `flips` and `referenceChanges`: median, mean, maximum and every
    /// pair's share, in frame order.
    void addTo(nlohmann::json& record, std::size_t l) const;

private:
    struct Classes {
        int width = 0;
        std::vector<std::uint8_t> receiver, techniqueLit, referenceLit;
        // Whether every receiver among pixel i's 8 neighbours has its classes.
        bool interior(std::size_t i) const;
    };
    float threshold_;
    std::vector<Classes> previous_;  ///< per light, the last frame's
    std::vector<std::vector<double>> flips_, referenceChanges_;  ///< per light, per pair of frames
};

/// A run's accuracy: the comparison at args.timeSeconds, as `compare --time`
/// gives it, and with --flips the flips over every timed frame's time.
struct Accuracy {
    Comparison comparison;
    FlipCounter flips;
};

/// Compares `scene` (as timeFrames left it) with the reference at
/// args.timeSeconds, and with --flips at every timed frame's time too (the
/// first of them is the one at args.timeSeconds); leaves `scene` at
/// args.timeSeconds. The references are traced by hooks.trace.
Accuracy measureAccuracy(Renderer& renderer, Scene& scene, const Scene& loaded, const BenchOptions& args, const BenchHooks& hooks);

/// The median of `values`; 0 when there are none.
double median(std::vector<double> values);

/// Run `index`'s record for results.json (`scene` at args.timeSeconds,
/// named `label`), its technique, reference and error images handed to
/// hooks.images with a file-name stem from `label`, under the names it gives.
nlohmann::json runRecord(const BenchRun& run, const Scene& scene, const TimedFrames& timed, const Accuracy& accuracy,
                         std::size_t index, const std::string& label, const BenchOptions& args, const BenchHooks& hooks);

} // namespace shadowlab::bench
