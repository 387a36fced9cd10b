#pragma once
// `shadowlab view`'s options (ViewCommand.cpp; the window: Viewer.h).
#include "Viewer.h"

#include <CLI/CLI.hpp>

namespace shadowlab::tool {

/// The subcommand and its options, into `args`.
CLI::App* addView(CLI::App& app, ViewArgs& args);

} // namespace shadowlab::tool
