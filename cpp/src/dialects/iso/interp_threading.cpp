// G76, the Fanuc T series' multiple threading cycle, in its two-block form:
//
//   G76 P(m)(r)(a) Q(Δdmin) R(d)        m finishing passes, chamfer r (tenths of the lead),
//                                       tool angle a; least depth of a pass; finishing allowance
//   G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)  the thread's root X and end Z, taper i (radius, the
//                                       start's minus the end's), thread height k, first depth
//                                       Δd, lead L
//
// P and Q are read as the control reads them: whole numbers in least input increments
// (0.001 mm, 0.0001 inch), Q100 = 0.1 mm. Each pass, at depth Δd·√n (n = 1, 2, ...; at least
// Δdmin deeper than the one before) until k - d, then m passes at k: rapid from the start point
// A to the pass's X, its Z moved along the thread's flank by depth·tan(a/2) in the cutting
// direction (one edge cuts), the thread (F the lead) to the end Z (pulled out at 45 degrees
// over the chamfer r·L/10 when r > 0), rapid out to A's X, rapid back to A's Z.
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

double Interp::whole_count(const BlockWords& bw, char c, const char* cycle) const {
    if (!bw.has(c)) return 0.0;
    const double v = bw[c].value;
    if (v != std::floor(v) || v < 0)
        fail(code::cycle_bad_value, std::string("PS0062 ILLEGAL COMMAND IN G71-G76: ") + cycle + " " + c +
                                        " is a whole number of least increments, 0 or more", bw[c].column);
    return v;
}

void Interp::threading_cycle(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    const double increment = least_increment();
    auto whole = [&](char c) { return whole_count(bw, c, "G76"); };
    for (char c : {'I', 'K', 'D', 'A', 'Y'})
        if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in G76 is not supported by toolcomp (the one-block form)", bw[c].column);
    const bool end_words = bw.has('X') || bw.has('U') || bw.has('Z') || bw.has('W');
    if (!end_words) {  // G76 P(m)(r)(a) Q(Δdmin) R(d)
        if (bw.has('F')) fail(code::unsupported_word, "F in the first G76 block", bw['F'].column);
        if (bw.has('P')) {
            const long p = std::lround(whole('P'));
            thread_.finishing = static_cast<int>(p / 10000);
            thread_.chamfer = static_cast<int>(p / 100 % 100);
            thread_.angle = static_cast<int>(p % 100);
            const int a = thread_.angle;
            if (p >= 1000000 || thread_.finishing < 1 || (a != 80 && a != 60 && a != 55 && a != 30 && a != 29 && a != 0))
                fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 P is mmrraa: 1-99 finishing passes, "
                                            "chamfer 0-99, tool angle 80, 60, 55, 30, 29 or 0",
                     bw['P'].column);
        }
        if (bw.has('Q')) thread_.min_depth = whole('Q') * increment;
        if (bw.has('R')) {
            if (bw['R'].value < 0) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 R below 0", bw['R'].column);
            thread_.allowance = bw['R'].value;
        }
        return;
    }
    if (!(bw.has('X') || bw.has('U')) || !(bw.has('Z') || bw.has('W')) || !bw.has('P') || !bw.has('Q') || !bw.has('F'))
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 needs X (U), Z (W), P (height), Q (first depth) and F", col);
    if (speed_ <= 0) fail(code::zero_spindle_speed, "G76 needs the spindle turning (S)", col);
    if (comp_on()) fail(code::unsupported_g_code, "G76 with tool nose radius compensation on is not supported by toolcomp", col);
    const double height = whole('P') * increment, first = whole('Q') * increment;
    const double taper = bw.has('R') ? bw['R'].value : 0.0;
    const double rough_to = height - thread_.allowance;
    if (!(first > 0) || !(height > 0) || rough_to <= 0 || thread_.min_depth > height)
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 needs height and first depth above 0, the "
                                    "allowance below the height, the least depth at most the height", col);
    const Vec6 end = find_end(bw);
    const Vec6 a = pos_;
    const double out = a[0] > end[0] ? 1.0 : -1.0;   // OD: the crest lies outwards of the root
    const double dir = end[2] < a[2] ? -1.0 : 1.0;  // the cut's direction along Z
    if (end[2] == a[2]) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 with no length along Z", col);
    const double flank = std::tan(thread_.angle * 3.14159265358979323846 / 360);
    const double lead = feed_ / scale();  // F in program units per revolution
    const double gamma = thread_.chamfer * lead / 10;
    std::vector<double> depths;
    for (int n = 1;; ++n) {
        double d = first * std::sqrt(static_cast<double>(n));
        if (!depths.empty() && d - depths.back() < thread_.min_depth) d = depths.back() + thread_.min_depth;
        if (d >= rough_to - 1e-12) break;
        depths.push_back(d);
        if (depths.size() > 100000) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: more than 100000 passes", col);
    }
    depths.push_back(rough_to);
    for (int m = 0; m < thread_.finishing; ++m) depths.push_back(height);
    auto go = [&](MotionKind k, Vec6 p, double f) {
        if (p != pos_) straight(k, p, f);
    };
    for (const double d : depths) {
        count_block(col);
        const double shift = dir * d * flank;
        const double x_end = end[0] + out * (height - d);
        Vec6 s = a, e = a;
        s[0] = x_end + taper, s[2] = a[2] + shift;
        e[0] = x_end, e[2] = end[2] + shift;
        go(MotionKind::rapid, s, std::nan(""));
        if (gamma > 0) {
            Vec6 c = e;  // the chamfer: the thread ends gamma early, then pulls out at 45 degrees
            c[2] -= dir * gamma;
            c[0] = e[0] + taper * gamma / std::fabs(e[2] - s[2]);
            go(MotionKind::line, c, thread_feed(c[0]));
            e[0] = c[0] + out * gamma;
            go(MotionKind::line, e, thread_feed(e[0]));
        } else {
            go(MotionKind::line, e, thread_feed(e[0]));
        }
        Vec6 o = e;
        o[0] = a[0];
        go(MotionKind::rapid, o, std::nan(""));
        go(MotionKind::rapid, a, std::nan(""));
    }
}

}  // namespace toolcomp::iso
