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
    const auto k = static_cast<MotionKind>(kind[i]);
    if (k != MotionKind::arc_cw && k != MotionKind::arc_ccw) return Vec3::Constant(kNaN);
    std::size_t arc = arc_rank_[i / kRankRows];  // arcs before the first row of i's stretch
    for (std::size_t r = i - i % kRankRows; r < i; ++r)
        arc += kind[r] == static_cast<std::uint8_t>(MotionKind::arc_cw) ||
               kind[r] == static_cast<std::uint8_t>(MotionKind::arc_ccw);
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

std::span<const double> Path::starts() const {
    Rows& w = written_.get();
    std::lock_guard lock(w.mutex);
    if (!w.have_starts) {
        const std::size_t n = size();
        w.starts.resize(3 * n);
        if (n > 1) std::memcpy(w.starts.data() + 3, end.data(), 3 * (n - 1) * sizeof(double));
        for (std::size_t j = 0; j < jump_rows_.size(); ++j)
            std::memcpy(w.starts.data() + 3 * jump_rows_[j], jump_starts_.data() + 3 * j, 3 * sizeof(double));
        w.have_starts = true;
    }
    return {w.starts.data(), w.starts.size()};
}

std::span<const double> Path::centers() const {
    Rows& w = written_.get();
    std::lock_guard lock(w.mutex);
    if (!w.have_centers) {
        const std::size_t n = size();
        w.centers.resize(3 * n, kNaN);
        const double* next = arc_centers_.data();
        for (std::size_t i = 0; i < n; ++i) {
            const auto k = static_cast<MotionKind>(kind[i]);
            if (k == MotionKind::arc_cw || k == MotionKind::arc_ccw) {
                std::memcpy(w.centers.data() + 3 * i, next, 3 * sizeof(double));
                next += 3;
            }
        }
        w.have_centers = true;
    }
    return {w.centers.data(), w.centers.size()};
}

std::span<const double> Path::feeds() const {
    Rows& w = written_.get();
    std::lock_guard lock(w.mutex);
    if (!w.have_feeds) {
        w.feeds.resize(size());
        feed.write(w.feeds.data());
        w.have_feeds = true;
    }
    return {w.feeds.data(), w.feeds.size()};
}

std::size_t Path::bytes() const {
    std::size_t b = kind.size() + side.size() + generated.size() + line.size() * sizeof(std::int32_t) +
                    (end.size() + jump_starts_.size() + arc_centers_.size()) * sizeof(double) +
                    (jump_rows_.size() + arc_rank_.size()) * sizeof(std::uint64_t) + feed.bytes();
    for (const Vec3Column* c : {&tool_offset, &abc, &normal, &tool_axis})
        b += c->uniform() ? 3 * sizeof(double) : 3 * c->size() * sizeof(double);
    for (const UniformColumn<std::int32_t, 1>* c : {&tool, &turns, &file})
        b += c->uniform() ? sizeof(std::int32_t) : c->size() * sizeof(std::int32_t);
    b += plane.uniform() ? 1 : plane.size();
    if (Rows* w = written_.rows.load(std::memory_order_acquire)) {
        std::lock_guard lock(w->mutex);
        b += (w->starts.size() + w->centers.size() + w->feeds.size()) * sizeof(double);
    }
    return b;
}

}  // namespace toolcomp
