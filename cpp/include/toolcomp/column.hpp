#pragma once
// Column: the growable array the Path's columns and the Program's blocks and words are
// stored in.
//
// Its memory asks the kernel for transparent huge pages (2 MB) for allocations of 512 kB
// and more (madvise MADV_HUGEPAGE where the kernel offers it): a million-segment Path touches
// a few hundred pages instead of tens of thousands, and threads filling their own Paths no
// longer queue on the process's page-fault lock. Small columns use the ordinary heap.
// A mapping is whole 2 MB pages; `release_unused` gives back what lies beyond the rows when a
// column is complete (a 600 kB column keeps 600 kB, not 2 MB).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>
#include <utility>
#include <type_traits>
#include <vector>

namespace toolcomp {

namespace detail {
void* column_allocate(std::size_t bytes);
void column_deallocate(void* p, std::size_t bytes) noexcept;
// Returns to the kernel the pages of an allocation of `capacity` bytes at `p` that lie
// wholly beyond its first `used` bytes (mapped allocations only; heap ones are left).
void column_release_tail(void* p, std::size_t used, std::size_t capacity) noexcept;
}  // namespace detail

// The same memory for a std::vector of values that are not plain (a Program's tokens, whose
// texts may own heap memory): large ones on huge pages, and a mapping given back is kept for
// the next column or vector to take, its pages already faulted in.
template <class T>
struct ColumnAllocator {
    using value_type = T;
    ColumnAllocator() noexcept = default;
    template <class U>
    ColumnAllocator(const ColumnAllocator<U>&) noexcept {}  // NOLINT: rebinding, as std::allocator
    T* allocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(detail::column_allocate(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { detail::column_deallocate(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const ColumnAllocator<U>&) const noexcept { return true; }
};

// A growable array of trivially copyable values (the std::vector operations the columns
// use), in memory from column_allocate. Beyond std::vector: `push_unchecked` and
// `append_unchecked` write into capacity reserved before, without a test per value (the Path
// checks its room once a segment, not once a value), and a copy keeps the capacity.
template <class T>
class Column {
    static_assert(std::is_trivially_copyable_v<T>, "a Column holds plain values");

public:
    using value_type = T;
    using iterator = T*;
    using const_iterator = const T*;

    Column() noexcept = default;
    Column(std::size_t n, const T& v) { resize(n, v); }
    Column(const T* first, std::size_t n) { insert(end(), first, first + n); }
    Column(const Column& o) { copy_from(o); }
    Column(Column&& o) noexcept { swap(o); }
    Column& operator=(const Column& o) {
        if (this != &o) {
            Column c(o);
            swap(c);
        }
        return *this;
    }
    Column& operator=(Column&& o) noexcept {
        Column c(std::move(o));
        swap(c);
        return *this;
    }
    ~Column() {
        if (first_) detail::column_deallocate(first_, capacity() * sizeof(T));
    }
    void swap(Column& o) noexcept {
        std::swap(first_, o.first_);
        std::swap(last_, o.last_);
        std::swap(limit_, o.limit_);
    }

    std::size_t size() const noexcept { return static_cast<std::size_t>(last_ - first_); }
    std::size_t capacity() const noexcept { return static_cast<std::size_t>(limit_ - first_); }
    bool empty() const noexcept { return last_ == first_; }
    T* data() noexcept { return first_; }
    const T* data() const noexcept { return first_; }
    T& operator[](std::size_t i) noexcept { return first_[i]; }
    const T& operator[](std::size_t i) const noexcept { return first_[i]; }
    T* begin() noexcept { return first_; }
    T* end() noexcept { return last_; }
    const T* begin() const noexcept { return first_; }
    const T* end() const noexcept { return last_; }
    T& front() noexcept { return *first_; }
    const T& front() const noexcept { return *first_; }
    T& back() noexcept { return last_[-1]; }
    const T& back() const noexcept { return last_[-1]; }

    void reserve(std::size_t n) {
        if (n > capacity()) reallocate(n);
    }
    void clear() noexcept { last_ = first_; }
    void pop_back() noexcept { --last_; }
    // Values passed in may be rows of this column (as with std::vector): they are copied
    // before the column grows and frees its old memory.
    void push_back(const T& v) {
        if (last_ == limit_) [[unlikely]]
            return grow_and_push(v);
        *last_++ = v;
    }
    template <class... A>
    T& emplace_back(A&&... a) {
        if (last_ == limit_) [[unlikely]] {
            grow_and_push(T{std::forward<A>(a)...});
            return back();
        }
        return *new (last_++) T{std::forward<A>(a)...};
    }
    void resize(std::size_t n) { resize(n, T{}); }
    void resize(std::size_t n, const T& v) {
        const T fill = v;
        if (n > capacity()) grow(n);
        for (T* p = last_; p < first_ + n; ++p) *p = fill;
        last_ = first_ + n;
    }
    // Appends [first, last) at the end (the only place the columns insert).
    void insert(const T* pos, const T* first, const T* last) {
        if (pos != end()) throw std::logic_error("Column::insert only appends");
        const std::size_t n = static_cast<std::size_t>(last - first);
        if (size() + n > capacity()) {
            const bool own = first >= first_ && first < last_;  // rows of this column
            const std::size_t at = own ? static_cast<std::size_t>(first - first_) : 0;
            grow(size() + n);
            if (own) first = first_ + at;
        }
        if (n) std::memcpy(last_, first, n * sizeof(T));
        last_ += n;
    }
    // Within reserved capacity only (size() < capacity(), resp. size() + n <= capacity()).
    void push_unchecked(const T& v) noexcept { *last_++ = v; }
    T* append_unchecked(std::size_t n) noexcept {
        T* p = last_;
        last_ += n;
        return p;
    }

private:
    [[gnu::noinline]] void grow(std::size_t need) { reallocate(std::max({need, 2 * capacity(), std::size_t{8}})); }
    [[gnu::noinline]] void grow_and_push(T v) {  // v: a copy, made before the memory moves
        grow(size() + 1);
        *last_++ = v;
    }
    void reallocate(std::size_t n) {
        if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
        T* p = static_cast<T*>(detail::column_allocate(n * sizeof(T)));
        const std::size_t rows = size();
        if (rows) std::memcpy(p, first_, rows * sizeof(T));
        if (first_) detail::column_deallocate(first_, capacity() * sizeof(T));
        first_ = p;
        last_ = p + rows;
        limit_ = p + n;
    }
    void copy_from(const Column& o) {
        if (o.capacity() == 0) return;
        reallocate(o.capacity());
        if (!o.empty()) std::memcpy(first_, o.first_, o.size() * sizeof(T));
        last_ = first_ + o.size();
    }

    T* first_ = nullptr;  // the rows are [first_, last_), the capacity [first_, limit_)
    T* last_ = nullptr;
    T* limit_ = nullptr;
};

// Gives back the memory of `c` beyond its rows (the column may still grow: pages given back
// come back zeroed when written).
template <class T>
void release_unused(Column<T>& c) noexcept {
    if (c.capacity() != 0) detail::column_release_tail(c.data(), c.size() * sizeof(T), c.capacity() * sizeof(T));
}

// K values per row that are usually the same on every row (rotary axes, surface normals,
// tool axis, tool, tool length offset, plane, the file a segment comes from): nothing is
// stored while every row equals `fill` (the first row; before it, the constructor's value);
// the first row that differs (bit for bit, except that NaN equals NaN) writes out the rows
// before it and from then on every row is stored. 105 of the Path's 192 bytes per segment on
// ordinary programs.
template <class T, int K>
class UniformColumn {
public:
    UniformColumn() { std::fill(fill_, fill_ + K, T{}); }
    // The first `rows` rows of `o`, stored as `o` stored them then: uniform up to the first
    // row that differs from the fill (the rows before it were written out as the fill).
    UniformColumn(const UniformColumn& o, std::size_t rows) : n_(rows), reserve_(o.reserve_) {
        std::copy(o.fill_, o.fill_ + K, fill_);
        if (!o.stored_) return;
        for (std::size_t r = 0; r < rows && !stored_; ++r)
            stored_ = std::memcmp(o.data_.data() + K * r, fill_, sizeof fill_) != 0;
        if (stored_) data_.insert(data_.end(), o.data_.data(), o.data_.data() + K * rows);
    }
    UniformColumn(const UniformColumn&) = default;
    UniformColumn& operator=(const UniformColumn&) = default;
    UniformColumn(UniformColumn&&) = default;
    UniformColumn& operator=(UniformColumn&&) = default;
    explicit UniformColumn(T x, T y = T{}, T z = T{}) {
        const T v[3] = {x, y, z};
        std::copy(v, v + K, fill_);
    }
    std::size_t size() const { return n_; }
    bool uniform() const { return !stored_; }  // every row equals fill()
    const T* fill() const { return fill_; }
    const T* data() const { return data_.data(); }  // rows, when not uniform
    T operator()(std::size_t row, int k = 0) const {
        return uniform() ? fill_[k] : data_[K * row + static_cast<std::size_t>(k)];
    }
    void reserve(std::size_t rows) { reserve_ = rows; }
    void release_unused() noexcept { toolcomp::release_unused(data_); }
    void push(const T* row) {
        if (uniform() && std::memcmp(row, fill_, sizeof fill_) == 0) {  // the common case, inline
            ++n_;
            return;
        }
        if (n_ == 0) {  // the first row is the fill
            std::copy(row, row + K, fill_);
            ++n_;
            return;
        }
        push_stored(row);
    }
    void push(T x, T y, T z) requires(K == 3) {
        const T v[3] = {x, y, z};
        push(v);
    }
    void push(T x) requires(K == 1) { push(&x); }
    // One more row equal to the last one pushed, which left the column uniform (the caller
    // knows: Path::push compares a segment's uniform values with the last segment's at once).
    void push_same() noexcept { ++n_; }

private:
    static bool same(T a, T b) {
        if constexpr (std::is_floating_point_v<T>)
            return a == b ? (a != 0 || std::signbit(a) == std::signbit(b)) : (a != a && b != b);
        else
            return a == b;
    }
    [[gnu::noinline]] void push_stored(const T* row) {
        if (uniform()) {
            bool same_row = true;  // also a NaN of another sign or payload
            for (int k = 0; k < K; ++k) same_row = same_row && same(row[k], fill_[k]);
            if (same_row) {
                ++n_;
                return;
            }
            data_.reserve(K * std::max(reserve_, n_ + 1));
            for (std::size_t i = 0; i < n_; ++i) data_.insert(data_.end(), fill_, fill_ + K);
            stored_ = true;
        }
        data_.insert(data_.end(), row, row + K);
        ++n_;
    }
    T fill_[K];
    bool stored_ = false;  // the rows are in data_
    std::size_t n_ = 0, reserve_ = 0;
    Column<T> data_;
};

using Vec3Column = UniformColumn<double, 3>;

}  // namespace toolcomp
