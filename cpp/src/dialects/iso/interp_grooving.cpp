// G74 (end face peck drilling: pecks along Z, grooves side by side in X) and G75 (grooving:
// pecks along X, grooves side by side in Z) of the Fanuc T series, two-block form:
//
//   G74 R(e)                          the return after each peck
//   G74 X(U) Z(W) P(Δi) Q(Δk) F       G74: P the shift in X, Q the peck depth in Z
//   G75 R(e)
//   G75 X(U) Z(W) P(Δi) Q(Δk) F       G75: P the peck depth in X (radius), Q the shift in Z
//
// P and Q are whole numbers of least increments (0.001 mm, 0.0001 inch). From the start point
// A, each groove: pecks at feed, each `peck` deeper than the last, rapid back by e after each
// but the last, which ends at the target; rapid back to A's level; rapid over by the shift to
// the next groove, the last one at the target. Then rapid back to A. The relief R(Δd) at the
// bottom of a groove is refused unless 0.
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

void Interp::peck_cycle(const BlockWords& bw, int code) {
    const int col = bw.g_column[g_nonmodal];
    const bool g75 = code == G75;
    const std::string name = g75 ? "G75" : "G74";
    for (char c : {'I', 'K', 'D', 'Y'})
        if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in " + name + " is not supported by toolcomp", bw[c].column);
    const bool target = bw.has('X') || bw.has('U') || bw.has('Z') || bw.has('W');
    if (!target) {  // G74 R(e) / G75 R(e)
        if (bw.has('R')) {
            if (bw['R'].value < 0) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: " + name + " R below 0", bw['R'].column);
            peck_return_ = bw['R'].value;
        }
        return;
    }
    if (bw.has('R') && bw['R'].value != 0)
        fail(code::unsupported_word, "R (the relief at the bottom) in " + name + " is not supported by toolcomp unless 0",
             bw['R'].column);
    if (feed_ <= 0) fail(code::zero_feed, "Cannot feed with zero feed rate in " + name, col);
    check_feed_per_rev(col);
    if (comp_on()) fail(code::unsupported_g_code, name + " with tool nose radius compensation on is not supported by toolcomp", col);
    auto whole = [&](char c) { return whole_count(bw, c, name.c_str()) * least_increment(); };
    // Peck along axis p, grooves side by side along axis s (X = 0, Z = 2).
    const int p = g75 ? 0 : 2, s = g75 ? 2 : 0;
    const double peck = whole(g75 ? 'P' : 'Q'), shift = whole(g75 ? 'Q' : 'P');
    const Vec6 end = find_end(bw), a = pos_;
    const double dirp = end[p] > a[p] ? 1.0 : end[p] < a[p] ? -1.0 : 0.0;
    const double dirs = end[s] > a[s] ? 1.0 : end[s] < a[s] ? -1.0 : 0.0;
    if (dirs != 0 && shift <= 0)
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: " + name + " moves to a second groove with no shift (" +
                                        (g75 ? "Q" : "P") + ")", col);
    const double back = peck_return_ >= 0 ? peck_return_ : profile_.turning_escape / scale();
    if (std::fabs(end[s] - a[s]) / std::max(shift, 1e-12) > 1e6 || (peck > 0 && std::fabs(end[p] - a[p]) / peck > 1e6))
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: " + name + " with more than a million pecks or grooves", col);
    auto go = [&](MotionKind k, const Vec6& q) {
        if (q != pos_) straight(k, q, k == MotionKind::rapid ? std::nan("") : feed_for(bw, G1, 0, q[0]));
    };
    double at = a[s];
    for (bool last = false; !last;) {
        last = dirs == 0 || (end[s] - at) * dirs <= 1e-9;
        if (last) at = end[s];
        Vec6 q = a;
        q[s] = at;
        go(MotionKind::rapid, q);
        double depth = a[p];
        for (;;) {
            count_block(col);
            const bool bottom = peck <= 0 || (end[p] - (depth + dirp * peck)) * dirp <= 1e-9;
            depth = bottom ? end[p] : depth + dirp * peck;
            q[p] = depth;
            go(MotionKind::line, q);
            if (bottom) break;
            q[p] = depth - dirp * back;
            go(MotionKind::rapid, q);
        }
        q[p] = a[p];
        go(MotionKind::rapid, q);
        at += dirs * shift;
    }
    go(MotionKind::rapid, a);
}

}  // namespace toolcomp::iso
