#pragma once
// Bytes as base64 text (RFC 4648, with '=' padding), for data URIs: the
// bench report's images, an exported glTF's buffer.
#include <string>

namespace shadowlab {

/// `bytes` in base64.
std::string base64(const std::string& bytes);

} // namespace shadowlab
