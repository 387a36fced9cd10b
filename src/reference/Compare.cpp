// compareWithReference: the technique's per-pixel visibility against the
// ray-traced truth at the very same surface points (read back from the
// rasterizer's base pass), classified and measured per light.
#include <shadowlab/Compare.h>

#include "reference/EdgeBand.h"
#include "reference/RayTracer.h"

#include <shadowlab/Error.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace shadowlab {

namespace {

std::uint8_t toByte(float v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

#ifdef SHADOWLAB_WITH_EMBREE
using reference::Extension;
using reference::PixelClasses;

// One light's visibility per surface pixel, the technique's (read back with
// its frame) and the reference's, their means and RGB; and the reference's
// at the extensions.
struct LightVisibility {
    const std::vector<float>& technique;
    const std::vector<float>& exact;
    const std::vector<glm::vec3>& techniqueRgb;
    const std::vector<glm::vec3>& truthRgb;
    const std::vector<float>& extensionExact;
};

// One light's counts and sums over its receivers, made rates by summarise().
struct Tally {
    std::size_t falseShadow = 0, falseLit = 0, falseShadowAway = 0, falseLitAway = 0;
    double absSum = 0.0, sqSum = 0.0, leakSum = 0.0;
    double sqSumRgb[3] = {0.0, 0.0, 0.0};
};

// Both visibility images, the error image over the dimmed `reference` image,
// and the receivers' counts: c's pixel counts directly, the rest in the tally.
Tally measure(LightComparison& c, const PixelClasses& classes, const LightVisibility& vis, const ImageRGBA8& reference,
              float litThreshold) {
    const int w = classes.w, h = classes.h;
    const std::size_t n = static_cast<std::size_t>(w) * h;
    const std::vector<std::uint8_t>& receiver = classes.receiver;
    const std::vector<std::uint8_t>& exactLit = classes.exactLit;
    const std::vector<std::uint8_t>& edge = classes.edge;
    const std::vector<float>& technique = vis.technique;
    const std::vector<float>& exact = vis.exact;
    Tally tally;
    c.referenceVisibility = {w, h, std::vector<std::uint16_t>(n, 0)};
    c.techniqueVisibility = {w, h, std::vector<std::uint16_t>(n, 0)};
    c.errorImage = {w, h, std::vector<std::uint8_t>(n * 4, 0)};
    for (std::size_t i = 0; i < n; ++i) {
        c.referenceVisibility.pixels[i] = static_cast<std::uint16_t>(std::lround(std::clamp(exact[i], 0.0f, 1.0f) * 65535.0f));
        c.techniqueVisibility.pixels[i] = static_cast<std::uint16_t>(std::lround(std::clamp(technique[i], 0.0f, 1.0f) * 65535.0f));
        // Grey: the reference image's own luminance, dimmed, so the scene stays readable.
        const std::uint8_t* ref = &reference.pixels[i * 4];
        std::uint8_t rgb[3];
        const float grey = (0.3f * ref[0] + 0.59f * ref[1] + 0.11f * ref[2]) / 255.0f;
        const std::uint8_t g = toByte(receiver[i] ? 0.25f + 0.5f * grey : 0.1f + 0.25f * grey);
        rgb[0] = rgb[1] = rgb[2] = g;
        if (receiver[i]) {
            ++c.receiverPixels;
            c.referenceShadowedPixels += !exactLit[i];
            c.edgePixels += edge[i];
            const bool techniqueLit = technique[i] >= litThreshold;
            const double e = static_cast<double>(technique[i]) - exact[i];
            tally.absSum += std::fabs(e);
            tally.sqSum += e * e;
            const glm::vec3& t = vis.techniqueRgb[i];
            const glm::vec3& r = vis.truthRgb[i];
            for (int ch = 0; ch < 3; ++ch) tally.sqSumRgb[ch] += static_cast<double>(t[ch] - r[ch]) * static_cast<double>(t[ch] - r[ch]);
            c.coloured = c.coloured || std::fabs(r.r - r.g) > 1e-3f || std::fabs(r.g - r.b) > 1e-3f;
            const auto penumbra = [](float v) { return v > 0.02f && v < 0.98f; };
            c.referencePenumbraPixels += penumbra(exact[i]);
            c.techniquePenumbraPixels += penumbra(technique[i]);
            if (exact[i] <= 0.0f && !edge[i]) {
                ++c.umbraPixels;
                tally.leakSum += std::clamp(technique[i], 0.0f, 1.0f);
            }
            if (techniqueLit && !exactLit[i]) {
                ++tally.falseLit;
                tally.falseLitAway += !edge[i];
                const std::uint8_t red[3] = {235, 40, 30}, pale[3] = {240, 150, 140};
                std::copy_n(edge[i] ? pale : red, 3, rgb);
            } else if (!techniqueLit && exactLit[i]) {
                ++tally.falseShadow;
                tally.falseShadowAway += !edge[i];
                const std::uint8_t blue[3] = {40, 110, 240}, pale[3] = {150, 180, 240};
                std::copy_n(edge[i] ? pale : blue, 3, rgb);
            }
        }
        std::copy_n(rgb, 3, &c.errorImage.pixels[i * 4]);
        c.errorImage.pixels[i * 4 + 3] = 255;
    }
    return tally;
}

// c's shares, errors and leak: the tally over its receivers (or over those
// away from the edge band, or in the umbra).
void summarise(LightComparison& c, const Tally& tally) {
    const double receivers = static_cast<double>(std::max<std::size_t>(c.receiverPixels, 1));
    const double away = static_cast<double>(std::max<std::size_t>(c.receiverPixels - c.edgePixels, 1));
    c.falseShadow = static_cast<double>(tally.falseShadow) / receivers;
    c.falseLit = static_cast<double>(tally.falseLit) / receivers;
    c.falseShadowAwayFromEdges = static_cast<double>(tally.falseShadowAway) / away;
    c.falseLitAwayFromEdges = static_cast<double>(tally.falseLitAway) / away;
    c.meanAbsError = tally.absSum / receivers;
    c.rmse = std::sqrt(tally.sqSum / receivers);
    for (int ch = 0; ch < 3; ++ch) c.rmseRgb[ch] = std::sqrt(tally.sqSumRgb[ch] / receivers);
    c.leakedInUmbra = c.umbraPixels ? tally.leakSum / static_cast<double>(c.umbraPixels) : 0.0;
}

// The texel footprint's median, 95th percentile and largest value over
// the receivers (`reach`) where the technique measured one (`footprint`,
// from its texel-density debug image: >= 0 where the map covers the
// point); left at -1 when there is none.
void footprintPercentiles(LightComparison& c, const std::vector<float>& footprint) {
    std::vector<float> v;
    for (std::size_t i = 0; i < footprint.size() && i < c.reach.pixels.size(); ++i)
        if (c.reach.pixels[i] && footprint[i] >= 0.0f) v.push_back(footprint[i]);
    if (v.empty()) return;
    std::sort(v.begin(), v.end());
    // Nearest rank: the smallest value with at least q of the values at or below it.
    const auto rank = [&](double q) { return static_cast<double>(v[static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size()))) - 1]); };
    c.texelFootprintP50 = rank(0.5);
    c.texelFootprintP95 = rank(0.95);
    c.texelFootprintMax = v.back();
}
#endif

} // namespace

#ifdef SHADOWLAB_WITH_EMBREE
struct ComparisonJob::Impl {
    Scene scene;
    CompareOptions options;
    Comparison out;
    std::vector<reference::SurfaceSample> samples;
    std::vector<Extension> extensions;
    std::vector<reference::SurfaceSample> extensionSamples;
    std::vector<std::vector<float>> techniqueVisibility;  ///< per light, read back with the technique's frame: the mean of...
    std::vector<std::vector<glm::vec3>> techniqueRgb;     ///< ...its channels
    std::vector<std::vector<float>> truth, extensionTruth;
    std::vector<std::vector<glm::vec3>> truthRgb;
    std::vector<std::vector<float>> footprints;  ///< per light: the texel footprint per pixel, or empty (footprintPercentiles)
    std::atomic<std::size_t> samplesDone{0};
    std::atomic<bool> cancelled{false};
    bool traced = false;
};
#else
struct ComparisonJob::Impl {};
#endif

ComparisonJob::~ComparisonJob() = default;

Comparison compareWithReference(Renderer& renderer, const Scene& scene, const CompareOptions& options) {
    ComparisonJob job(renderer, scene, options);
    job.trace();
    return job.finish(renderer);
}

#ifndef SHADOWLAB_WITH_EMBREE
ComparisonJob::ComparisonJob(Renderer&, const Scene&, const CompareOptions&) {
    throw Error("compare: this build has no ray-traced reference (configure with -DSHADOWLAB_WITH_EMBREE=ON)");
}
void ComparisonJob::trace() {}
double ComparisonJob::progress() const { return 0.0; }
void ComparisonJob::cancel() {}
Comparison ComparisonJob::finish(Renderer&) { return {}; }
#else
ComparisonJob::ComparisonJob(Renderer& renderer, const Scene& scene, const CompareOptions& options) : impl_(std::make_unique<Impl>()) {
    if (options.softSamples < 1 || options.softSamples > kMaxSoftSamples)
        throw Error("compare: softSamples must be in 1.." + std::to_string(kMaxSoftSamples) + ", got " + std::to_string(options.softSamples));
    if (options.edgeBand < 1 || options.edgeBand > 64) throw Error("compare: edgeBand must be in 1..64 pixels, got " + std::to_string(options.edgeBand));
    if (!(options.litThreshold > 0.0f && options.litThreshold <= 1.0f))
        throw Error("compare: litThreshold must be in (0, 1]");
    Impl& d = *impl_;
    d.scene = scene;
    d.options = options;
    RenderOptions renderOptions;
    renderOptions.width = options.width;
    renderOptions.height = options.height;
    renderOptions.clock = TimingClock::Auto;
    renderOptions.surfaces = true;  // the reference traces from the base pass's surface points
    renderOptions.timeSeconds = options.timeSeconds;
    Comparison& out = d.out;
    out.techniqueFrame = renderer.render(scene, renderOptions);
    out.technique = renderer.readColor();
    out.surfaces = renderer.readSurfaces();
    // The technique's own visibility per light.
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        d.techniqueRgb.push_back(renderer.readVisibilityRgb(scene, l));
        std::vector<float> mean(d.techniqueRgb.back().size());
        for (std::size_t i = 0; i < mean.size(); ++i) mean[i] = (d.techniqueRgb.back()[i].r + d.techniqueRgb.back()[i].g + d.techniqueRgb.back()[i].b) / 3.0f;
        d.techniqueVisibility.push_back(std::move(mean));
    }
    // Each light's texel footprint, from the debug image that shows it.
    d.footprints.assign(scene.lights.size(), {});
    for (DebugImage& image : renderer.debugImages(scene, {{DebugImageKind::TexelDensity}}))
        if (image.light >= 0 && static_cast<std::size_t>(image.light) < scene.lights.size())
            d.footprints[static_cast<std::size_t>(image.light)] = std::move(image.values);
    const SurfaceBuffer& surfaces = out.surfaces;
    const std::size_t n = static_cast<std::size_t>(surfaces.width) * surfaces.height;

    d.samples.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 normal(surfaces.normal[i]);
        const float len = glm::length(normal);
        reference::SurfaceSample& s = d.samples[i];
        s.valid = surfaces.position[i].w > 0.5f && len > 0.5f;
        s.position = glm::vec3(surfaces.position[i]);
        s.normal = s.valid ? normal / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }

    // Points on each surface pixel's own plane under its neighbours' pixel
    // centres, where a neighbour is on another surface (the edge band below).
    d.extensions = surfaceExtensions(scene, surfaces, d.samples);
    d.extensionSamples.resize(d.extensions.size());
    for (std::size_t k = 0; k < d.extensions.size(); ++k)
        d.extensionSamples[k] = {d.extensions[k].position, d.samples[d.extensions[k].pixel].normal, true};
}

void ComparisonJob::trace() {
    Impl& d = *impl_;
    if (d.traced) return;
    if (d.cancelled) throw Error("compare: cancelled");
    const auto traceStart = std::chrono::steady_clock::now();
    const reference::RayTracer tracer(d.scene);
    reference::VisibilityOptions visibilityOptions;
    visibilityOptions.softSamples = d.options.softSamples;
    visibilityOptions.seed = d.options.seed;
    visibilityOptions.samplesDone = &d.samplesDone;
    visibilityOptions.cancel = &d.cancelled;
    for (const Light& light : d.scene.lights) {
        d.truthRgb.emplace_back();
        visibilityOptions.transmittance = &d.truthRgb.back();
        d.truth.push_back(tracer.visibility(light, d.samples, visibilityOptions));
        visibilityOptions.transmittance = nullptr;
        d.extensionTruth.push_back(tracer.visibility(light, d.extensionSamples, visibilityOptions));
    }
    d.out.referenceMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - traceStart).count();
    d.traced = true;
}

double ComparisonJob::progress() const {
    const Impl& d = *impl_;
    const double total = static_cast<double>(d.scene.lights.size()) * static_cast<double>(d.samples.size() + d.extensionSamples.size());
    return total > 0.0 ? std::min(1.0, static_cast<double>(d.samplesDone.load()) / total) : 1.0;
}

void ComparisonJob::cancel() { impl_->cancelled = true; }

Comparison ComparisonJob::finish(Renderer& renderer) {
    Impl& d = *impl_;
    if (!d.traced) throw Error("compare: finish() before trace() completed");
    const Scene& scene = d.scene;
    const CompareOptions& options = d.options;
    Comparison& out = d.out;
    const SurfaceBuffer& surfaces = out.surfaces;

    // The reference image (same shading, exact visibility) for the error images' backdrop.
    RenderOptions referenceOptions;
    referenceOptions.width = options.width;
    referenceOptions.height = options.height;
    referenceOptions.timeSeconds = options.timeSeconds;
    renderer.renderWithVisibility(scene, referenceOptions, d.truth);
    out.reference = renderer.readColor();

    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        const LightVisibility vis{d.techniqueVisibility[l], d.truth[l], d.techniqueRgb[l], d.truthRgb[l], d.extensionTruth[l]};
        LightComparison c;
        c.name = light.name;
        c.soft = light.size > 0.0f;
        PixelClasses classes = classify(light, d.samples, surfaces, vis.exact, options.litThreshold, c.reach);
        markEdgeBand(classes, d.extensions, vis.extensionExact, options.litThreshold);
        widenEdgeBand(classes, options.edgeBand);
        summarise(c, measure(c, classes, vis, out.reference, options.litThreshold));
        footprintPercentiles(c, d.footprints[l]);
        out.lights.push_back(std::move(c));
    }
    return std::move(out);
}
#endif

} // namespace shadowlab
