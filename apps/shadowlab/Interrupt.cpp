#include "Interrupt.h"

#include <shadowlab/Error.h>

#include <csignal>
#include <string>

namespace shadowlab::tool {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void onInterrupt(int signal) {
    received = signal;
    std::signal(signal, SIG_DFL);  // a second one ends the process
}

} // namespace

void installInterruptHandlers() {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, onInterrupt);
}

void ignoreFileSizeSignal() { std::signal(SIGXFSZ, SIG_IGN); }

void throwIfInterrupted() {
    const int signal = received;
    if (signal == 0) return;
    const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "a signal";
    throw Error(std::string("interrupted (") + name + "): nothing of this run was kept");
}

} // namespace shadowlab::tool
