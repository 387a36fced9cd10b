#pragma once
// shadowlab bench: the library's runBench (include/shadowlab/Bench.h) with
// the command's output: a progress bar, notes on stderr, interrupts that
// stop the run, and results.json, report.html and the images written
// through a staging directory.
#include <shadowlab/Bench.h>
#include <shadowlab/Context.h>

#include <filesystem>

namespace shadowlab::tool {

/// bench's options and its -o.
struct BenchArgs : BenchOptions {
    std::filesystem::path output = "bench";
};

/// A directory beside `target` (`target.partial-PID`) that bench writes into;
/// commit() moves its content into `target` (created if missing, same-named
/// entries replaced). Destroyed without commit(), it is removed with its content.
class StagingDirectory {
public:
    explicit StagingDirectory(std::filesystem::path target);
    ~StagingDirectory();
    StagingDirectory(const StagingDirectory&) = delete;
    StagingDirectory& operator=(const StagingDirectory&) = delete;
    const std::filesystem::path& path() const { return staging_; }
    void commit();

private:
    std::filesystem::path target_, staging_;
    bool committed_ = false;
};

/// Runs the benchmark into args.output (a staging directory's path):
/// images/, results.json and report.html.
void runBenchInto(Context& context, const BenchArgs& args);

} // namespace shadowlab::tool
