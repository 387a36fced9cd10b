#pragma once
// Interrupts (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM): the first one asks the run to stop
// at its next check, where it throws like any other error, so that what it
// has half written is removed on the way out; a second one within a second
// of it waits for that too (a double Ctrl-C), a later one ends the process
// at once, first removing what the run registered with removeOnForcedEnd
// (with async-signal-safe calls only). A file past the size limit (SIGXFSZ) fails its write instead of
// ending the process, so the write's error names the file.

#include <filesystem>

namespace shadowlab {
class ComparisonJob;
}

namespace shadowlab::tool {

/// Installs the interrupt handlers (render, compare, bench and the
/// viewer, whose window loop checks once a frame).
void installInterruptHandlers();
/// A file past the size limit fails its write (every command).
void ignoreFileSizeSignal();
/// What an interrupt that ends the process at once removes first.
enum class OnForcedEnd {
    OurPendingFiles,  ///< the entries of a directory named NAME.pending-PID[...] with this process's PID
    Everything,       ///< a directory and all in it (bench's OUT.partial-PID)
    IfEmpty,          ///< a directory this run made, if nothing else is in it
};
/// Registers `path` for removal if a later interrupt ends the process at
/// once. Places are removed in the reverse order of registration (so a
/// directory made before the files in it goes after them). Registering
/// the same place twice is harmless; past 64 places, the rest is left to
/// the next run to the same names, which removes a dead process's leftovers.
void removeOnForcedEnd(const std::filesystem::path& path, OnForcedEnd what);
/// Throws Error "interrupted (SIGNAL)" once an interrupt came.
void throwIfInterrupted();
/// Traces job's reference on a second thread while this one watches for an
/// interrupt, which cancels the trace (a trace of minutes stops within a
/// chunk of rays) and then throws as throwIfInterrupted does.
void traceInterruptibly(ComparisonJob& job);

} // namespace shadowlab::tool
