#pragma once
// report.html's plots, as inline SVG (ReportPlots.cpp).
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace shadowlab::bench {

/// Whether row i is on its scene's time-error front: no other row of the
/// same scene file is at least as fast and at least as exact, and better in one.
bool onFront(const nlohmann::json& records, std::size_t i);
/// Frame time against error, a point per row (the front's points marked).
std::string scatterPlot(const nlohmann::json& records);
/// The frame time against the number of lights, a line per technique,
/// with its table (empty when the rows do not vary the lights).
std::string lightCountSection(const nlohmann::json& records);

} // namespace shadowlab::bench
