#include "toolcomp/column.hpp"

#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace toolcomp::detail {

namespace {
constexpr std::size_t kHuge = std::size_t(2) << 20;  // 2 MB
constexpr std::size_t kThreshold = std::size_t(4) << 20;
}  // namespace

void* column_allocate(std::size_t bytes) {
    if (bytes < kThreshold) {
        void* p = std::malloc(bytes ? bytes : 1);
        if (!p) throw std::bad_alloc();
        return p;
    }
    const std::size_t size = (bytes + kHuge - 1) / kHuge * kHuge;
    void* p = std::aligned_alloc(kHuge, size);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE);  // advice only: without THP it is ignored
#endif
    return p;
}

void column_deallocate(void* p, std::size_t) noexcept { std::free(p); }

}  // namespace toolcomp::detail
