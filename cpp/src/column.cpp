#include "toolcomp/column.hpp"

#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <utility>
#include <vector>
#if defined(__linux__)
#include <pthread.h>
#include <sys/mman.h>
#endif

namespace toolcomp::detail {

namespace {
constexpr std::size_t kHuge = std::size_t(2) << 20;  // 2 MB
constexpr std::size_t kThreshold = std::size_t(512) << 10;
constexpr std::size_t kPage = 4096;

#if defined(__linux__)
// Mappings freed lately, kept for an allocation of the same size. A stream's chunks, the
// runs of a batch one after the other and a program's pieces ask for the same sizes again
// and again: a kept mapping's pages are in memory already, where a fresh one costs a page
// fault and the kernel's zeroing per page (on a virtual machine also the host's, when it has
// taken the memory back: 0.3 to 0.7 GB/s against 9 GB/s measured). At most kKeptMaps
// mappings and kKeptBytes; a mapping that does not fit is unmapped, and all are when the
// system refuses a new one.
constexpr std::size_t kKeptBytes = std::size_t(256) << 20;
constexpr std::size_t kKeptMaps = 32;
struct Kept {
    std::mutex mu;
    std::vector<std::pair<void*, std::size_t>> maps;  // start, size (whole 2 MB pages)
    std::size_t bytes = 0;
};
Kept& kept() {
    static Kept* k = [] {
        auto* made = new Kept;  // never destroyed: columns may be freed during exit
        // A fork while another thread holds the lock would leave it held in the child for
        // good: the fork waits for it, and both sides let go.
        pthread_atfork([] { kept().mu.lock(); }, [] { kept().mu.unlock(); }, [] { kept().mu.unlock(); });
        return made;
    }();
    return *k;
}
void* take_kept(std::size_t size) {
    Kept& k = kept();
    std::lock_guard<std::mutex> lock(k.mu);
    for (std::size_t i = k.maps.size(); i-- > 0;) {  // the latest first: its pages are the warmest
        if (k.maps[i].second != size) continue;
        void* p = k.maps[i].first;
        k.maps.erase(k.maps.begin() + static_cast<std::ptrdiff_t>(i));
        k.bytes -= size;
        return p;
    }
    return nullptr;
}
bool keep(void* p, std::size_t size) {
    Kept& k = kept();
    std::lock_guard<std::mutex> lock(k.mu);
    if (k.maps.size() >= kKeptMaps || k.bytes + size > kKeptBytes) return false;
    k.maps.emplace_back(p, size);
    k.bytes += size;
    return true;
}
void unmap_kept() {
    Kept& k = kept();
    std::lock_guard<std::mutex> lock(k.mu);
    for (auto [p, size] : k.maps) munmap(p, size);
    k.maps.clear();
    k.bytes = 0;
}
void* map_aligned(std::size_t size) {
    void* raw = mmap(nullptr, size + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) return nullptr;
    const auto base = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = (base + kHuge - 1) / kHuge * kHuge;
    if (aligned > base) munmap(raw, aligned - base);
    if (const std::size_t tail = base + size + kHuge - (aligned + size)) munmap(reinterpret_cast<void*>(aligned + size), tail);
    void* p = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE);  // advice only: without THP it is ignored
#endif
    return p;
}
#endif
}  // namespace

// Large columns are mapped from the kernel: their memory goes back when freed, whichever
// thread frees it (the heap would keep it in that thread's arena, and a streamed run frees
// chunks in another thread than the one that filled them), unless it is kept for the next
// allocation of its size (above). The mapping starts on a 2 MB boundary so that transparent
// huge pages can back it.
void* column_allocate(std::size_t bytes) {
    if (bytes < kThreshold) {
        void* p = std::malloc(bytes ? bytes : 1);
        if (!p) throw std::bad_alloc();
        return p;
    }
    const std::size_t size = (bytes + kHuge - 1) / kHuge * kHuge;
#if defined(__linux__)
    if (void* p = take_kept(size)) return p;
    void* p = map_aligned(size);
    if (!p) {
        unmap_kept();  // under an address-space limit the kept mappings may be what is missing
        p = map_aligned(size);
    }
    if (!p) throw std::bad_alloc();
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
        const std::size_t size = (bytes + kHuge - 1) / kHuge * kHuge;
        if (!keep(p, size)) munmap(p, size);
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
