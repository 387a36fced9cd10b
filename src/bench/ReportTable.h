#pragma once
// report.html's table of runs (ReportTable.cpp): one row per run, its
// lights folded into it.
#include <nlohmann/json.hpp>

#include <ostream>

namespace shadowlab::bench {

/// The table's rows (its heading is the page template's): a row per run
/// (scene and settings), the accuracy first; its lights' own figures in a
/// detail that opens inside the row.
void resultsRows(std::ostream& h, const nlohmann::json& records, bool flips);

} // namespace shadowlab::bench
