// report.html: one self-contained page that opens from disk: the template
// src/bench/report/page.html filled with the results (the table's rows,
// images inlined as data URIs) and the plots' data, drawn by its script
// with Chart.js, both inlined (bench/ReportAssets.h).
#include "bench/ReportAssets.h"
#include "bench/ReportPlots.h"
#include "bench/ReportTable.h"
#include "bench/ReportText.h"

#include <shadowlab/Bench.h>
#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

namespace shadowlab::bench {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The first paragraph's run parameters (the template adds what the
// accuracy is measured against).
std::string introduction(const json& results) {
    const json& records = results["results"];
    std::ostringstream h;
    h << escape(results["renderer"].get<std::string>()) << ", OpenGL " << escape(results["glVersion"].get<std::string>())
      << ". " << results["width"] << "&times;" << results["height"] << " pixels, " << results["frames"] << " timed frames after "
      << results["warmup"] << " warm-up frames per row; animated lights at " << results.value("time", 0.0) << " s + k / "
      << results.value("fps", 30.0) << " fps in timed frame k, at " << results.value("time", 0.0)
      << " s in the warm-up and the accuracy comparison. Frame: wall time of a finished frame as users get it; passes: "
      << escape(records.empty() ? std::string("-") : records[0]["clock"].get<std::string>())
      << " clock (cpu-finish: glFinish around each pass on a software rasteriser; gpu-timestamp: GL_TIMESTAMP queries); "
         "medians, min&ndash;max in brackets.";
    if (const int rounds = results.value("rounds", 1); rounds > 1)
        h << " Timed in " << rounds << " interleaved rounds, the rows in turn in each; every row shows its fastest round (lowest median frame), whole.";
    if (results.value("flips", false))
        h << " Flips: each timed frame compared with the reference; the share of receiver pixels whose shadow changes between "
             "consecutive frames at the same world point while the truth there does not (docs/metrics.md), median and maximum "
             "over the pairs of frames, beside the share whose reference changed on screen (true motion).";
    return h.str();
}

// The template with each marker replaced by its text, in one pass: a text
// put in (a scene's name, Chart.js) is never searched for markers.
std::string filled(std::string_view page, std::vector<std::pair<std::string_view, std::string>> markers) {
    std::vector<std::pair<std::size_t, std::size_t>> at;  // (where in the page, which marker)
    for (std::size_t k = 0; k < markers.size(); ++k) {
        const std::size_t where = page.find(markers[k].first);
        if (where == std::string_view::npos || page.find(markers[k].first, where + 1) != std::string_view::npos)
            throw Error("bench report: the page template (src/bench/report/page.html) has not exactly one " + std::string(markers[k].first));
        at.emplace_back(where, k);
    }
    std::sort(at.begin(), at.end());
    std::string out;
    std::size_t from = 0;
    for (const auto& [where, k] : at) {
        out.append(page.substr(from, where - from)).append(markers[k].second);
        from = where + markers[k].first.size();
    }
    return out.append(page.substr(from));
}

std::string_view asset(std::string_view file) {
    const std::optional<std::string_view> text = reportAsset(file);
    if (!text) throw Error("bench report: " + std::string(file) + " is not embedded in the library (src/CMakeLists.txt)");
    return *text;
}

// JSON to sit inside a <script> element: no '<', so no "</script>" or "<!--".
std::string scriptJson(const json& value) {
    std::string text = value.dump();
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        if (c == '<') out += "\\u003c";
        else out += c;
    }
    return out;
}

// The images' width in the page, pixels (figure img's CSS width): they are
// inlined at that size, the rendered frames as JPEG.
constexpr int kThumbnailWidth = 320;

// Every row's technique, reference and error images, inlined.
void imageSections(std::ostream& h, const json& records, const fs::path& directory) {
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
    std::ostringstream rows, images;
    resultsRows(rows, records, results.value("flips", false));
    imageSections(images, records, directory);
    const std::string page = filled(asset("page.html"), {{"<!--@introduction-->", introduction(results)},
                                                         {"<!--@rows-->", rows.str()},
                                                         {"<!--@lightcount-rows-->", lightCountRows(records)},
                                                         {"<!--@images-->", images.str()},
                                                         {"/*@data*/", scriptJson(plotData(records))},
                                                         {"/*@chart.js*/", std::string(asset("chart.min.js"))},
                                                         {"/*@page.js*/", std::string(asset("page.js"))}});
    writeFileAtomically(directory / "report.html", page);
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
