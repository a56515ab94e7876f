#pragma once
// RunColumn: one value a row that changes now and then (a feed rate): kept only at the rows
// where it differs from the row before, bit for bit, as runs; read back one row at a time
// (a binary search over the runs) or written out for every row.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

#include "toolcomp/column.hpp"

namespace toolcomp {

template <class T>
class RunColumn {
public:
    RunColumn() = default;
    RunColumn(const RunColumn&) = default;
    RunColumn& operator=(const RunColumn&) = default;
    RunColumn(RunColumn&& o) noexcept : starts_(std::move(o.starts_)), values_(std::move(o.values_)), n_(std::exchange(o.n_, 0)) {}
    RunColumn& operator=(RunColumn&& o) noexcept {
        starts_ = std::move(o.starts_);
        values_ = std::move(o.values_);
        n_ = std::exchange(o.n_, 0);
        return *this;
    }

    // The first `rows` rows of `o`.
    RunColumn(const RunColumn& o, std::size_t rows) : n_(rows) {
        const std::size_t runs = static_cast<std::size_t>(
            std::lower_bound(o.starts_.begin(), o.starts_.end(), static_cast<std::uint64_t>(rows)) - o.starts_.begin());
        starts_.insert(starts_.end(), o.starts_.data(), o.starts_.data() + runs);
        values_.insert(values_.end(), o.values_.data(), o.values_.data() + runs);
    }

    std::size_t size() const noexcept { return n_; }
    std::size_t runs() const noexcept { return values_.size(); }
    // Throws (bad_alloc) only where a run starts, and then leaves the column as it was.
    void push(T v) {
        if (n_ == 0 || std::memcmp(&v, &values_.back(), sizeof(T)) != 0) [[unlikely]] {
            starts_.push_back(n_);
            try {
                values_.push_back(v);
            } catch (...) {
                starts_.pop_back();
                throw;
            }
        }
        ++n_;
    }
    void pop_back() noexcept {
        --n_;
        if (starts_.back() == n_) {
            starts_.pop_back();
            values_.pop_back();
        }
    }
    T operator[](std::size_t i) const noexcept {
        const auto* run = std::upper_bound(starts_.begin(), starts_.end(), static_cast<std::uint64_t>(i));
        return values_[static_cast<std::size_t>(run - starts_.begin()) - 1];
    }
    // Every row's value into out[0, size()).
    void write(T* out) const noexcept {
        for (std::size_t r = 0; r < runs(); ++r) {
            const std::size_t to = r + 1 < runs() ? starts_[r + 1] : n_;
            std::fill(out + starts_[r], out + to, values_[r]);
        }
    }
    std::size_t bytes() const noexcept { return runs() * (sizeof(std::uint64_t) + sizeof(T)); }
    void release_unused() noexcept {
        toolcomp::release_unused(starts_);
        toolcomp::release_unused(values_);
    }

private:
    Column<std::uint64_t> starts_;  // the first row of each run
    Column<T> values_;              // its value
    std::size_t n_ = 0;
};

}  // namespace toolcomp
