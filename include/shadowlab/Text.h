#pragma once
/// @file Text.h
/// Checks and escaping for text that comes from users and files: every quoted
/// user string goes through escapeControl() so an error stays one line, and
/// JSON is depth-checked before it reaches a recursive parser.
#include <shadowlab/Export.h>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::text {

/// JSON nesting deeper than this is refused before parsing: nlohmann::json
/// copies and tinygltf's conversion recurse once per level, and scene
/// `children` nest two levels per hierarchy level (object, array), so this
/// allows 100 levels of node hierarchy while keeping the recursion shallow.
constexpr std::size_t kMaxJsonDepth = 200;

/// `s` with control characters (bytes < 0x20 and 0x7f) written as \n, \r,
/// \t, \v, \f or \xNN, and bytes that are not valid UTF-8 as \xNN. Other
/// text, backslashes included, is unchanged, so escaping twice changes nothing.
SHADOWLAB_API std::string escapeControl(std::string_view s);

/// `v` as messages and docs write it: the shortest of six significant
/// digits (`2048`, `0.5`, `1e+300`), as std::ostream prints it.
SHADOWLAB_API std::string numberText(double v);

/// `s` when it is at most `limit` bytes; else its first and last parts
/// around `... (N bytes cut) ...`, cut at UTF-8 character boundaries, so a
/// message that quotes a huge value stays short and keeps its end (where
/// the reason is).
SHADOWLAB_API std::string clipMiddle(std::string_view s, std::size_t limit = 600);

/// Byte offset of the first byte that is not part of valid UTF-8 (overlong
/// forms, surrogates and code points past U+10FFFF are invalid), or npos.
SHADOWLAB_API std::size_t invalidUtf8At(std::string_view s);

/// The comma-separated names in `list`, each without surrounding blanks;
/// empty entries dropped (an option's list of node names).
SHADOWLAB_API std::vector<std::string> splitNames(const std::string& list);

/// Deepest nesting of [ and { in JSON text, outside strings. Stops counting
/// at `limit` + 1, so a hostile file is scanned once and never more.
SHADOWLAB_API std::size_t jsonDepth(std::string_view json, std::size_t limit = kMaxJsonDepth);

} // namespace shadowlab::text
