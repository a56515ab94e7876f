#include "start.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace toolcomp {

namespace {

// The moves of a beginning, in mm, up to `limit` of them (then it stops the run).
class Recorder : public MotionSink {
public:
    struct Stop {};
    struct Move {
        Vec3 start, end;
        bool arc;
        bool rotated;
    };
    explicit Recorder(std::size_t limit) : limit_(limit) {}
    void push(const Motion& m) override {
        if (m.radius.side != 0) throw Stop{};  // compensation must not depend on a guessed start
        moves.push_back({m.start * m.unit, m.end * m.unit, m.is_arc(), m.work_rotation != 0});
        if (moves.size() >= limit_) throw Stop{};
    }
    std::vector<Move> moves;

private:
    std::size_t limit_;
};

std::vector<Recorder::Move> record(const RunOptions& options, const Beginning& beginning, const Vec3& at,
                                   std::size_t limit) {
    RunOptions o = options;
    o.start = at;
    o.progress = nullptr;
    o.threads = false;
    Recorder rec(limit);
    try {
        beginning(o, rec);
    } catch (...) {  // the limit, an error, the end: the moves so far are the beginning
    }
    return std::move(rec.moves);
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a)); }

Vec3 first_positions(const RunOptions& options, const Beginning& beginning) {
    static constexpr double kProbe = 1000;  // mm: the second machine position, on every axis
    Vec3 start = Vec3::Zero();
    for (std::size_t limit : {std::size_t{64}, std::size_t{4096}}) {
        const auto a = record(options, beginning, Vec3::Zero(), limit);
        const auto b = record(options, beginning, Vec3::Constant(kProbe), limit);
        const std::size_t n = std::min(a.size(), b.size());
        for (std::size_t k = 0; k < n; ++k)
            if (a[k].rotated || b[k].rotated) return Vec3::Zero();
        bool all = true;
        for (int axis = 0; axis < 3; ++axis) {
            std::size_t k = 0;
            while (k < n && !same(a[k].end[axis], b[k].end[axis])) ++k;
            if (k == n) {
                all = false;
                continue;
            }
            const double slope = (b[k].start[axis] - a[k].start[axis]) / kProbe;
            if (a[k].arc || std::abs(slope) < 1e-6) continue;
            start[axis] = (a[k].end[axis] - a[k].start[axis]) / slope;
        }
        if (all || a.size() < limit || b.size() < limit) break;
        start = Vec3::Zero();
    }
    return start;
}

}  // namespace

RunOptions with_start(const RunOptions& options, const Beginning& beginning) {
    RunOptions o = options;
    if (o.start) return o;
    if (o.machine) {
        const auto& s = o.machine->start;
        o.start = Vec3(s[0], s[1], s[2]);
        return o;
    }
    o.start = first_positions(options, beginning);
    return o;
}

}  // namespace toolcomp
