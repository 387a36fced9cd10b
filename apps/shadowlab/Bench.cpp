// shadowlab bench (Bench.h): the library's runBench with the command's
// progress bar, notes, interrupts and files, and the staging directory main
// writes its results through.
#include "Bench.h"
#include "Interrupt.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>
#include <shadowlab/Text.h>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace shadowlab::tool {

namespace fs = std::filesystem;

namespace {

// One line per step when stderr is not a terminal, an updating bar when it is.
class Progress {
public:
    // "bench: N runs" first, then a line or the bar each step.
    void step(std::size_t done, std::size_t total, const std::string& what) {
        if (!started_) std::fprintf(stderr, "bench: %zu run%s\n", total, total == 1 ? "" : "s");
        started_ = true;
        total_ = total;
        const int width = 30;
        const int filled = static_cast<int>(width * done / std::max<std::size_t>(total_, 1));
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.resize(width, '.');
        std::fprintf(stderr, "%s[%s] %zu/%zu %s%s", tty_ ? "\r\033[K" : "", bar.c_str(), done, total_, text::escapeControl(what).c_str(),
                     tty_ ? "" : "\n");
        if (tty_ && done == total_) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    std::size_t total_ = 0;
    bool tty_ = isatty(STDERR_FILENO) != 0;
    bool started_ = false;
};

} // namespace

void runBenchInto(Context& context, const BenchArgs& args) {
    Progress progress;
    BenchHooks hooks;
    hooks.progress = [&](std::size_t done, std::size_t total, const std::string& label) { progress.step(done, total, label); };
    hooks.checkpoint = throwIfInterrupted;
    hooks.trace = traceInterruptibly;
    hooks.note = [](const std::string& note) { std::fprintf(stderr, "shadowlab: note: %s\n", note.c_str()); };
    hooks.images = [&](std::size_t, const std::string& stem, const Comparison& c) { return writeBenchImages(args.output, stem, c); };
    const std::string results = runBench(context, args, hooks);
    throwIfInterrupted();
    writeFileAtomically(args.output / "results.json", results);
    writeBenchReport(results, args.output);
}

} // namespace shadowlab::tool
