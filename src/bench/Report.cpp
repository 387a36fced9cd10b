// report.html: one self-contained page (images inlined as data URIs, plot as
// inline SVG, no scripts from elsewhere) that opens from disk.
#include "bench/ReportPlots.h"
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

// Where a row's time goes: its top-level passes' medians summed by kind.
struct PassSums {
    double shadowMs = 0, baseMs = 0, lightMs = 0;
};

PassSums passSums(const json& r) {
    PassSums sums;
    for (const auto& [name, st] : r["passMs"].items()) {
        const bool floorScope = name.ends_with("].floor") || name.ends_with("].lookupFloor");
        if (name.rfind("shadow", 0) == 0 && floorScope) sums.shadowMs -= st["median"].get<double>();  // bench's floors, drawn inside the pass
        if (name.find('.') != std::string::npos) continue;  // nested scopes are inside their pass
        if (name.rfind("shadow", 0) == 0) sums.shadowMs += st["median"].get<double>();
        if (name == "base") sums.baseMs += st["median"].get<double>();
        if (name.rfind("light", 0) == 0) sums.lightMs += st["median"].get<double>();
    }
    return sums;
}

// Where light `l`'s share of row `r`'s frame goes, as a bar `scale` px per
// ms: the shadow pass's floor (a bare depth draw of the same casters), the
// pass above it, the lookups (its pass minus the same pass unshadowed),
// split at their floor (one nearest fetch a pixel) where bench measured
// one, and the rest of the frame. The passes are clocked apart from the frame
// (cpu-finish adds a glFinish around each), so the parts may not add up
// to it: the rest is what is left, at least 0.
std::string costBar(const json& r, const json& l, double scale) {
    const double frame = r["frameMs"]["median"].get<double>();
    // A pass or floor clocked below 0 (their differences, on a busy machine) counts as 0.
    const double pass = std::max(l.value("shadowPassMs", 0.0), 0.0), floor = std::clamp(l.value("shadowFloorMs", 0.0), 0.0, pass);
    const double lookup = std::max(l.value("lookupMs", 0.0), 0.0), rest = std::max(frame - pass - lookup, 0.0);
    const double lookupFloor = std::clamp(l.value("lookupFloorMs", 0.0), 0.0, lookup);
    std::ostringstream s;
    s << "<div class=\"cost\" title=\"shadow pass floor " << fixed(floor, 1) << " ms, pass above its floor " << fixed(pass - floor, 1)
      << " ms, lookup floor " << fixed(lookupFloor, 1) << " ms, lookups above their floor " << fixed(lookup - lookupFloor, 1) << " ms, rest of the frame "
      << fixed(rest, 1) << " ms\">";
    const std::pair<const char*, double> parts[] = {{"c-floor", floor},         {"c-pass", pass - floor},           {"c-lfloor", lookupFloor},
                                                    {"c-lookup", lookup - lookupFloor}, {"c-rest", rest}};
    for (const auto& [cls, ms] : parts) s << "<span class=\"" << cls << "\" style=\"width:" << fixed(ms * scale, 1) << "px\"></span>";
    s << "</div>";
    return s.str();
}

// Row `index`'s line for its light `l` in the table.
void lightRow(std::ostream& h, const json& records, int index, const json& l, double fastest, double scale, bool flips) {
    const json& r = records[static_cast<std::size_t>(index)];
    const auto [shadowMs, baseMs, lightMs] = passSums(r);
    const json& g = r["frameMs"];
    h << "<tr><td>" << index << "</td><td class=\"l\">" << escape(r["scene"].get<std::string>()) << "</td><td class=\"l\">"
      << escape(settingsText(r)) << "</td><td class=\"l\">" << escape(l["name"].get<std::string>()) << " ("
      << escape(l["type"].get<std::string>()) << (l["soft"].get<bool>() ? ", soft" : "") << ")</td><td class=\"l\">"
      << escape(l["technique"].get<std::string>()) << "</td><td>" << r["triangles"] << "</td><td>"
      << fixed(g["median"], 1) << " (" << fixed(g["min"], 1) << "&ndash;" << fixed(g["max"], 1) << ")</td><td>"
      << (fastest > 0.0 ? fixed(g["median"].get<double>() / fastest, 2) : std::string("&ndash;")) << "</td><td>"
      << (r.contains("frameOverUnshadowed") ? fixed(r["frameOverUnshadowed"], 2) : std::string("&ndash;")) << "</td><td>"
      << (r.contains("floorFrameOverUnshadowed") ? fixed(r["floorFrameOverUnshadowed"], 2) : std::string("&ndash;")) << "</td><td>"
      << fixed(shadowMs, 1) << "</td><td>" << (l.contains("shadowFloorMs") ? fixed(l["shadowFloorMs"], 1) : std::string("&ndash;")) << "</td><td>"
      << (l.contains("lookupMs") ? fixed(l["lookupMs"], 1) : std::string("&ndash;")) << "</td><td>"
      << (l.contains("lookupFloorMs") ? fixed(l["lookupFloorMs"], 1) : std::string("&ndash;")) << "</td><td>"
      << (l.contains("shadowCounters") && l["shadowCounters"].contains("mapBytes") ? fixed(l["shadowCounters"]["mapBytes"].get<double>() / 1048576.0, 1)
                                                                                   : std::string("&ndash;"))
      << "</td><td>" << costBar(r, l, scale) << "</td><td>" << fixed(baseMs, 1) << "</td><td>" << fixed(lightMs, 1) << "</td><td class=\"l\">"
      << escape(r["clock"].get<std::string>())
      << "</td><td>" << percent(l["falseLit"]) << "</td><td>" << percent(l["falseShadow"]) << "</td><td>"
      << percent(l["falseLitAwayFromEdges"]) << "</td><td>" << percent(l["falseShadowAwayFromEdges"]) << "</td><td>"
      << fixed(l["meanAbsError"], 4) << "</td><td>" << fixed(l["rmse"], 4)
      << (l.value("coloured", false) ? " (r " + fixed(l["rmseRgb"][0], 4) + ", g " + fixed(l["rmseRgb"][1], 4) + ", b " + fixed(l["rmseRgb"][2], 4) + ")"
                                     : std::string())
      << "</td><td>"
      << (l.contains("leakedInUmbra") ? percent(l["leakedInUmbra"]) : std::string("&ndash;")) << "</td><td>"
      << (l.value("soft", false) && l.contains("penumbraRatio") ? fixed(l["penumbraRatio"], 2) : std::string("&ndash;")) << "</td><td>"
      << (l.contains("texelFootprintP95") ? fixed(l["texelFootprintP50"], 2) + " / " + fixed(l["texelFootprintP95"], 2) : std::string("&ndash;")) << "</td><td>"
      << (r.contains("frameOverHardMap") ? fixed(r["frameOverHardMap"], 2) : std::string("&ndash;")) << "</td><td>"
      << (onFront(records, static_cast<std::size_t>(index)) ? "&#9679;" : "") << "</td>";
    if (flips && l.contains("flips"))
        h << "<td>" << percent(l["flips"]["median"]) << "</td><td>" << percent(l["flips"]["max"]) << "</td><td>"
          << percent(l["referenceChanges"]["median"]) << "</td>";
    h << "</tr>\n";
}

// The table: one line per row and light.
void resultsTable(std::ostream& h, const json& records, bool flips) {
    double fastest = 0.0, slowest = 0.0;
    for (const json& r : records) {
        const double m = r["frameMs"]["median"].get<double>();
        if (m > 0.0 && (fastest == 0.0 || m < fastest)) fastest = m;
        slowest = std::max(slowest, m);
    }
    const double scale = slowest > 0.0 ? 160.0 / slowest : 0.0;  // the slowest frame fills the bar
    h << "<h2>Time and error</h2>\n<p class=\"legend\">Where the time goes (bar: the slowest frame is 160 px): "
         "<span class=\"c-floor\">shadow pass floor</span><span class=\"c-pass\">pass above its floor</span>"
         "<span class=\"c-lfloor\">lookup floor</span><span class=\"c-lookup\">lookups above their floor</span><span class=\"c-rest\">rest of the frame</span></p>\n"
         "<div class=\"scroll\"><table id=\"results\">\n<tr><th>#</th><th>scene</th><th>settings</th><th>light</th><th>technique</th>"
         "<th>triangles</th><th>frame ms</th><th>&times; fastest</th><th>&times; unshadowed</th><th>floor &times; unshadowed</th><th>shadow ms</th><th>shadow floor ms</th><th>lookup ms</th><th>lookup floor ms</th><th>map MiB</th><th>where the time goes</th><th>base ms</th><th>lighting ms</th><th>clock</th>"
         "<th>false lit %</th><th>false shadow %</th><th>false lit % (away from edges)</th><th>false shadow % (away from edges)</th>"
         "<th>MAE</th><th>RMSE</th><th>leak % (umbra)</th><th>penumbra &times; truth</th><th>texel footprint px (median / p95)</th><th>&times; hard map</th><th>front</th>"
      << (flips ? "<th>flips % (median)</th><th>flips % (max)</th><th>reference changed % (median)</th>" : "") << "</tr>\n";
    int index = 0;
    for (const json& r : records) {
        for (const json& l : r["lights"]) lightRow(h, records, index, l, fastest, scale, flips);
        ++index;
    }
    h << "</table></div>\n";
}

// Every row's technique, reference and error images, inlined.
void imageSections(std::ostream& h, const json& records, const fs::path& directory) {
    h << "<h2>Images</h2>\n<p class=\"legend\">Error images: <span style=\"background:#eb281e\">false lit</span>"
         "<span style=\"background:#286ef0\">false shadow</span> paler in the 1-pixel band around true shadow edges; grey: agrees.</p>\n";
    int index = 0;
    for (const json& r : records) {
        h << "<section class=\"row\"><h3>" << index << ". " << escape(r["scene"].get<std::string>()) << " &mdash; "
          << escape(settingsText(r)) << "</h3>\n";
        auto figure = [&](const std::string& file, const std::string& caption) {
            h << "<figure><img alt=\"" << escape(caption) << "\" src=\"" << dataUri(directory / file) << "\"><figcaption>"
              << escape(caption) << "</figcaption></figure>\n";
        };
        figure(r["techniqueImage"], "technique");
        figure(r["referenceImage"], "ray-traced reference");
        for (const json& l : r["lights"]) figure(l["errorImage"], "error: " + l["name"].get<std::string>());
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
    h << "<h2>Time against error</h2>\n<p>Each point is a row of the table (its number); lower left is better. "
         "Orange, and &#9679; in the table's front column: the rows on their scene's time&ndash;error front (the Pareto front), "
         "those no other row of the same scene beats in both frame time and error: for a frame-time budget, the least error "
         "is among them. Error: misclassified away from edges for hard lights, RMSE for soft ones, averaged over the lights.</p>\n"
      << scatterPlot(records);
    h << lightCountSection(records);
    imageSections(h, records, directory);
    // Lets a test (or a person) see that every image decoded.
    h << R"(<script>
window.addEventListener('load', () => {
  const images = Array.from(document.images);
  const ok = images.filter(i => i.complete && i.naturalWidth > 0).length;
  document.body.dataset.imagesLoaded = ok + '/' + images.length;
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
