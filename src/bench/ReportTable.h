#pragma once
// report.html's table of runs (ReportTable.cpp): one row per run, its
// lights folded into it.
#include <nlohmann/json.hpp>

#include <ostream>

namespace shadowlab::bench {

/// The table: a row per run (scene and settings), the accuracy first; its
/// lights' own figures in a detail that opens inside the row.
void resultsTable(std::ostream& h, const nlohmann::json& records, bool flips);

} // namespace shadowlab::bench
