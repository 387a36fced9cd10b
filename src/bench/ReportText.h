#pragma once
// report.html's text: HTML escaping, images inlined as data URIs, fixed
// digits, a row's settings (ReportText.cpp).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace shadowlab::bench {

/// `text` with &, <, > and " escaped for HTML.
std::string escape(const std::string& text);
/// The PNG `file` at most `width` pixels wide (averaged down), as a data:
/// URI: a JPEG at quality 85 when `photo` (a rendered frame), else a PNG
/// (an error image's flat colours). Keeps a report of many images small.
std::string thumbnailUri(const std::filesystem::path& file, int width, bool photo);
/// `v` with `digits` digits after the point.
std::string fixed(double v, int digits);
/// A share as a percentage with three digits.
std::string percent(double share);
/// A row's settings as "key=value, ..." ("defaults" for none).
std::string settingsText(const nlohmann::json& record);

} // namespace shadowlab::bench
