#pragma once
// `shadowlab bench`: its options, and the run staged beside the output
// (BenchCommand.cpp; the run itself: Bench.h).
#include "Bench.h"

#include <CLI/CLI.hpp>

#include <string>

namespace shadowlab::tool {

/// The subcommand and its options, into `args`; -o into `output`, checked
/// in main before it becomes args.output.
CLI::App* addBench(CLI::App& app, BenchArgs& args, std::string& output);
/// Benches into a staging directory moved into place once the whole run
/// succeeded; 0 (an error throws).
int runBenchCommand(const BenchArgs& args);

} // namespace shadowlab::tool
