// report.html: one self-contained page (images inlined as data URIs, plot as
// inline SVG, no scripts from elsewhere) that opens from disk.
#include "bench/ReportPlots.h"
#include "bench/ReportTable.h"
#include "bench/ReportText.h"

#include <shadowlab/Bench.h>
#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

namespace shadowlab::bench {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The page's head and its first paragraph: the run's parameters.
void introduction(std::ostream& h, const json& results) {
    const json& records = results["results"];
    h << R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>shadowlab bench report</title>
<style>
body { font: 14px/1.4 system-ui, sans-serif; margin: 24px; color: #222; }
.scroll { overflow-x: auto; }
table { border-collapse: collapse; margin: 12px 0; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
th { background: #f0f0f0; } td.l { text-align: left; }
figure { display: inline-block; margin: 4px; } figure img { width: 320px; display: block; }
figcaption { font-size: 12px; color: #555; }
.legend span { display: inline-block; padding: 0 6px; margin-right: 6px; color: #fff; }
.cost { display: flex; height: 12px; width: 160px; background: #f4f4f4; } .cost span { display: block; height: 12px; }
ul.lights { margin: 4px 0; padding-left: 18px; min-width: 600px; white-space: normal; font-size: 12px; } details p { font-size: 12px; margin: 2px 0; }
.c-floor { background: #4c72b0; } .c-pass { background: #9ab3dd; } .c-lfloor { background: #a0522d; } .c-lookup { background: #dd8452; } .c-rest { background: #bbb; }
</style></head><body>
<h1>shadowlab bench</h1>
)";
    h << "<p>" << escape(results["renderer"].get<std::string>()) << ", OpenGL " << escape(results["glVersion"].get<std::string>())
      << ". " << results["width"] << "&times;" << results["height"] << " pixels, " << results["frames"] << " timed frames after "
      << results["warmup"] << " warm-up frames per row; animated lights at " << results.value("time", 0.0) << " s + k / "
      << results.value("fps", 30.0) << " fps in timed frame k, at " << results.value("time", 0.0)
      << " s in the warm-up and the accuracy comparison. Frame: wall time of a finished frame as users get it; passes: "
      << escape(records.empty() ? std::string("-") : records[0]["clock"].get<std::string>())
      << " clock (cpu-finish: glFinish around each pass on a software rasteriser; gpu-timestamp: GL_TIMESTAMP queries); "
         "medians, min&ndash;max in brackets. ";
    if (const int rounds = results.value("rounds", 1); rounds > 1)
        h << "Timed in " << rounds << " interleaved rounds, the rows in turn in each; every row shows its fastest round (lowest median frame), whole. ";
    h << "Accuracy against the Embree ray-traced reference at the same surface points; shares of receiver pixels "
         "(see docs/metrics.md).";
    const bool flips = results.value("flips", false);
    if (flips)
        h << " Flips: each timed frame compared with the reference; the share of receiver pixels whose shadow changes between "
             "consecutive frames at the same world point while the truth there does not (docs/metrics.md), median and maximum "
             "over the pairs of frames, beside the share whose reference changed on screen (true motion).";
    h << "</p>\n";
}

// The images' width in the page, pixels (figure img's CSS width): they are
// inlined at that size, the rendered frames as JPEG.
constexpr int kThumbnailWidth = 320;

// Every row's technique, reference and error images, inlined.
void imageSections(std::ostream& h, const json& records, const fs::path& directory) {
    h << "<h2>Images</h2>\n<p class=\"legend\">Error images: <span style=\"background:#eb281e\">false lit</span>"
         "<span style=\"background:#286ef0\">false shadow</span> paler in the 1-pixel band around true shadow edges; grey: agrees.</p>\n";
    int index = 0;
    for (const json& r : records) {
        h << "<section class=\"row\"><h3>" << index << ". " << escape(r["scene"].get<std::string>()) << " &mdash; "
          << escape(settingsText(r)) << "</h3>\n";
        auto figure = [&](const std::string& file, const std::string& caption, bool photo) {
            h << "<figure><img alt=\"" << escape(caption) << "\" src=\"" << thumbnailUri(directory / file, kThumbnailWidth, photo) << "\"><figcaption>"
              << escape(caption) << "</figcaption></figure>\n";
        };
        figure(r["techniqueImage"], "technique", true);
        figure(r["referenceImage"], "ray-traced reference", true);
        for (const json& l : r["lights"]) figure(l["errorImage"], "error: " + l["name"].get<std::string>(), false);
        h << "</section>\n";
        ++index;
    }
}

void writeReport(const json& results, const fs::path& directory) {
    const json& records = results["results"];
    std::ostringstream h;
    introduction(h, results);
    const bool flips = results.value("flips", false);
    resultsTable(h, records, flips);
    h << "<h2>Time against error</h2>\n<p>Each point is a row of the table (its number; a number that would overlap another is left "
         "to the point's tooltip); lower left is better. One plot per measure: the misclassified share away from edges for the rows' "
         "hard lights, the visibility RMSE for their soft ones. Orange, and &#9679; in the table's front column: the rows on their "
         "scene's time&ndash;error front (the Pareto front), those no other row of the same scene beats in both frame time and error "
         "(the two measures averaged over a row's lights): for a frame-time budget, the least error is among them.</p>\n"
      << scatterPlot(records, false) << scatterPlot(records, true);
    h << lightCountSection(records);
    imageSections(h, records, directory);
    // Lets a test (or a person) see that every image decoded.
    h << R"(<script>
window.addEventListener('load', () => {
  const images = Array.from(document.images);
  const ok = images.filter(i => i.complete && i.naturalWidth > 0).length;
  document.body.dataset.imagesLoaded = ok + '/' + images.length;
  // Where the table's accuracy columns and the plots lie on the page (CSS
  // pixels from its top left), for a test in a browser of a given size.
  const rect = e => { const r = e.getBoundingClientRect(); return {x: r.left + scrollX, y: r.top + scrollY, width: r.width, height: r.height}; };
  const heads = Array.from(document.querySelectorAll('#results th'));
  const accuracy = heads.filter(th => /misclassified|false lit|false shadow|RMSE/.test(th.textContent)).map(rect);
  const plots = Array.from(document.querySelectorAll('svg[id^="scatter"], svg#lightcount')).map(e => Object.assign({id: e.id}, rect(e)));
  const rows = document.querySelectorAll('#results > tbody > tr, #results > tr').length;
  document.body.dataset.layout = JSON.stringify({viewport: {width: innerWidth, height: innerHeight}, accuracy, plots, rows});
});
</script>
</body></html>
)";
    writeFileAtomically(directory / "report.html", h.str());
}

} // namespace

} // namespace shadowlab::bench

namespace shadowlab {

void writeBenchReport(const std::string& resultsJson, const std::filesystem::path& directory) {
    const nlohmann::json results = nlohmann::json::parse(resultsJson, nullptr, false);
    if (results.is_discarded() || !results.is_object() || !results.contains("results") || !results["results"].is_array())
        throw Error("writeBenchReport: not bench's results (a JSON object with a \"results\" array)");
    bench::writeReport(results, directory);
}

} // namespace shadowlab
