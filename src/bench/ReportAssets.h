#pragma once
// The report page's files, embedded at build time (cmake/EmbedText.cmake,
// src/CMakeLists.txt): "page.html" (the template, src/bench/report/),
// "page.js" (its script) and "chart.min.js" (Chart.js from Debian's
// libjs-chart.js), so the installed tool writes a report that opens from
// disk with no network.
#include <optional>
#include <string_view>

namespace shadowlab::bench {

/// The text of the embedded `file`, or nothing for a name not embedded.
std::optional<std::string_view> reportAsset(std::string_view file);

} // namespace shadowlab::bench
