#pragma once
/// @file Compare.h
/// A technique against exact ray-traced shadows (Embree): per light, which
/// pixels it shadows wrongly, and how far its visibility is from the truth.
/// Only in builds with SHADOWLAB_WITH_EMBREE (the default). Metrics are
/// explained in docs/metrics.md.
#include <shadowlab/Export.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/Scene.h>

#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

/// The most reference rays a pixel a soft light may take (CompareOptions::softSamples).
constexpr int kMaxSoftSamples = 65536;

struct CompareOptions {
    int width = 960;          ///< pixels, default 960
    int height = 540;         ///< pixels, default 540
    int softSamples = 256;    ///< reference rays per pixel for lights with size > 0, 1..kMaxSoftSamples; default 256
    unsigned seed = 1;        ///< the reference's stratified jitter; default 1
    /// Visibility at or above this counts as lit when pixels are classified
    /// (both sides). Default 0.5.
    float litThreshold = 0.5f;
    /// Seconds since the start of an animation, handed to the techniques as
    /// RenderOptions::timeSeconds. It does not move the lights: pass a scene
    /// evaluated at this time (sceneAtTime), so both sides see the same
    /// light positions. Default 0.
    double timeSeconds = 0.0;
    /// Pixels: receivers within this many pixels of a true shadow edge form
    /// the edge band (LightComparison::edgePixels, the *AwayFromEdges
    /// shares), 1..64. A filter meant to soften is judged outside a band of
    /// its own reach on screen. Default 1
    int edgeBand = 1;
};

struct LightComparison {
    std::string name;             ///< the light's name
    bool soft = false;            ///< light.size > 0: the reference is Monte-Carlo visibility
    /// Receiver pixels: geometry that receives shadows, faces the light (geometric
    /// normal) and lies within its reach (spot cone, range). All shares below are of these.
    std::size_t receiverPixels = 0;
    std::size_t referenceShadowedPixels = 0; ///< receivers the reference classifies as shadowed
    std::size_t edgePixels = 0;   ///< receivers within 1 pixel of a true shadow edge
    double falseShadow = 0.0;     ///< share of receivers shadowed by the technique but lit in truth
    double falseLit = 0.0;        ///< share of receivers lit by the technique but shadowed in truth
    double falseShadowAwayFromEdges = 0.0; ///< falseShadow counted outside the edge band, share of receivers outside it
    double falseLitAwayFromEdges = 0.0;    ///< falseLit counted outside the edge band, share of receivers outside it
    double meanAbsError = 0.0;    ///< mean |technique - reference| visibility over receivers
    /// Receivers in the reference's umbra (visibility 0) outside the edge band.
    std::size_t umbraPixels = 0;
    /// Light leaked into the umbra: the technique's mean visibility over
    /// umbraPixels (0 when there are none). What filterable maps' light
    /// bleeding costs (docs/metrics.md).
    double leakedInUmbra = 0.0;
    /// Receivers in a penumbra (visibility strictly between 0.02 and 0.98),
    /// by the reference and by the technique. Over the same shadow edges
    /// their ratio is the penumbrae's width ratio (1: as wide as the truth;
    /// a hard technique under a soft light: near 0).
    std::size_t referencePenumbraPixels = 0, techniquePenumbraPixels = 0;
    double penumbraRatio() const {
        return referencePenumbraPixels ? static_cast<double>(techniquePenumbraPixels) / static_cast<double>(referencePenumbraPixels) : 0.0;
    }
    double rmse = 0.0;            ///< root mean square of the same
    /// The texel footprint (docs/metrics.md): how many screen pixels one
    /// shadow-map texel covers at a receiver pixel, the longer of a texel's
    /// two axes on screen (Lloyd's aliasing measure: about 1 is none, above
    /// 10 heavy; a cube map: the face the pixel samples). Median, 95th
    /// percentile and largest over the receivers the light's map covers;
    /// -1 when the technique has no map (nothing measured).
    double texelFootprintP50 = -1.0, texelFootprintP95 = -1.0, texelFootprintMax = -1.0;
    /// The same per channel (red, green, blue): light through translucent
    /// casters arrives coloured (both sides' RGB transmittance; equal to
    /// rmse in every channel without them).
    double rmseRgb[3] = {0.0, 0.0, 0.0};
    /// Whether the reference's light arrives coloured anywhere (a receiver
    /// whose channels differ): translucent casters in the way.
    bool coloured = false;
    /// 0 = shadowed .. 65535 = lit, whole image. Also 0 where the light does not
    /// reach (background, outside a spot's cone, beyond range, facing away): `reach` tells them apart.
    ImageGray16 referenceVisibility;
    /// The technique's own visibility the same way: 0 = shadowed .. 65535 = lit, 0 on the background.
    ImageGray16 techniqueVisibility;
    /// 255 on receiver pixels (the ones counted in receiverPixels: receive shadows,
    /// within the light's reach, facing it), 0 elsewhere.
    ImageGray8 reach;
    ImageRGBA8 errorImage;        ///< false lit red, false shadow blue, grey elsewhere (paler colours in the edge band)
};

struct Comparison {
    std::vector<LightComparison> lights;
    ImageRGBA8 technique;         ///< the scene as its techniques render it
    ImageRGBA8 reference;         ///< the same shading with exact visibility
    FrameStats techniqueFrame;    ///< the technique frame's timings (TimingClock::Auto, surfaces written)
    double referenceMs = 0.0;     ///< wall time of ray tracing, milliseconds
    SurfaceBuffer surfaces;       ///< the surface points both sides were judged at (the technique frame's base pass)
};

/// Renders `scene` (already uploaded to `renderer`) with its configured
/// techniques and with ray-traced visibility from the same visible surface
/// points, and compares them per light. Throws shadowlab::Error for bad
/// options, or when built without Embree. The same as a ComparisonJob's
/// three steps in a row.
SHADOWLAB_API Comparison compareWithReference(Renderer& renderer, const Scene& scene, const CompareOptions& options = {});

/// Light `light`'s comparison `c` as the JSON object compare's metrics.json
/// and bench's results.json write per light (without their image paths):
/// name, type, technique, soft, receiverPixels, referenceShadowedPixels,
/// edgePixels, falseShadow, falseLit, falseShadowAwayFromEdges,
/// falseLitAwayFromEdges, meanAbsError, rmse, umbraPixels, leakedInUmbra,
/// the penumbra counts and ratio, coloured, rmseRgb and, for a light with
/// a map, texelFootprintP50/P95/Max (docs/metrics.md).
SHADOWLAB_API std::string lightMetricsJson(const Light& light, const LightComparison& c);

/// compare's metrics.json for comparison `c` of `scene` (as compared, at
/// options.timeSeconds), as JSON text: scene, sceneFile (`sceneFile`, or
/// "<default>" when empty), width, height, softSamples, time, referenceMs
/// and per light lightMetricsJson's record. With `fileNames`, the records
/// also name the files `shadowlab compare -o DIR` writes beside it:
/// techniqueImage (technique.png), referenceImage (reference.png) and per
/// light N errorImage (error-N.png), visibilityImage (visibility-N.png),
/// techniqueVisibilityImage (technique-visibility-N.png) and reachImage (reach-N.png).
SHADOWLAB_API std::string comparisonMetricsJson(const Scene& scene, const std::string& sceneFile, const CompareOptions& options,
                                                const Comparison& c, bool fileNames);

/// compareWithReference in three steps, so that a window stays responsive
/// while the reference is traced:
///  1. the constructor renders the technique's frame and reads back what it
///     needs (on the renderer's GL thread; quick);
///  2. trace() ray-traces the reference (on any thread; the long part),
///     with progress() and cancel() callable from any thread meanwhile;
///  3. finish() shades the reference image and classifies the pixels (on the
///     GL thread again, after trace() returned, the scene still uploaded).
class SHADOWLAB_API ComparisonJob {
public:
    /// Throws shadowlab::Error for bad options, or when built without Embree.
    ComparisonJob(Renderer& renderer, const Scene& scene, const CompareOptions& options = {});
    ~ComparisonJob();
    ComparisonJob(const ComparisonJob&) = delete;
    ComparisonJob& operator=(const ComparisonJob&) = delete;

    /// Traces every light's reference. Once; throws shadowlab::Error when
    /// cancelled or when the tracer fails.
    void trace();
    /// The share of surface points traced, 0 .. 1.
    double progress() const;
    /// Makes a running or later trace() stop soon and throw.
    void cancel();
    /// The comparison; throws shadowlab::Error unless trace() completed.
    Comparison finish(Renderer& renderer);

private:
    struct SHADOWLAB_HIDDEN Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace shadowlab
