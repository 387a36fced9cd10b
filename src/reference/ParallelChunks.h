#pragma once
/// @file ParallelChunks.h
/// The tracer's threads: work handed out in chunks to one worker per
/// hardware thread (parallelChunks), each with denormals flushed to zero
/// while it runs (FlushDenormalsGuard). Private to the reference.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <system_error>
#include <thread>
#include <vector>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#define SHADOWLAB_HAVE_MXCSR 1
#endif

namespace shadowlab::reference {

// Embree recommends flush-to-zero and denormals-are-zero while tracing; set
// for the lifetime of a worker and restore the thread's previous mode.
class FlushDenormalsGuard {
public:
#ifdef SHADOWLAB_HAVE_MXCSR
    FlushDenormalsGuard() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); } // FTZ | DAZ
    ~FlushDenormalsGuard() { _mm_setcsr(saved_); }
private:
    unsigned saved_;
#endif
public:
    FlushDenormalsGuard(const FlushDenormalsGuard&) = delete;
    FlushDenormalsGuard& operator=(const FlushDenormalsGuard&) = delete;
};

// Runs fn(begin, end) over [0, count) in chunks of `chunk`, handed out with an
// atomic counter to one worker per hardware thread (the caller is one of them).
template <class Fn>
void parallelChunks(std::size_t count, std::size_t chunk, const Fn& fn) {
    if (count == 0) return;
    const std::size_t chunks = (count + chunk - 1) / chunk;
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        FlushDenormalsGuard ftz;
        for (;;) {
            const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
            if (c >= chunks) break;
            fn(c * chunk, std::min(count, (c + 1) * chunk));
        }
    };
    const std::size_t threads =
        std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), chunks);
    std::vector<std::jthread> helpers;
    helpers.reserve(threads - 1);
    for (std::size_t t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back(worker);
        } catch (const std::system_error&) {
            break; // fewer threads: the remaining workers take all chunks
        }
    }
    worker();
} // helpers join here

} // namespace shadowlab::reference
