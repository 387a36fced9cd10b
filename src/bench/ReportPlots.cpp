// report.html's plots (ReportPlots.h).
#include "bench/ReportPlots.h"

#include "bench/ReportText.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

namespace shadowlab::bench {

using nlohmann::json;

namespace {

// A row's error: per light the misclassified share away from edges (hard
// lights) or the visibility RMSE (soft ones, whose truth is not two
// classes), averaged over its lights.
double errorOf(const json& record) {
    double sum = 0.0;
    for (const json& l : record["lights"])
        sum += l.value("soft", false) ? l["rmse"].get<double>() : l["falseLitAwayFromEdges"].get<double>() + l["falseShadowAwayFromEdges"].get<double>();
    return record["lights"].empty() ? 0.0 : sum / static_cast<double>(record["lights"].size());
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

const char* const kSeriesColours[] = {"#2b6cb0", "#dd6b20", "#38a169", "#805ad5", "#d53f8c", "#718096"};

// One plot's points: frame time against the rows' error (`soft` false: the
// misclassified share of hard lights, in %; true: the RMSE of soft ones,
// x 100), null when no row has such a light.
json scatterData(const json& records, bool soft) {
    json points = json::array();
    for (std::size_t i = 0; i < records.size(); ++i) {
        const json& r = records[i];
        const Accuracy a = accuracyOf(r);
        const double v = soft ? a.rmse : a.misclassified;
        if (v < 0.0) continue;
        points.push_back({{"row", i},
                          {"x", r["frameMs"]["median"].get<double>()},
                          {"y", 100.0 * v},
                          {"front", onFront(records, i)},
                          {"name", std::to_string(i) + ". " + r["scene"].get<std::string>() + " (" + settingsText(r) + ")"}});
    }
    if (points.empty()) return nullptr;
    return {{"id", soft ? "scatter-soft" : "scatter"},
            {"axis", soft ? "visibility RMSE of soft lights (%)" : "misclassified away from edges, hard lights (%)"},
            {"points", points}};
}

} // namespace

json plotData(const json& records) {
    json plots = json::array();
    for (const bool soft : {false, true})
        if (json p = scatterData(records, soft); !p.is_null()) plots.push_back(std::move(p));
    json counts = json::array();
    const std::vector<CountSeries> series = countSeries(records);
    for (std::size_t k = 0; k < series.size(); ++k) {
        json points = json::array();
        for (const auto& [n, ms] : series[k].points) points.push_back({n, ms});
        counts.push_back({{"label", series[k].label}, {"colour", kSeriesColours[k % 6]}, {"points", points}});
    }
    return {{"plots", plots}, {"lightCount", counts}};
}

std::string lightCountRows(const json& records) {
    const std::vector<CountSeries> series = countSeries(records);
    std::ostringstream s;
    for (std::size_t k = 0; k < series.size(); ++k)
        for (const auto& [n, ms] : series[k].points) {
            const auto half = std::find_if(series[k].points.begin(), series[k].points.end(), [&](const auto& p) { return 2 * p.first == n; });
            s << "<tr><td class=\"l\"><span style=\"color:" << kSeriesColours[k % 6] << "\">&#9632;</span> " << escape(series[k].label) << "</td><td>" << n
              << "</td><td>" << fixed(ms, 1) << "</td><td>"
              << (half != series[k].points.end() && half->second > 0.0 ? fixed(ms / half->second, 2) : std::string("&ndash;")) << "</td></tr>\n";
        }
    return s.str();
}

} // namespace shadowlab::bench
