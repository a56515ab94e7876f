#pragma once
// Column: the std::vector the Path's columns and other big result arrays are stored in.
//
// Its allocator asks the kernel for transparent huge pages (2 MB) for allocations of 4 MB and
// more (madvise MADV_HUGEPAGE where the kernel offers it): a million-segment Path touches a
// few hundred pages instead of tens of thousands, and threads filling their own Paths no
// longer queue on the process's page-fault lock. Small columns use the ordinary heap.
#include <algorithm>
#include <cmath>
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

// Three doubles per row that are usually the same on every row (rotary axes, surface
// normals, tool axis): nothing is stored while every row equals `fill`; the first row that
// differs (bit for bit, so NaN equals NaN) writes out the rows before it and from then on
// every row is stored. 72 of the Path's 192 bytes per segment on ordinary programs.
class Vec3Column {
public:
    explicit Vec3Column(double x = 0, double y = 0, double z = 0) : fill_{x, y, z} {}
    std::size_t size() const { return n_; }
    bool uniform() const { return data_.empty(); }  // every row equals fill()
    const double* fill() const { return fill_; }
    const double* data() const { return data_.data(); }  // rows, when not uniform
    double operator()(std::size_t row, int k) const { return uniform() ? fill_[k] : data_[3 * row + static_cast<std::size_t>(k)]; }
    void reserve(std::size_t rows) { reserve_ = rows; }
    void push(double x, double y, double z) {
        if (uniform() && same(x, fill_[0]) && same(y, fill_[1]) && same(z, fill_[2])) {
            ++n_;
            return;
        }
        if (uniform()) {
            data_.reserve(3 * std::max(reserve_, n_ + 1));
            for (std::size_t i = 0; i < n_; ++i) data_.insert(data_.end(), fill_, fill_ + 3);
        }
        data_.push_back(x);
        data_.push_back(y);
        data_.push_back(z);
        ++n_;
    }

private:
    static bool same(double a, double b) { return a == b ? (a != 0 || std::signbit(a) == std::signbit(b)) : (a != a && b != b); }
    double fill_[3];
    std::size_t n_ = 0, reserve_ = 0;
    Column<double> data_;
};

}  // namespace toolcomp
