#include "Interrupt.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Error.h>

#include <chrono>
#include <future>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

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

// The places removeOnForcedEnd registered, in fixed storage the handler
// reads without allocating. An entry is filled before the count covers it.
struct Place {
    char path[4096];
    OnForcedEnd what;
};
constexpr int kMaxPlaces = 64;
Place places[kMaxPlaces];
volatile std::sig_atomic_t placeCount = 0;
char pendingMarker[32];  // ".pending-PID", set by installInterruptHandlers

// Whether `name` is NAME.pending-PID or NAME.pending-PID.SOMETHING for this
// process's PID (not a longer PID that begins with the same digits).
bool ourPending(const char* name) {
    const std::size_t m = std::strlen(pendingMarker);
    for (const char* at = std::strstr(name, pendingMarker); at; at = std::strstr(at + 1, pendingMarker))
        if (at != name && (at[m] == '\0' || at[m] == '.')) return true;
    return false;
}

// The kernel's directory record (getdents64), read without opendir, which
// allocates and is not async-signal-safe.
struct DirectoryRecord {
    unsigned long long inode;
    long long offset;
    unsigned short length;
    unsigned char type;
    char name[1];
};

// Removes the entries of the open directory `fd` (all of them, or this
// process's pending files), subdirectories with their content when `all`.
// Reads the directory again until a pass removes nothing, since removing
// while reading may skip entries.
void removeEntries(int fd, bool all, int depth) {
    alignas(8) char buffer[2048];
    for (int pass = 0; pass < 100000; ++pass) {
        bool removed = false;
        if (lseek(fd, 0, SEEK_SET) != 0) return;
        for (long n; (n = syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0;)
            for (long at = 0; at < n;) {
                const auto* record = reinterpret_cast<const DirectoryRecord*>(buffer + at);
                at += record->length;
                const char* name = record->name;
                if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
                if (!all && !ourPending(name)) continue;
                if (unlinkat(fd, name, 0) == 0) {
                    removed = true;
                } else if (all && depth < 8) {  // a directory: its content, then it
                    const int inner = openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
                    if (inner >= 0) {
                        removeEntries(inner, true, depth + 1);
                        close(inner);
                    }
                    if (unlinkat(fd, name, AT_REMOVEDIR) == 0) removed = true;
                }
            }
        if (!removed) return;
    }
}

// What the run registered, newest first (async-signal-safe calls only).
void removeRegisteredPlaces() {
    for (int i = placeCount - 1; i >= 0; --i) {
        const Place& place = places[i];
        if (place.what == OnForcedEnd::IfEmpty) {
            rmdir(place.path);
            continue;
        }
        const int fd = open(place.path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) continue;
        removeEntries(fd, place.what == OnForcedEnd::Everything, 0);
        close(fd);
        if (place.what == OnForcedEnd::Everything) rmdir(place.path);
    }
}

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
    const int savedErrno = errno;
    removeRegisteredPlaces();
    errno = savedErrno;
    std::signal(signal, SIG_DFL);
    std::raise(signal);  // delivered, with the default action, once this handler returns
}

} // namespace

void removeOnForcedEnd(const std::filesystem::path& path, OnForcedEnd what) {
    const std::string text = path.empty() ? std::string(".") : path.string();
    const int count = placeCount;
    for (int i = 0; i < count; ++i)
        if (places[i].what == what && text == places[i].path) return;
    if (count >= kMaxPlaces || text.size() >= sizeof places[0].path) return;
    std::memcpy(places[count].path, text.c_str(), text.size() + 1);
    places[count].what = what;
    placeCount = count + 1;  // after the entry is whole: the handler may read it from now on
}

void installInterruptHandlers() {
    std::snprintf(pendingMarker, sizeof pendingMarker, ".pending-%ld", static_cast<long>(getpid()));
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
