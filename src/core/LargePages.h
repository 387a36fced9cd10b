#pragma once
// An allocator for large working arrays that are filled once and then
// walked at random (core/MeshLevels.cpp): on Linux, an allocation of a
// megabyte or more is mapped on 2 MB boundaries and asks for transparent
// huge pages (madvise), so that first touching it faults once per 2 MB
// instead of once per 4 KB page, and walking it misses the TLB less: a
// million-triangle mesh's levels took a tenth less time (on a virtual
// machine, where a fault costs several microseconds).
// Small allocations, other systems, or a kernel that gives no huge pages:
// as std::allocator. What it holds is the same either way. GPU-free.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shadowlab {

template <class T>
struct LargePages {
    using value_type = T;

    LargePages() = default;
    template <class U>
    LargePages(const LargePages<U>&) {}

    T* allocate(std::size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= kLeast) {
            const std::size_t size = rounded(bytes);
            // Mapped with a huge page's room to spare, the ends beyond a
            // huge page boundary given back.
            void* raw = mmap(nullptr, size + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (raw == MAP_FAILED) throw std::bad_alloc();
            auto* base = static_cast<char*>(raw);
            const std::size_t skip = (kHuge - reinterpret_cast<std::uintptr_t>(base) % kHuge) % kHuge;
            if (skip > 0) munmap(base, skip);
            munmap(base + skip + size, kHuge - skip);
            madvise(base + skip, size, MADV_HUGEPAGE);
            return reinterpret_cast<T*>(base + skip);
        }
#endif
        return std::allocator<T>().allocate(n);
    }

    void deallocate(T* p, std::size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= kLeast) {
            munmap(p, rounded(bytes));
            return;
        }
#endif
        std::allocator<T>().deallocate(p, n);
    }

    template <class U>
    bool operator==(const LargePages<U>&) const {
        return true;
    }

private:
    static constexpr std::size_t kHuge = std::size_t(2) << 20;
    // Below this an allocation is left to malloc (its faults cost little).
    static constexpr std::size_t kLeast = std::size_t(1) << 20;
    static std::size_t rounded(std::size_t bytes) { return (bytes + kHuge - 1) / kHuge * kHuge; }
};

} // namespace shadowlab
