// report.html's plots (ReportPlots.h).
#include "bench/ReportPlots.h"

#include "bench/ReportText.h"

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

namespace shadowlab::bench {

using nlohmann::json;

namespace {

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

// Digits after the point that tell an axis's ticks `step` apart.
int digitsFor(double step) { return std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 6); }

double niceStep(double range) {
    const double raw = range / 5.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * p) return m * p;
    return 10.0 * p;
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

} // namespace

Accuracy accuracyOf(const json& r) {
    Accuracy a;
    double lit = 0, shadow = 0, rmse = 0;
    int hard = 0, soft = 0;
    for (const json& l : r["lights"]) {
        if (l.value("soft", false)) {
            rmse += l["rmse"].get<double>();
            ++soft;
        } else {
            lit += l["falseLitAwayFromEdges"].get<double>();
            shadow += l["falseShadowAwayFromEdges"].get<double>();
            ++hard;
        }
    }
    if (hard > 0) {
        a.falseLit = lit / hard;
        a.falseShadow = shadow / hard;
        a.misclassified = a.falseLit + a.falseShadow;
    }
    if (soft > 0) a.rmse = rmse / soft;
    return a;
}

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

namespace {

// A point's label, `width` x 10 px, at the first of four places around the
// point (right above, left above, right below, left below) that overlaps
// no label placed before; none when all four do (the point's tooltip still names it).
std::optional<std::pair<double, double>> labelPlace(double x, double y, double width, std::vector<std::array<double, 4>>& placed) {
    const std::pair<double, double> offsets[] = {{7, -6}, {-7 - width, -6}, {7, 14}, {-7 - width, 14}};
    for (const auto& [dx, dy] : offsets) {
        const std::array<double, 4> box{x + dx, y + dy - 10, x + dx + width, y + dy};
        const bool free = std::none_of(placed.begin(), placed.end(), [&](const std::array<double, 4>& o) {
            return box[0] < o[2] && o[0] < box[2] && box[1] < o[3] && o[1] < box[3];
        });
        if (free) {
            placed.push_back(box);
            return std::make_pair(x + dx, y + dy);
        }
    }
    return std::nullopt;
}

} // namespace

std::string scatterPlot(const json& records, bool soft) {
    const auto value = [&](const json& r) {
        const Accuracy a = accuracyOf(r);
        return 100.0 * (soft ? a.rmse : a.misclassified);
    };
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < records.size(); ++i)
        if (value(records[i]) >= 0.0) rows.push_back(i);
    if (rows.empty()) return {};
    const double W = 640, H = 360, left = 70, right = 20, top = 20, bottom = 50;
    double maxX = 0, maxY = 0;
    for (std::size_t i : rows) {
        maxX = std::max(maxX, records[i]["frameMs"]["median"].get<double>());
        maxY = std::max(maxY, value(records[i]));
    }
    const double stepX = niceStep(std::max(maxX, 1e-3)), stepY = niceStep(std::max(maxY, 1e-3));
    maxX = std::ceil(std::max(maxX, 1e-3) / stepX) * stepX;
    maxY = std::ceil(std::max(maxY, 1e-3) / stepY) * stepY;
    auto px = [&](double x) { return left + (W - left - right) * x / maxX; };
    auto py = [&](double y) { return H - bottom - (H - top - bottom) * y / maxY; };
    const std::string what = soft ? "visibility RMSE of soft lights (%)" : "misclassified away from edges, hard lights (%)";
    std::ostringstream s;
    s << "<svg id=\"" << (soft ? "scatter-soft" : "scatter") << "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" role=\"img\" aria-label=\"frame time against " << what << "\">\n";
    s << "<rect x=\"0\" y=\"0\" width=\"" << W << "\" height=\"" << H << "\" fill=\"#fff\"/>\n";
    for (double x = 0; x <= maxX + 1e-9; x += stepX)
        s << "<line x1=\"" << px(x) << "\" y1=\"" << top << "\" x2=\"" << px(x) << "\" y2=\"" << H - bottom << "\" stroke=\"#e4e4e4\"/><text x=\"" << px(x)
          << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\" font-size=\"11\">" << fixed(x, digitsFor(stepX)) << "</text>\n";
    for (double y = 0; y <= maxY + 1e-9; y += stepY)
        s << "<line x1=\"" << left << "\" y1=\"" << py(y) << "\" x2=\"" << W - right << "\" y2=\"" << py(y) << "\" stroke=\"#e4e4e4\"/><text x=\"" << left - 6
          << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\" font-size=\"11\">" << fixed(y, digitsFor(stepY)) << "</text>\n";
    s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\" font-size=\"12\">frame time, median (ms)</text>\n";
    s << "<text transform=\"translate(16," << (top + H - bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">" << what << "</text>\n";
    std::vector<std::array<double, 4>> placed;
    for (std::size_t i : rows) {
        const double x = px(records[i]["frameMs"]["median"].get<double>()), y = py(value(records[i]));
        placed.push_back({x - 5, y - 5, x + 5, y + 5});  // labels keep off the points too
    }
    for (std::size_t i : rows) {
        const json& r = records[i];
        const double x = px(r["frameMs"]["median"].get<double>()), y = py(value(r));
        const bool front = onFront(records, i);
        s << "<g class=\"point" << (front ? " front" : "") << "\"><circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" fill=\""
          << (front ? "#dd6b20" : "#2b6cb0") << "\" fill-opacity=\"0.75\"><title>" << i << ". "
          << escape(r["scene"].get<std::string>() + " (" + settingsText(r) + ")") << "</title></circle>";
        const std::string label = std::to_string(i);
        if (const auto at = labelPlace(x, y, 6.5 * static_cast<double>(label.size()), placed))
            s << "<text x=\"" << at->first << "\" y=\"" << at->second << "\" font-size=\"10\">" << label << "</text>";
        s << "</g>\n";
    }
    s << "</svg>\n";
    return s.str();
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
          << fixed(y, digitsFor(stepY)) << "</text>\n";
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

} // namespace shadowlab::bench
