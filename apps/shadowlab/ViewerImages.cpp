// The images the viewer reads back for the panel and the picture: the
// comparison with the ray-traced reference (traced on a worker thread while
// the window goes on drawing, then one error image per light), and the
// techniques' debug images (maps, cube crosses, the texel density).
#include "ViewerSession.h"

#include <shadowlab/Error.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace fs = std::filesystem;

namespace shadowlab::viewer {

void ViewerSession::startComparison(int width, int height) {
    referenceAsked = false;
    try {
        CompareOptions options;
        options.width = width;
        options.height = height;
        options.timeSeconds = seconds;
        auto run = std::make_unique<ReferenceRun>();
        run->directory = compareDirectory;
        run->label = compareLabel;
        run->startFrame = frame;
        run->job = std::make_unique<ComparisonJob>(renderer, lastShown, options);
        ReferenceRun* r = run.get();
        r->worker = std::thread([r] {
            try {
                r->job->trace();
            } catch (const Error& e) {
                r->error = e.what();
            }
            r->done = true;
        });
        tracing = std::move(run);
    } catch (const Error& e) {
        error = e.what();
        if (!script.empty()) throw;
    }
    compareDirectory.clear();
}

void ViewerSession::finishComparison() {
    tracing->worker.join();
    const std::unique_ptr<ReferenceRun> run = std::move(tracing);
    if (!run->error.empty()) {
        error = run->error;
        if (!script.empty()) throw Error((run->label.empty() ? args.script + ": compare" : run->label) + ": " + run->error);
    } else {
        const Comparison c = run->job->finish(renderer);
        if (!script.empty())
            std::cout << "compare: traced in " << std::lround(c.referenceMs) << " ms while the window drew " << frame - run->startFrame << " frames\n";
        freeReferenceTextures();
        referenceLines.clear();
        referenceImages.clear();
        for (std::size_t l = 0; l < c.lights.size(); ++l) {
            const LightComparison& lc = c.lights[l];
            char line[240];
            std::snprintf(line, sizeof line, "%s: %.3f %% wrong away from edges, %.3f %% in all (%zu receiver pixels)", lc.name.c_str(),
                          100.0 * (lc.falseLitAwayFromEdges + lc.falseShadowAwayFromEdges), 100.0 * (lc.falseLit + lc.falseShadow),
                          lc.receiverPixels);
            referenceLines.push_back(line);
            referenceImages.push_back(lc.errorImage);
            referenceTextures.push_back(ImageTexture(lc.errorImage));
            if (!script.empty()) std::cout << "compare: light " << l << " " << line << "\n";
            if (!run->directory.empty()) {
                const std::string file = (fs::path(run->directory) / ("error-" + std::to_string(l) + ".png")).string();
                try {
                    // Put in place with the script's screenshots when it ends well (a failing later line leaves none).
                    if (std::error_code ec; fs::is_directory(file, ec)) throw Error(file + ": cannot write (a directory of that name is in the way)");
                    scriptOutputs.write(file, lc.errorImage);
                } catch (const Error& e) {
                    throw Error(run->label.empty() ? std::string(e.what()) : run->label + ": " + e.what());
                }
            }
        }
    }
}

void ViewerSession::refreshDebugImages() {
    // Read back every tenth frame for the panel, every fourth for the
    // texel-density tint (it follows the camera).
    if (frame > 0 && ((showDebug && frame % 10 == 1) || (showDensity && frame % 4 == 1))) {
        debugImages = renderer.debugImages(lastShown);
        freeDebugTextures();
        if (showDebug)
            for (const DebugImage& d : debugImages) debugTextures.push_back(ImageTexture(d.image));
        densityTexture = ImageTexture();
        for (const DebugImage& d : debugImages)
            if (showDensity && d.kind == DebugImageKind::TexelDensity && d.light == selectedLight) densityTexture = ImageTexture(d.image);
    }
    if (!showDebug && !debugTextures.empty()) freeDebugTextures();
    if (!showDensity) densityTexture = ImageTexture();
    if (!showDebug && !showDensity) debugImages.clear();
}

} // namespace shadowlab::viewer
