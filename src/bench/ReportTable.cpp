// report.html's table of runs (ReportTable.h). Times are clocked apart and
// their differences (a pass above its floor, the lookups) can come out
// below 0 or a floor above its pass on a busy machine: the table shows
// them clamped to 0 and to their pass, and says so.
#include "bench/ReportTable.h"

#include "bench/ReportPlots.h"
#include "bench/ReportText.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace shadowlab::bench {

using nlohmann::json;

namespace {

// A time difference shown as a time: at least 0.
double nonNegative(const json& v) { return v.is_number() ? std::max(v.get<double>(), 0.0) : 0.0; }

// A run's time by part, its lights' summed, each clamped: the shadow
// passes and their floors (a bare depth draw of the same casters), the
// lookups and their floors (one nearest fetch a pixel).
struct Costs {
    double pass = 0, floor = 0, lookup = 0, lookupFloor = 0, mapMiB = 0;
    bool hasFloor = false, hasLookup = false, hasLookupFloor = false, hasMap = false;
};

Costs costsOf(const json& r) {
    Costs c;
    for (const json& l : r["lights"]) {
        const double pass = nonNegative(l.value("shadowPassMs", json(0.0))), lookup = nonNegative(l.value("lookupMs", json(0.0)));
        c.pass += pass;
        c.floor += std::min(nonNegative(l.value("shadowFloorMs", json(0.0))), pass);
        c.lookup += lookup;
        c.lookupFloor += std::min(nonNegative(l.value("lookupFloorMs", json(0.0))), lookup);
        c.hasFloor |= l.contains("shadowFloorMs");
        c.hasLookup |= l.contains("lookupMs");
        c.hasLookupFloor |= l.contains("lookupFloorMs");
        if (l.contains("shadowCounters") && l["shadowCounters"].contains("mapBytes")) {
            c.mapMiB += l["shadowCounters"]["mapBytes"].get<double>() / 1048576.0;
            c.hasMap = true;
        }
    }
    return c;
}

// Where a run's frame goes, as a bar `scale` px per ms: the shadow passes'
// floor, the passes above it, the lookups' floor, the lookups above it,
// and the rest of the frame (what is left, at least 0).
std::string costBar(const json& r, const Costs& c, double scale) {
    const double frame = r["frameMs"]["median"].get<double>(), rest = std::max(frame - c.pass - c.lookup, 0.0);
    std::ostringstream s;
    s << "<div class=\"cost\" title=\"shadow pass floor " << fixed(c.floor, 1) << " ms, pass above its floor " << fixed(c.pass - c.floor, 1)
      << " ms, lookup floor " << fixed(c.lookupFloor, 1) << " ms, lookups above their floor " << fixed(c.lookup - c.lookupFloor, 1)
      << " ms, rest of the frame " << fixed(rest, 1) << " ms\">";
    const std::pair<const char*, double> parts[] = {{"c-floor", c.floor}, {"c-pass", c.pass - c.floor}, {"c-lfloor", c.lookupFloor},
                                                    {"c-lookup", c.lookup - c.lookupFloor}, {"c-rest", rest}};
    for (const auto& [cls, ms] : parts) s << "<span class=\"" << cls << "\" style=\"width:" << fixed(ms * scale, 1) << "px\"></span>";
    s << "</div>";
    return s.str();
}

std::string shareOrDash(double share) { return share < 0.0 ? std::string("&ndash;") : percent(share); }
std::string msOrDash(bool has, double ms) { return has ? fixed(ms, 1) : std::string("&ndash;"); }

// The run's techniques, each once, in light order.
std::string techniquesOf(const json& r) {
    std::string out;
    std::set<std::string> seen;
    for (const json& l : r["lights"])
        if (seen.insert(l["technique"].get<std::string>()).second) out += (out.empty() ? "" : ", ") + l["technique"].get<std::string>();
    return out;
}

// One light of a run, one line of its detail.
std::string lightLine(const json& l, bool flips) {
    std::ostringstream s;
    s << "<li><b>" << escape(l["name"].get<std::string>()) << "</b> (" << escape(l["type"].get<std::string>()) << (l.value("soft", false) ? ", soft" : "")
      << ", " << escape(l["technique"].get<std::string>()) << "): false lit " << percent(l["falseLit"]) << " % (" << percent(l["falseLitAwayFromEdges"])
      << " % away from edges), false shadow " << percent(l["falseShadow"]) << " % (" << percent(l["falseShadowAwayFromEdges"])
      << " %), MAE " << fixed(l["meanAbsError"], 4) << ", RMSE " << fixed(l["rmse"], 4);
    if (l.value("coloured", false)) s << " (r " << fixed(l["rmseRgb"][0], 4) << ", g " << fixed(l["rmseRgb"][1], 4) << ", b " << fixed(l["rmseRgb"][2], 4) << ")";
    if (l.contains("leakedInUmbra")) s << ", leak (umbra) " << percent(l["leakedInUmbra"]) << " %";
    if (l.value("soft", false) && l.contains("penumbraRatio")) s << ", penumbra &times; truth " << fixed(l["penumbraRatio"], 2);
    if (l.contains("texelFootprintP95"))
        s << ", texel footprint px (median / p95) " << fixed(l["texelFootprintP50"], 2) << " / " << fixed(l["texelFootprintP95"], 2);
    const double pass = nonNegative(l.value("shadowPassMs", json(0.0)));
    s << "; shadow pass " << fixed(pass, 1) << " ms";
    if (l.contains("shadowFloorMs")) s << " (floor " << fixed(std::min(nonNegative(l["shadowFloorMs"]), pass), 1) << ")";
    if (l.contains("lookupMs")) {
        const double lookup = nonNegative(l["lookupMs"]);
        s << ", lookups " << fixed(lookup, 1) << " ms";
        if (l.contains("lookupFloorMs")) s << " (floor " << fixed(std::min(nonNegative(l["lookupFloorMs"]), lookup), 1) << ")";
    }
    if (l.contains("shadowCounters") && l["shadowCounters"].contains("mapBytes"))
        s << ", map " << fixed(l["shadowCounters"]["mapBytes"].get<double>() / 1048576.0, 1) << " MiB";
    if (flips && l.contains("flips"))
        s << "; flips " << percent(l["flips"]["median"]) << " % median, " << percent(l["flips"]["max"]) << " % max (reference changed "
          << percent(l["referenceChanges"]["median"]) << " %)";
    s << "</li>";
    return s.str();
}

// The fastest median frame of each scene file: "x fastest" compares runs of one scene.
std::map<std::string, double> fastestByScene(const json& records) {
    std::map<std::string, double> fastest;
    for (const json& r : records) {
        const double m = r["frameMs"]["median"].get<double>();
        const std::string scene = r["sceneFile"].get<std::string>();
        if (m > 0.0 && (!fastest.count(scene) || m < fastest[scene])) fastest[scene] = m;
    }
    return fastest;
}

void runRow(std::ostream& h, const json& records, std::size_t index, double fastest, double scale, bool flips) {
    const json& r = records[index];
    const Costs c = costsOf(r);
    const Accuracy a = accuracyOf(r);
    const json& g = r["frameMs"];
    h << "<tr><td>" << index << "</td><td class=\"l\">" << escape(r["scene"].get<std::string>()) << "</td><td class=\"l\">" << escape(settingsText(r))
      << "</td><td class=\"l\">" << escape(techniquesOf(r)) << "</td><td>" << shareOrDash(a.misclassified) << "</td><td>" << shareOrDash(a.falseLit)
      << "</td><td>" << shareOrDash(a.falseShadow) << "</td><td>" << (a.rmse < 0.0 ? std::string("&ndash;") : fixed(a.rmse, 4)) << "</td><td>"
      << fixed(g["median"], 1) << " (" << fixed(g["min"], 1) << "&ndash;" << fixed(g["max"], 1) << ")</td><td>"
      << (fastest > 0.0 ? fixed(g["median"].get<double>() / fastest, 2) : std::string("&ndash;")) << "</td><td>"
      << (r.contains("frameOverUnshadowed") ? fixed(r["frameOverUnshadowed"], 2) : std::string("&ndash;")) << "</td><td>" << costBar(r, c, scale)
      << "</td><td>" << fixed(c.pass, 1) << "</td><td>" << msOrDash(c.hasFloor, c.floor) << "</td><td>" << msOrDash(c.hasLookup, c.lookup) << "</td><td>"
      << msOrDash(c.hasLookupFloor, c.lookupFloor) << "</td><td>" << msOrDash(c.hasMap, c.mapMiB) << "</td><td>"
      << (onFront(records, index) ? "&#9679;" : "") << "</td><td class=\"l\"><details><summary>" << r["lights"].size()
      << (r["lights"].size() == 1 ? " light" : " lights") << "</summary><ul class=\"lights\">";
    for (const json& l : r["lights"]) h << lightLine(l, flips);
    h << "</ul><p>" << r["triangles"] << " triangles; floor &times; unshadowed "
      << (r.contains("floorFrameOverUnshadowed") ? fixed(r["floorFrameOverUnshadowed"], 2) : std::string("&ndash;")) << "; &times; hard map "
      << (r.contains("frameOverHardMap") ? fixed(r["frameOverHardMap"], 2) : std::string("&ndash;")) << "; clock " << escape(r["clock"].get<std::string>())
      << "</p></details></td></tr>\n";
}

} // namespace

void resultsRows(std::ostream& h, const json& records, bool flips) {
    double slowest = 0.0;
    for (const json& r : records) slowest = std::max(slowest, r["frameMs"]["median"].get<double>());
    const double scale = slowest > 0.0 ? 160.0 / slowest : 0.0;  // the slowest frame fills the bar
    const std::map<std::string, double> fastest = fastestByScene(records);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const auto it = fastest.find(records[i]["sceneFile"].get<std::string>());
        runRow(h, records, i, it == fastest.end() ? 0.0 : it->second, scale, flips);
    }
}

} // namespace shadowlab::bench
