// `shadowlab compare` (CompareCommand.h).
#include "CompareCommand.h"

#include "Commands.h"
#include "Interrupt.h"
#include "OutputFiles.h"

#include <shadowlab/Compare.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/Limits.h>
#include <shadowlab/Renderer.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <unistd.h>  // isatty

namespace fs = std::filesystem;

namespace shadowlab::tool {

namespace {

std::string pct(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f%%", 100.0 * share);
    return buf;
}

// Light i's lines of the summary: its receivers, misclassified shares,
// visibility error, leaks, texel footprint (`hasCamera`: a technique that
// drew it a light camera, which should have one) and penumbra.
void printLight(std::ostream& out, std::size_t i, const LightComparison& l, const Light& light, bool hasCamera) {
    out << "light " << i << " '" << l.name << "' (" << toString(light.type) << ", " << (l.soft ? "soft" : "hard")
        << ", technique " << light.shadow.technique << "): " << l.receiverPixels << " receiver pixels, "
        << pct(l.receiverPixels ? double(l.referenceShadowedPixels) / double(l.receiverPixels) : 0.0)
        << " shadowed in truth\n"
        << "  misclassified, all receivers:      false shadow " << pct(l.falseShadow) << ", false lit " << pct(l.falseLit) << "\n"
        << "  misclassified, away from edges:    false shadow " << pct(l.falseShadowAwayFromEdges) << ", false lit "
        << pct(l.falseLitAwayFromEdges) << " (" << l.edgePixels << " pixels in the 1-pixel edge band)\n"
        << "  visibility error:                  MAE " << l.meanAbsError << ", RMSE " << l.rmse << "\n";
    if (l.coloured)
        out << "  coloured light, RMSE per channel:  red " << l.rmseRgb[0] << ", green " << l.rmseRgb[1] << ", blue " << l.rmseRgb[2] << "\n";
    if (l.umbraPixels > 0) out << "  light leaked into the umbra:       " << pct(l.leakedInUmbra) << " of the light (" << l.umbraPixels << " umbra pixels)\n";
    if (l.texelFootprintP50 >= 0.0)
        out << "  texel footprint (pixels a texel):  median " << l.texelFootprintP50 << ", p95 " << l.texelFootprintP95 << ", max "
                  << l.texelFootprintMax << "\n";
    else if (hasCamera)  // a map with no texel-density image (the shadow atlas's tiles): said, not left out silently
        out << "  texel footprint (pixels a texel):  not measured (the technique makes no texel-density image of this light's map)\n";
    if (l.soft)
        out << "  penumbra:                          " << l.techniquePenumbraPixels << " pixels against " << l.referencePenumbraPixels
                  << " in truth (ratio " << l.penumbraRatio() << ")\n";
}

} // namespace

CLI::App* addCompare(CLI::App& app, CompareArgs& args) {
    CLI::App* compare = app.add_subcommand("compare", "Compare a scene's shadow techniques with exact ray-traced shadows");
    compare->add_option("scene", args.scene, "Scene file (JSON); the built-in default scene when omitted");
    compare->add_option("-o,--output", args.output, "Output directory")->capture_default_str();
    compare->add_option("--width", args.width, "Image width in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    compare->add_option("--height", args.height, "Image height in pixels")->check(CLI::Range(1, 1 << 20))->capture_default_str();
    compare->add_option("--samples", args.softSamples, "Reference rays per pixel for lights with a size")
        ->check(CLI::Range(1, kMaxSoftSamples))->capture_default_str();
    compare->add_option("--set", args.overrides, "Override a scene value by JSON path")->take_all();
    compare->add_option("--camera", args.camera, "A glTF file's camera: its index among those the file's scene places, from 0 (default: the first)")->check(CLI::Range(0, 65535));
    compare->add_option("--time", args.timeSeconds, "Seconds since the start of the animation: where the light and camera paths are")
        ->capture_default_str();
    return compare;
}

int runCompare(const CompareArgs& args) {
    checkTime(args.timeSeconds, "--time");
    // Both sides, technique and reference, see the lights and the camera at --time.
    const Scene scene = sceneAtTime(loadScene(args.scene, args.overrides, args.camera), args.timeSeconds);
    const fs::path dir = checkOutputDirectory(args.output);
    checkMemory(args.width, args.height);
    checkReferenceRays(args.width, args.height, args.softSamples);
    checkSceneReferenceRays(args.width, args.height, args.softSamples,
                            static_cast<std::size_t>(std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.size > 0.0f; })));
    Context context = Context::createHeadless();
    checkSize(args.width, args.height, context.info());
    Renderer renderer(context);
    renderer.upload(scene);
    CompareOptions options;
    options.width = args.width;
    options.height = args.height;
    options.softSamples = args.softSamples;
    options.timeSeconds = args.timeSeconds;
    // compareWithReference's three steps, so that an interrupt stops the trace.
    ComparisonJob job(renderer, scene, options);
    // On a terminal, a trace of seconds or more says that it has begun (a
    // soft light's rays per pixel, every light's pixels); a log or a pipe
    // gets the error line alone when it fails.
    double rays = 0.0;
    for (const Light& light : scene.lights)
        rays += static_cast<double>(args.width) * args.height * (light.size > 0.0f ? args.softSamples : 1);
    if (rays >= 1e8 && isatty(STDERR_FILENO)) std::fprintf(stderr, "compare: tracing the reference, %.3g rays\n", rays);
    traceInterruptibly(job);
    const Comparison c = job.finish(renderer);
    // The lights whose technique drew them a light camera (a map): each
    // should have a texel footprint, and one that has none is said to have none.
    std::vector<bool> hasCamera(scene.lights.size(), false);
    for (const LightFrustum& f : renderer.lightFrustums(scene))
        if (f.light >= 0 && static_cast<std::size_t>(f.light) < hasCamera.size()) hasCamera[static_cast<std::size_t>(f.light)] = true;
    printNotes(c.techniqueFrame.notes);
    requireNoGlErrors(context);

    // Every file staged, then all renamed into place or none (OutputFiles.h).
    // Made here and the run fails: removed again once the files are (declared first, destroyed last).
    MadeDirectories made;
    made.make(dir, "-o " + args.output);
    PendingFiles pending;
    pending.write(dir / "technique.png", c.technique);
    pending.write(dir / "reference.png", c.reference);
    std::cout << "scene " << scene.name << ", " << args.width << "x" << args.height << ", reference traced in "
        << static_cast<long>(c.referenceMs) << " ms\n";
    for (std::size_t i = 0; i < c.lights.size(); ++i) {
        const LightComparison& l = c.lights[i];
        printLight(std::cout, i, l, scene.lights[i], hasCamera[i]);
        const std::string index = std::to_string(i);
        pending.write(dir / ("error-" + index + ".png"), l.errorImage);
        pending.write(dir / ("visibility-" + index + ".png"), l.referenceVisibility);
        pending.write(dir / ("technique-visibility-" + index + ".png"), l.techniqueVisibility);
        pending.write(dir / ("reach-" + index + ".png"), l.reach);
    }
    const std::string metrics = comparisonMetricsJson(scene, args.scene, options, c, true);
    pending.write(dir / "metrics.json", [&](const fs::path& p) { writeFileAtomically(p, metrics); });
    const std::vector<fs::path> written = pending.commit();
    made.keep();
    std::cout << "wrote";
    for (const fs::path& p : written) std::cout << " " << p.string();
    std::cout << "\n";
    if (!c.lights.empty())
        std::cout << "error-<i>.png: red = lit where truth is shadowed (false lit), blue = shadowed where truth is lit (false shadow), "
                     "paler in the 1-pixel edge band; grey = agrees, darker grey = not a receiver\n";
    return 0;
}

} // namespace shadowlab::tool
