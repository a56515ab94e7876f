// The Path's start points, arc centres and feeds as they are stored (jumps, arcs' centres,
// runs) read back one segment at a time, or written out for every segment once asked for.
#include <algorithm>
#include <cstring>
#include <limits>

#include "toolcomp/path.hpp"

namespace toolcomp {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
Vec3 row3(const double* p) { return {p[0], p[1], p[2]}; }
}  // namespace

Vec3 Path::start_at(std::size_t i) const {
    // The last jump at or before i: the jump itself, or i follows the end before it.
    const auto* last = std::upper_bound(jump_rows_.begin(), jump_rows_.end(), i);
    if (last != jump_rows_.begin() && last[-1] == i)
        return row3(jump_starts_.data() + 3 * static_cast<std::size_t>(last - 1 - jump_rows_.begin()));
    return row3(end.data() + 3 * (i - 1));
}

Vec3 Path::center_at(std::size_t i) const {
    if (!arc_row(kind[i])) return Vec3::Constant(kNaN);
    std::size_t arc = arc_rank_[i / kRankRows];  // arcs before the first row of i's stretch
    for (std::size_t r = i - i % kRankRows; r < i; ++r) arc += arc_row(kind[r]);
    return row3(arc_centers_.data() + 3 * arc);
}

Path::Rows& Path::Written::get() const {
    Rows* r = rows.load(std::memory_order_acquire);
    if (r) return *r;
    auto* made = new Rows;
    if (rows.compare_exchange_strong(r, made, std::memory_order_acq_rel)) return *made;
    delete made;  // another thread's came first
    return *r;
}

namespace {
// A column written out once: `write` fills its n values under the lock, then it is kept.
template <class Rows, class Write>
std::span<const double> once(Rows& w, Column<double>& col, std::size_t n, Write write) {
    std::lock_guard lock(w.mutex);
    if (col.size() != n) {
        col.resize(n);
        write(col.data());
    }
    return {col.data(), col.size()};
}
}  // namespace

std::span<const double> Path::starts() const {
    Rows& w = written_.get();
    return once(w, w.starts, 3 * size(), [&](double* out) {
        // each the end before it, then the jumps (row 0 is one)
        if (size() > 1) std::memcpy(out + 3, end.data(), 3 * (size() - 1) * sizeof(double));
        for (std::size_t j = 0; j < jump_rows_.size(); ++j)
            std::memcpy(out + 3 * jump_rows_[j], jump_starts_.data() + 3 * j, 3 * sizeof(double));
    });
}

std::span<const double> Path::centers() const {
    Rows& w = written_.get();
    return once(w, w.centers, 3 * size(), [&](double* out) {
        const double* next = arc_centers_.data();
        for (std::size_t i = 0; i < size(); ++i, out += 3) {
            if (arc_row(kind[i])) {
                std::memcpy(out, next, 3 * sizeof(double));
                next += 3;
            } else {
                out[0] = out[1] = out[2] = kNaN;
            }
        }
    });
}

std::span<const double> Path::feeds() const {
    Rows& w = written_.get();
    return once(w, w.feeds, size(), [&](double* out) { feed.write(out); });
}

std::size_t Path::bytes() const {
    std::size_t b = kind.size() + side.size() + generated.size() + line.size() * sizeof(std::int32_t) +
                    (end.size() + jump_starts_.size() + arc_centers_.size()) * sizeof(double) +
                    (jump_rows_.size() + arc_rank_.size()) * sizeof(std::uint64_t) + feed.bytes();
    for (const Vec3Column* c : {&tool_offset, &work_offset, &abc, &normal, &tool_axis})
        b += c->uniform() ? 3 * sizeof(double) : 3 * c->size() * sizeof(double);
    for (const UniformColumn<std::int32_t, 1>* c : {&tool, &turns, &file})
        b += c->uniform() ? sizeof(std::int32_t) : c->size() * sizeof(std::int32_t);
    b += work_rotation.uniform() ? sizeof(double) : work_rotation.size() * sizeof(double);
    b += plane.uniform() ? 1 : plane.size();
    if (Rows* w = written_.rows.load(std::memory_order_acquire)) {
        std::lock_guard lock(w->mutex);
        b += (w->starts.size() + w->centers.size() + w->feeds.size()) * sizeof(double);
    }
    return b;
}

}  // namespace toolcomp
