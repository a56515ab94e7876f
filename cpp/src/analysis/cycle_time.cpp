#include "toolcomp/analysis/cycle_time.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "toolcomp/geometry/arc.hpp"

namespace toolcomp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double rapid_rate(const MachineRates& r, int axis) {
    const double v = r.rapid[static_cast<std::size_t>(axis)];
    return v > 0 ? v : kDefaultRapidRate;
}

// Minutes the slowest axis needs for its share `d` of a move at `rate(axis)` (0: no limit).
template <class Rate>
double slowest_axis(const Vec3& d, Rate rate) {
    double minutes = 0;
    for (int a = 0; a < 3; ++a) {
        const double v = rate(a);
        if (v > 0) minutes = std::max(minutes, std::abs(d[a]) / v);
    }
    return minutes;
}

// The plane's two axes and the one normal to it (its helix axis).
std::array<int, 3> plane_axes(Plane p) {
    switch (p) {
        case Plane::zx: return {2, 0, 1};
        case Plane::yz: return {1, 2, 0};
        default: return {0, 1, 2};
    }
}

double feed_move_minutes(const Motion& m, double feed, const MachineRates& r) {
    if (!(feed > 0)) return kNaN;
    const auto max_feed = [&](int a) { return r.max_feed[static_cast<std::size_t>(a)]; };
    if (!m.is_arc()) {
        const Vec3 d = m.end - m.start;
        return std::max(d.norm() / feed, slowest_axis(d, max_feed));
    }
    const double length = arc_length(m.arc());
    const auto [a, b, normal] = plane_axes(m.plane);
    double speed = feed;
    for (int axis : {a, b})
        if (max_feed(axis) > 0) speed = std::min(speed, max_feed(axis));
    const double helix = std::abs(m.end[normal] - m.start[normal]);
    return std::max(length / speed, max_feed(normal) > 0 ? helix / max_feed(normal) : 0.0);
}

}  // namespace

std::vector<double> segment_seconds(const Path& path, const MachineRates& rates) {
    const std::size_t n = path.size();
    std::vector<double> out(n);
    const std::span<const double> feeds = path.feeds();
    for (std::size_t i = 0; i < n; ++i) {
        const auto kind = static_cast<MotionKind>(path.kind[i]);
        double minutes;
        if (kind == MotionKind::rapid) {
            const Vec3 d = Vec3(path.end[3 * i], path.end[3 * i + 1], path.end[3 * i + 2]) - path.start_at(i);
            minutes = slowest_axis(d, [&](int a) { return rapid_rate(rates, a); });
        } else {
            minutes = feed_move_minutes(path.segment(i), feeds[i], rates);
        }
        out[i] = minutes * 60;
    }
    return out;
}

std::size_t tool_changes(const Path& path) {
    const std::size_t n = path.size();
    if (n == 0) return 0;
    if (path.tool.uniform()) return path.tool.fill()[0] != 0 ? 1 : 0;
    const std::int32_t* tool = path.tool.data();
    std::size_t changes = tool[0] != 0 ? 1 : 0;
    for (std::size_t i = 1; i < n; ++i) changes += tool[i] != tool[i - 1];
    return changes;
}

}  // namespace toolcomp
