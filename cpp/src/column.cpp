#include "toolcomp/column.hpp"

#include <cstdint>
#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace toolcomp::detail {

namespace {
constexpr std::size_t kHuge = std::size_t(2) << 20;  // 2 MB
constexpr std::size_t kThreshold = std::size_t(512) << 10;
constexpr std::size_t kPage = 4096;
}  // namespace

// Large columns are mapped from the kernel and unmapped when freed: their memory goes back
// at once, whichever thread frees it (the heap would keep it in that thread's arena, and a
// streamed run frees chunks in another thread than the one that filled them). The mapping
// starts on a 2 MB boundary so that transparent huge pages can back it.
void* column_allocate(std::size_t bytes) {
    if (bytes < kThreshold) {
        void* p = std::malloc(bytes ? bytes : 1);
        if (!p) throw std::bad_alloc();
        return p;
    }
    const std::size_t size = (bytes + kHuge - 1) / kHuge * kHuge;
#if defined(__linux__)
    void* raw = mmap(nullptr, size + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const auto base = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = (base + kHuge - 1) / kHuge * kHuge;
    if (aligned > base) munmap(raw, aligned - base);
    if (const std::size_t tail = base + size + kHuge - (aligned + size)) munmap(reinterpret_cast<void*>(aligned + size), tail);
    void* p = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE);  // advice only: without THP it is ignored
#endif
    return p;
#else
    void* p = std::aligned_alloc(kHuge, size);
    if (!p) throw std::bad_alloc();
    return p;
#endif
}

void column_deallocate(void* p, std::size_t bytes) noexcept {
#if defined(__linux__)
    if (bytes >= kThreshold) {
        munmap(p, (bytes + kHuge - 1) / kHuge * kHuge);
        return;
    }
#endif
    std::free(p);
}

void column_release_tail(void* p, std::size_t used, std::size_t capacity) noexcept {
#if defined(__linux__) && defined(MADV_DONTNEED)
    if (capacity < kThreshold) return;  // on the heap
    const auto base = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t from = (base + used + kPage - 1) / kPage * kPage;
    const std::uintptr_t to = base + (capacity + kHuge - 1) / kHuge * kHuge;  // the mapping's end
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
    (void)p, (void)used, (void)capacity;
#endif
}

}  // namespace toolcomp::detail
