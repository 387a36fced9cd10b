#include "Interrupt.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>

#include <chrono>
#include <future>

#include <csignal>
#include <ctime>
#include <string>

namespace shadowlab::tool {

namespace {

volatile std::sig_atomic_t received = 0;
constexpr long long kRepeatGraceMs = 1000;

// The signals whose default ends the process without a core's worth of
// purpose for this tool, with their names for the message.
struct Named {
    int signal;
    const char* name;
};
constexpr Named kInterrupts[] = {{SIGINT, "SIGINT"},   {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"},  {SIGQUIT, "SIGQUIT"},
                                 {SIGUSR1, "SIGUSR1"}, {SIGUSR2, "SIGUSR2"}, {SIGALRM, "SIGALRM"}};

// When the first interrupt came (CLOCK_MONOTONIC; clock_gettime is
// async-signal-safe). Only the handler reads and writes it.
timespec firstInterrupt{};

extern "C" void onInterrupt(int signal) {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (received == 0) {
        firstInterrupt = now;
        received = signal;
        return;
    }
    // Repeats within a second (an impatient double Ctrl-C) wait for the run
    // to stop cleanly at its next check; a later one ends the process at once.
    const long long ms = (now.tv_sec - firstInterrupt.tv_sec) * 1000LL + (now.tv_nsec - firstInterrupt.tv_nsec) / 1000000;
    if (ms < kRepeatGraceMs) return;
    std::signal(signal, SIG_DFL);
    std::raise(signal);  // delivered, with the default action, once this handler returns
}

} // namespace

void installInterruptHandlers() {
    for (const Named& n : kInterrupts) std::signal(n.signal, onInterrupt);
}

void ignoreFileSizeSignal() { std::signal(SIGXFSZ, SIG_IGN); }

void throwIfInterrupted() {
    const int signal = received;
    if (signal == 0) return;
    const char* name = "a signal";
    for (const Named& n : kInterrupts)
        if (n.signal == signal) name = n.name;
    throw Error(std::string("interrupted (") + name + "): nothing of this run was kept");
}

void traceInterruptibly(ComparisonJob& job) {
    std::future<void> traced = std::async(std::launch::async, [&job] { job.trace(); });
    bool cancelled = false;
    while (traced.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready)
        if (!cancelled && received != 0) {
            job.cancel();
            cancelled = true;
        }
    throwIfInterrupted();  // before the trace's own "cancelled" error
    traced.get();
}

} // namespace shadowlab::tool
