// bench: a run's accuracy (BenchParts.h): its comparison with the
// ray-traced reference, and the temporal stability of its shadows (--flips).
#include "BenchParts.h"

#include <algorithm>

namespace shadowlab::bench {

using nlohmann::json;

void FlipCounter::add(const Comparison& c, const std::vector<std::vector<float>>& techniqueVisibility,
                      const std::vector<std::vector<float>>& throughPreviousMaps, const std::vector<bool>& lightStayed) {
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
            // A light that stayed: the same world points through both frames' maps.
            const bool samePoints = l < lightStayed.size() && lightStayed[l] && l < throughPreviousMaps.size();
            std::size_t receivers = 0, flips = 0, changes = 0;
            for (std::size_t i = 0; i < b.receiver.size(); ++i) {
                if (!a.receiver[i] || !b.receiver[i]) continue;
                ++receivers;
                const bool truthChanged = a.referenceLit[i] != b.referenceLit[i];
                changes += truthChanged;
                if (samePoints)
                    flips += (throughPreviousMaps[l][i] >= threshold_) != (b.techniqueLit[i] != 0);
                else
                    flips += !truthChanged && a.techniqueLit[i] != b.techniqueLit[i] && a.interior(i) && b.interior(i);
            }
            const double denominator = static_cast<double>(std::max<std::size_t>(receivers, 1));
            flips_[l].push_back(static_cast<double>(flips) / denominator);
            referenceChanges_[l].push_back(static_cast<double>(changes) / denominator);
        }
    }
    previous_ = std::move(frame);
}

void FlipCounter::addTo(json& record, std::size_t l) const {
    const auto summary = [](const std::vector<double>& shares) {
        double sum = 0.0;
        for (double share : shares) sum += share;
        return json{{"median", median(shares)}, {"mean", shares.empty() ? 0.0 : sum / static_cast<double>(shares.size())},
                    {"max", shares.empty() ? 0.0 : *std::max_element(shares.begin(), shares.end())}, {"perPair", shares}};
    };
    record["flips"] = summary(l < flips_.size() ? flips_[l] : std::vector<double>{});
    record["referenceChanges"] = summary(l < referenceChanges_.size() ? referenceChanges_[l] : std::vector<double>{});
}

bool FlipCounter::Classes::interior(std::size_t i) const {
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

Accuracy measureAccuracy(Renderer& renderer, Scene& scene, const Scene& loaded, const BenchOptions& args, const BenchHooks& hooks) {
    // The accuracy numbers at --time, as `compare --time` gives them;
    // with --flips, a comparison at every timed frame's time too
    // (the first of them is the one at --time).
    CompareOptions compareOptions;
    compareOptions.width = args.width;
    compareOptions.height = args.height;
    compareOptions.softSamples = args.softSamples;
    Accuracy out{{}, FlipCounter(compareOptions.litThreshold)};
    std::vector<Light> previousLights;
    for (int i = 0; i < (args.flips ? args.frames : 1); ++i) {
        const double t = args.timeSeconds + i / args.fps;
        moveToTime(scene, loaded, t);
        compareOptions.timeSeconds = t;
        // This view through the previous frame's maps, before this frame's replace them.
        std::vector<std::vector<float>> throughPreviousMaps;
        std::vector<bool> lightStayed;
        if (args.flips && i > 0) {
            RenderOptions through;
            through.width = args.width;
            through.height = args.height;
            through.timeSeconds = t;
            through.reuseShadowMaps = true;
            renderer.render(scene, through);
            for (std::size_t l = 0; l < scene.lights.size(); ++l) {
                throughPreviousMaps.push_back(renderer.readVisibility(scene, l));
                const Light &now = scene.lights[l], &before = previousLights[l];
                lightStayed.push_back(now.position == before.position && now.direction == before.direction);
            }
        }
        ComparisonJob job(renderer, scene, compareOptions);
        // The technique's visibility on the job's technique frame, the last one rendered.
        std::vector<std::vector<float>> techniqueVisibility;
        if (args.flips)
            for (std::size_t l = 0; l < scene.lights.size(); ++l) techniqueVisibility.push_back(renderer.readVisibility(scene, l));
        if (hooks.trace)
            hooks.trace(job);
        else
            job.trace();
        Comparison c = job.finish(renderer);
        if (args.flips) out.flips.add(c, techniqueVisibility, throughPreviousMaps, lightStayed);
        if (i == 0) out.comparison = std::move(c);
        previousLights = scene.lights;
    }
    moveToTime(scene, loaded, args.timeSeconds);
    return out;
}

} // namespace shadowlab::bench
