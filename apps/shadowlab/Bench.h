#pragma once
// shadowlab bench: the library's runBench (include/shadowlab/Bench.h) with
// the command's output: a progress bar, notes on stderr, interrupts that
// stop the run, and results.json, report.html and the images written
// through a staging directory.
#include <shadowlab/Bench.h>
#include <shadowlab/Context.h>
#include <shadowlab/FileWrite.h>

#include <filesystem>

namespace shadowlab::tool {

/// bench's options and its -o.
struct BenchArgs : BenchOptions {
    std::filesystem::path output = "bench";
};

/// Runs the benchmark into args.output (a staging directory's path):
/// images/, results.json and report.html.
void runBenchInto(Context& context, const BenchArgs& args);

} // namespace shadowlab::tool
