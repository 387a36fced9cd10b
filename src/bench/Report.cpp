// report.html: one self-contained page (images inlined as data URIs, plot as
// inline SVG, no scripts from elsewhere) that opens from disk.
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

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                           static_cast<unsigned char>(bytes[i + 2]);
        out += table[v >> 18 & 63];
        out += table[v >> 12 & 63];
        out += table[v >> 6 & 63];
        out += table[v & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += table[v >> 18 & 63];
        out += table[v >> 12 & 63];
        out += i + 1 < bytes.size() ? table[v >> 6 & 63] : '=';
        out += '=';
    }
    return out;
}

std::string dataUri(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot read image for the report");
    std::stringstream s;
    s << in.rdbuf();
    return "data:image/png;base64," + base64(s.str());
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

std::string percent(double share) { return fixed(100.0 * share, 3); }

std::string settingsText(const json& record) {
    std::string out;
    for (const auto& [key, value] : record["settings"].items()) out += (out.empty() ? "" : ", ") + key + "=" + value.get<std::string>();
    return out.empty() ? "defaults" : out;
}

// Misclassified share away from edges, mean over lights: the plot's y.
// A row's error: per light the misclassified share away from edges (hard
// lights) or the visibility RMSE (soft ones, whose truth is not two
// classes), averaged over its lights.
double errorOf(const json& record) {
    double sum = 0.0;
    for (const json& l : record["lights"])
        sum += l.value("soft", false) ? l["rmse"].get<double>() : l["falseLitAwayFromEdges"].get<double>() + l["falseShadowAwayFromEdges"].get<double>();
    return record["lights"].empty() ? 0.0 : sum / static_cast<double>(record["lights"].size());
}

// Whether row i is on its scene's time-error front: no other row of the
// same scene file is at least as fast and at least as exact, and better in one.
bool onFront(const json& records, std::size_t i) {
    const json& r = records[i];
    const double t = r["frameMs"]["median"].get<double>(), e = errorOf(r);
    for (std::size_t j = 0; j < records.size(); ++j) {
        const json& o = records[j];
        if (j == i || o["sceneFile"] != r["sceneFile"]) continue;
        const double ot = o["frameMs"]["median"].get<double>(), oe = errorOf(o);
        if (ot <= t && oe <= e && (ot < t || oe < e)) return false;
    }
    return true;
}

double niceStep(double range) {
    const double raw = range / 5.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * p) return m * p;
    return 10.0 * p;
}

std::string scatterPlot(const json& records) {
    const double W = 640, H = 360, left = 70, right = 20, top = 20, bottom = 50;
    double maxX = 0, maxY = 0;
    for (const json& r : records) {
        maxX = std::max(maxX, r["frameMs"]["median"].get<double>());
        maxY = std::max(maxY, 100.0 * errorOf(r));
    }
    const double stepX = niceStep(std::max(maxX, 1e-3)), stepY = niceStep(std::max(maxY, 1e-3));
    maxX = std::ceil(std::max(maxX, 1e-3) / stepX) * stepX;
    maxY = std::ceil(std::max(maxY, 1e-3) / stepY) * stepY;
    auto px = [&](double x) { return left + (W - left - right) * x / maxX; };
    auto py = [&](double y) { return H - bottom - (H - top - bottom) * y / maxY; };
    std::ostringstream s;
    s << "<svg id=\"scatter\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" role=\"img\" aria-label=\"frame time against misclassified pixels\">\n";
    s << "<rect x=\"0\" y=\"0\" width=\"" << W << "\" height=\"" << H << "\" fill=\"#fff\"/>\n";
    for (double x = 0; x <= maxX + 1e-9; x += stepX) {
        s << "<line x1=\"" << px(x) << "\" y1=\"" << top << "\" x2=\"" << px(x) << "\" y2=\"" << H - bottom
          << "\" stroke=\"#e4e4e4\"/><text x=\"" << px(x) << "\" y=\"" << H - bottom + 16
          << "\" text-anchor=\"middle\" font-size=\"11\">" << fixed(x, stepX < 1 ? 2 : 0) << "</text>\n";
    }
    for (double y = 0; y <= maxY + 1e-9; y += stepY) {
        s << "<line x1=\"" << left << "\" y1=\"" << py(y) << "\" x2=\"" << W - right << "\" y2=\"" << py(y)
          << "\" stroke=\"#e4e4e4\"/><text x=\"" << left - 6 << "\" y=\"" << py(y) + 4
          << "\" text-anchor=\"end\" font-size=\"11\">" << fixed(y, stepY < 1 ? 2 : 0) << "</text>\n";
    }
    s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12
      << "\" text-anchor=\"middle\" font-size=\"12\">frame time, median (ms)</text>\n";
    s << "<text transform=\"translate(16," << (top + H - bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">misclassified away from edges, or RMSE (%)</text>\n";
    int index = 0;
    for (const json& r : records) {
        const double x = px(r["frameMs"]["median"].get<double>()), y = py(100.0 * errorOf(r));
        const bool front = onFront(records, static_cast<std::size_t>(index));
        s << "<g class=\"point" << (front ? " front" : "") << "\"><circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" fill=\""
          << (front ? "#dd6b20" : "#2b6cb0") << "\" fill-opacity=\"0.75\"><title>"
          << escape(r["scene"].get<std::string>() + " (" + settingsText(r) + ")") << "</title></circle><text x=\"" << x + 7
          << "\" y=\"" << y - 6 << "\" font-size=\"10\">" << index << "</text></g>\n";
        ++index;
    }
    s << "</svg>\n";
    return s.str();
}

// Rows that vary the generated light count (lightGrid.count), grouped by
// their other settings: frame time against the count (issue: each doubling
// of lights at most so much more frame). Empty when no row sets it.
struct CountSeries {
    std::string label;                          ///< the other settings
    std::vector<std::pair<int, double>> points; ///< (lights, frame median ms), by count
};

std::vector<CountSeries> countSeries(const json& records) {
    std::vector<CountSeries> out;
    for (const json& r : records) {
        if (!r["settings"].contains("lightGrid.count")) continue;
        int count = 0;
        try {
            count = std::stoi(r["settings"]["lightGrid.count"].get<std::string>());
        } catch (const std::exception&) {
            continue;
        }
        std::string label = r["scene"].get<std::string>();
        for (const auto& [key, value] : r["settings"].items())
            if (key != "lightGrid.count") label += ", " + key + "=" + value.get<std::string>();
        auto it = std::find_if(out.begin(), out.end(), [&](const CountSeries& c) { return c.label == label; });
        if (it == out.end()) it = out.insert(out.end(), CountSeries{label, {}});
        it->points.emplace_back(count, r["frameMs"]["median"].get<double>());
    }
    for (CountSeries& c : out) std::sort(c.points.begin(), c.points.end());
    return out;
}

// Frame time against the light count, the count on a log2 axis, one line
// per series, and under it each series' points with the ratio to the
// point at half the count.
std::string lightCountSection(const json& records) {
    const std::vector<CountSeries> series = countSeries(records);
    if (series.empty()) return {};
    const double W = 640, H = 360, left = 70, right = 20, top = 20, bottom = 50;
    int maxCount = 1;
    double maxY = 0;
    for (const CountSeries& c : series)
        for (const auto& [n, ms] : c.points) {
            maxCount = std::max(maxCount, n);
            maxY = std::max(maxY, ms);
        }
    const double maxX = std::max(1.0, std::ceil(std::log2(static_cast<double>(maxCount))));
    const double stepY = niceStep(std::max(maxY, 1e-3));
    maxY = std::ceil(std::max(maxY, 1e-3) / stepY) * stepY;
    auto px = [&](int n) { return left + (W - left - right) * std::log2(static_cast<double>(std::max(n, 1))) / maxX; };
    auto py = [&](double y) { return H - bottom - (H - top - bottom) * y / maxY; };
    static const char* colours[] = {"#2b6cb0", "#dd6b20", "#38a169", "#805ad5", "#d53f8c", "#718096"};
    std::ostringstream s;
    s << "<h2>Frame time against the number of lights</h2>\n<p>The rows that set <code>lightGrid.count</code>, one line per "
         "setting of the rest; the count on a log<sub>2</sub> axis. Under the plot: each point's frame and its ratio to the "
         "point with half as many lights.</p>\n";
    s << "<svg id=\"lightcount\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" role=\"img\" aria-label=\"frame time against the number of lights\">\n";
    s << "<rect x=\"0\" y=\"0\" width=\"" << W << "\" height=\"" << H << "\" fill=\"#fff\"/>\n";
    for (int k = 0; k <= static_cast<int>(maxX); ++k)
        s << "<line x1=\"" << px(1 << k) << "\" y1=\"" << top << "\" x2=\"" << px(1 << k) << "\" y2=\"" << H - bottom
          << "\" stroke=\"#e4e4e4\"/><text x=\"" << px(1 << k) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\" font-size=\"11\">"
          << (1 << k) << "</text>\n";
    for (double y = 0; y <= maxY + 1e-9; y += stepY)
        s << "<line x1=\"" << left << "\" y1=\"" << py(y) << "\" x2=\"" << W - right << "\" y2=\"" << py(y)
          << "\" stroke=\"#e4e4e4\"/><text x=\"" << left - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\" font-size=\"11\">"
          << fixed(y, stepY < 1 ? 2 : 0) << "</text>\n";
    s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\" font-size=\"12\">lights (lightGrid.count)</text>\n";
    s << "<text transform=\"translate(16," << (top + H - bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">frame time, median (ms)</text>\n";
    for (std::size_t k = 0; k < series.size(); ++k) {
        const char* colour = colours[k % 6];
        s << "<g class=\"series\"><title>" << escape(series[k].label) << "</title><polyline fill=\"none\" stroke=\"" << colour
          << "\" stroke-width=\"2\" points=\"";
        for (const auto& [n, ms] : series[k].points) s << px(n) << "," << py(ms) << " ";
        s << "\"/>";
        for (const auto& [n, ms] : series[k].points) s << "<circle cx=\"" << px(n) << "\" cy=\"" << py(ms) << "\" r=\"3.5\" fill=\"" << colour << "\"/>";
        s << "</g>\n";
    }
    s << "</svg>\n<table><tr><th>series</th><th>lights</th><th>frame (ms)</th><th>&times; half as many</th></tr>\n";
    for (std::size_t k = 0; k < series.size(); ++k)
        for (const auto& [n, ms] : series[k].points) {
            const auto half = std::find_if(series[k].points.begin(), series[k].points.end(), [&](const auto& p) { return 2 * p.first == n; });
            s << "<tr><td class=\"l\"><span style=\"color:" << colours[k % 6] << "\">&#9632;</span> " << escape(series[k].label) << "</td><td>" << n
              << "</td><td>" << fixed(ms, 1) << "</td><td>"
              << (half != series[k].points.end() && half->second > 0.0 ? fixed(ms / half->second, 2) : std::string("&ndash;")) << "</td></tr>\n";
        }
    s << "</table>\n";
    return s.str();
}

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
