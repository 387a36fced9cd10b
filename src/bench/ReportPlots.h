#pragma once
// report.html's plots, as inline SVG (ReportPlots.cpp).
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
/// Frame time against error, a point per row with such lights (the
/// front's points marked, labels placed where they overlap no other):
/// `soft` false, the misclassified share of hard lights (id "scatter");
/// true, the RMSE of soft lights (id "scatter-soft"). Empty when no row
/// has such a light.
std::string scatterPlot(const nlohmann::json& records, bool soft);
/// The frame time against the number of lights, a line per technique,
/// with its table (empty when the rows do not vary the lights).
std::string lightCountSection(const nlohmann::json& records);

} // namespace shadowlab::bench
