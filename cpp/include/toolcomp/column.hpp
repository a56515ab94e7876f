#pragma once
// Column: the std::vector the Path's columns and other big result arrays are stored in.
//
// Its allocator asks the kernel for transparent huge pages (2 MB) for allocations of 4 MB and
// more (madvise MADV_HUGEPAGE where the kernel offers it): a million-segment Path touches a
// few hundred pages instead of tens of thousands, and threads filling their own Paths no
// longer queue on the process's page-fault lock. Small columns use the ordinary heap.
#include <cstddef>
#include <new>
#include <vector>

namespace toolcomp {

namespace detail {
void* column_allocate(std::size_t bytes);
void column_deallocate(void* p, std::size_t bytes) noexcept;
}  // namespace detail

template <class T>
struct ColumnAllocator {
    using value_type = T;
    ColumnAllocator() noexcept = default;
    template <class U>
    ColumnAllocator(const ColumnAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(detail::column_allocate(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { detail::column_deallocate(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const ColumnAllocator<U>&) const noexcept { return true; }
};

template <class T>
using Column = std::vector<T, ColumnAllocator<T>>;

}  // namespace toolcomp
