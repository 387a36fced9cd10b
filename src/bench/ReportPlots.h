#pragma once
// report.html's plots: their data, drawn by the page with Chart.js (ReportPlots.cpp).
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace shadowlab::bench {

/// A run's accuracy over its lights: the misclassified share away from
/// edges (hard lights' mean), false lit and false shadow (the same), and
/// the visibility RMSE (soft lights' mean); -1 where no light has it.
struct Accuracy {
    double misclassified = -1, falseLit = -1, falseShadow = -1, rmse = -1;
};
Accuracy accuracyOf(const nlohmann::json& record);

/// Whether row i is on its scene's time-error front: no other row of the
/// same scene file is at least as fast and at least as exact, and better in one.
bool onFront(const nlohmann::json& records, std::size_t i);
/// The plots' data, for the page's script (src/bench/report/page.js):
/// "plots", frame time against error a point per row with such lights
/// (id "scatter": the misclassified share of hard lights; "scatter-soft":
/// the RMSE of soft ones), each point's row, name and whether it is on its
/// scene's front; "lightCount", the rows that vary lightGrid.count as
/// series of (lights, frame median ms), a colour each.
nlohmann::json plotData(const nlohmann::json& records);
/// The light-count table's rows (each point's frame and its ratio to the
/// point with half the lights), in the series' colours; empty when no row
/// sets lightGrid.count.
std::string lightCountRows(const nlohmann::json& records);

} // namespace shadowlab::bench
