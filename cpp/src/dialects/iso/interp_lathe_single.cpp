// G-code system A's threading and single cycles (Fanuc T series, Haas lathes), modal in
// group 01: G32 a thread cut along a line, G90 the turning cycle, G92 the threading cycle,
// G94 the facing cycle. Each cycle goes from its start point A and back to it:
//
//   G90 X Z R F   rapid to X (+R), feed to (X, Z), feed out to A's X, rapid back to A's Z
//   G92 X Z R F   the same with a thread cut (F the lead) and a rapid out
//   G94 X Z R F   rapid to Z (+R), feed to (X, Z), feed back to A's Z, rapid back to A's X
//
// R is the taper: how much the cut's start lies beyond its end (X radius for G90/G92, Z for
// G94). A block with only X or Z (U, W) under a cycle repeats it with the other value kept.
// G92's thread ends with the profile's pull-out chamfer (thread_chamfer, Haas M23/M24).
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

// F is the lead (mm or inch per revolution) whatever G98/G99 say; the spindle's speed is S
// (G97), or under G96 the speed at X, held by G50 S.
double Interp::thread_feed(double x_end) const {
    const double rpm = spindle_rpm(x_end);
    return std::isfinite(rpm) ? feed_ * rpm : std::nan("");
}

void Interp::thread_line(const BlockWords& bw) {
    if (feed_ <= 0) fail(code::zero_feed, "G32 needs the lead F", bw.axis_column());
    if (spindle().speed <= 0) fail(code::zero_spindle_speed, "G32 needs the spindle turning (S)", bw.axis_column());
    if (comp_on()) fail(code::unsupported_g_code, "G32 with tool nose radius compensation on is not supported by toolcomp",
                        bw.axis_column());
    const Vec6 end = find_end(bw);
    straight(MotionKind::line, end, thread_feed(end[0]));
}

void Interp::single_cycle(const BlockWords& bw, int code) {
    const int col = bw.g[g_motion] >= 0 ? bw.g_column[g_motion] : bw.axis_column();
    const char* name = code == G90 ? "G90" : code == G92 ? "G92" : "G94";
    if (feed_ <= 0) fail(code::zero_feed, std::string(name) + " needs a feed F", col);
    if (code == G92 ? spindle().speed <= 0 : st_.feed_mode == G95 && spindle().speed <= 0)
        fail(code::zero_spindle_speed, std::string(name) + " needs the spindle turning (S)", col);
    if (comp_on())
        fail(code::unsupported_g_code, std::string(name) + " with tool nose radius compensation on is not supported by toolcomp",
             col);
    for (char c : {'Y', 'I', 'K', 'Q'})
        if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in " + name + " is not supported by toolcomp", bw[c].column);
    // A new cycle (its G code) needs X and Z; a repeat keeps what it does not give.
    const Vec6 end = find_end(bw);
    const bool fresh = bw.g[g_motion] == code;
    if (fresh && !((bw.has('X') || bw.has('U')) && (bw.has('Z') || bw.has('W'))))
        fail(code::cycle_bad_value, std::string("PS0062 ILLEGAL COMMAND IN G71-G76: ") + name + " needs X (U) and Z (W)", col);
    if (bw.has('X') || bw.has('U')) single_.x = end[0];
    if (bw.has('Z') || bw.has('W')) single_.z = end[2];
    single_.r = bw.has('R') ? bw['R'].value : fresh ? 0.0 : single_.r;
    const Vec6 a = pos_;
    auto at = [&](double x, double z) {
        Vec6 p = a;
        p[0] = x;
        p[2] = z;
        return p;
    };
    auto feed_at = [&](const Vec6& e) { return feed_for(bw, G1, 0, e[0]); };
    auto straight = [&](MotionKind k, const Vec6& p, double f) {
        if (p != pos_) Interp::straight(k, p, f);
    };
    if (code == G94) {
        const Vec6 p1 = at(a[0], single_.z + single_.r), p2 = at(single_.x, single_.z), p3 = at(single_.x, a[2]);
        straight(MotionKind::rapid, p1, std::nan(""));
        straight(MotionKind::line, p2, feed_at(p2));
        straight(MotionKind::line, p3, feed_at(p3));
    } else {
        const Vec6 p1 = at(single_.x + single_.r, a[2]), p2 = at(single_.x, single_.z), p3 = at(a[0], single_.z);
        straight(MotionKind::rapid, p1, std::nan(""));
        if (code == G92) {
            thread_cut(p1, p2, thread_chamfer_length(feed_ / scale()), profile_.thread_chamfer_angle, a[0] >= p2[0] ? 1.0 : -1.0);
            straight(MotionKind::rapid, at(a[0], pos_[2]), std::nan(""));
        } else {
            straight(MotionKind::line, p2, feed_at(p2));
            straight(MotionKind::line, p3, feed_at(p3));
        }
    }
    straight(MotionKind::rapid, a, std::nan(""));
    count_block(col);
}

}  // namespace toolcomp::iso
