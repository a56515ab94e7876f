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
#include <algorithm>
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
    if (bw.has('K') || bw.has('D')) return haas_threading(bw, col);
    for (char c : {'I', 'A', 'Y'})
        if (bw.has(c)) fail(code::unsupported_word, std::string(1, c) + " in the two-block G76 is not supported by toolcomp", bw[c].column);
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
    thread_cycle_can_start(col);
    const double height = whole('P') * increment, first = whole('Q') * increment;
    const double rough_to = height - thread_.allowance;
    if (!(first > 0) || !(height > 0) || rough_to <= 0 || thread_.min_depth > height)
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 needs height and first depth above 0, the "
                                    "allowance below the height, the least depth at most the height", col);
    ThreadPasses t;
    t.end = find_end(bw);
    t.height = height;
    t.taper = bw.has('R') ? bw['R'].value : 0.0;
    t.angle = thread_.angle;
    t.chamfer = thread_.chamfer * (feed_ / scale()) / 10;
    t.depths = thread_depths(first, thread_.min_depth, rough_to, col);
    t.depths.push_back(rough_to);
    for (int m = 0; m < thread_.finishing; ++m) t.depths.push_back(height);
    thread_passes(t, col);
}

// Haas's (and Fanuc 15-format) one-block G76: X(U) Z(W) the root at the thread's end, K the
// thread height and D the first depth (program units, radius), A the tool angle (whole
// degrees, 0-120; 0 without A), I the taper (radius), F the lead, P1 (one edge cuts, constant
// cutting amount; the only infeed read). Passes at D·√n, each at least `thread_min_cut`
// deeper, while short of K less `thread_finish_allowance`; then one at K less the allowance
// (when there is one) and one at K. The chamfer is the profile's (settings 95, 96; M23/M24).
void Interp::haas_threading(const BlockWords& bw, int col) {
    for (char c : {'R', 'Q', 'Y'})
        if (bw.has(c))
            fail(code::unsupported_word, std::string(1, c) + " in the one-block G76 is not supported by toolcomp", bw[c].column);
    if (bw.has('P') && bw['P'].value != 1)
        fail(code::unsupported_word, "G76 P2-P4 (other infeeds than P1, one edge with a constant cutting amount) are not "
                                     "supported by toolcomp", bw['P'].column);
    if (!(bw.has('X') || bw.has('U')) || !(bw.has('Z') || bw.has('W')) || !bw.has('K') || !bw.has('D') || !bw.has('F'))
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 needs X (U), Z (W), K (height), D (first depth) and F", col);
    thread_cycle_can_start(col);
    const double height = bw['K'].value, first = bw['D'].value;
    const double allowance = profile_.thread_finish_allowance / scale(), least = profile_.thread_min_cut / scale();
    double angle = 0;
    if (bw.has('A')) {
        angle = bw['A'].value;
        if (angle != std::floor(angle) || angle < 0 || angle > 120)
            fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 A is the tool angle, whole degrees 0-120", bw['A'].column);
    }
    if (!(first > 0) || !(height > 0) || allowance >= height)
        fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 needs K and D above 0, the finishing allowance "
                                    "below K", col);
    ThreadPasses t;
    t.end = find_end(bw);
    t.height = height;
    t.taper = bw.has('I') ? bw['I'].value : 0.0;
    t.angle = angle;
    t.chamfer = thread_chamfer_length(feed_ / scale());
    t.chamfer_angle = profile_.thread_chamfer_angle;
    const double rough_to = height - allowance;
    t.depths = thread_depths(first, least, rough_to, col);
    if (allowance > 0) t.depths.push_back(rough_to);
    t.depths.push_back(height);
    thread_passes(t, col);
}

// What either G76 needs to start: the spindle turning, no nose radius compensation.
void Interp::thread_cycle_can_start(int col) const {
    if (spindle().speed <= 0) fail(code::zero_spindle_speed, "G76 needs the spindle turning (S)", col);
    if (comp_on()) fail(code::unsupported_g_code, "G76 with tool nose radius compensation on is not supported by toolcomp", col);
}

// The depths of the passes short of rough_to: first·√n, each at least `least` deeper.
std::vector<double> Interp::thread_depths(double first, double least, double rough_to, int col) const {
    std::vector<double> depths;
    for (int n = 1;; ++n) {
        double d = first * std::sqrt(static_cast<double>(n));
        if (!depths.empty() && d - depths.back() < least) d = depths.back() + least;
        if (d >= rough_to - 1e-12) return depths;
        depths.push_back(d);
        if (depths.size() > 100000) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: more than 100000 passes", col);
    }
}

double Interp::thread_chamfer_length(double lead) const {
    return thread_chamfer_on_ ? profile_.thread_chamfer * lead : 0.0;
}

// A thread from s to e (F the lead), ending `chamfer` early along Z and pulled out from there
// to e's Z, rising outwards (out: +1 OD, -1 ID) at `angle` degrees from the Z axis.
void Interp::thread_cut(const Vec6& s, const Vec6& e, double chamfer, double angle, double out) {
    const double length = std::fabs(e[2] - s[2]);
    const double gamma = std::min(chamfer, length);
    if (gamma <= 0) {
        if (e != pos_) straight(MotionKind::line, e, thread_feed(e[0]));
        return;
    }
    constexpr double kPi = 3.14159265358979323846;
    const double rise = angle == 45 ? gamma : gamma * std::tan(angle * kPi / 180);
    Vec6 c = e;
    c[2] = e[2] - (e[2] < s[2] ? -1.0 : 1.0) * gamma;
    c[0] = e[0] + (s[0] - e[0]) * gamma / length;  // on the thread's taper
    if (c != pos_) straight(MotionKind::line, c, thread_feed(c[0]));
    Vec6 p = e;
    p[0] = c[0] + out * rise;
    straight(MotionKind::line, p, thread_feed(p[0]));
}

// Each pass: rapid from A to the pass's X, its Z moved along the flank by depth·tan(a/2) in
// the cutting direction, the thread (F the lead) to the end Z, pulled out over the chamfer
// (its length along Z, rising at its angle) when there is one, rapid out to A's X and back
// to A's Z.
void Interp::thread_passes(const ThreadPasses& t, int col) {
    const Vec6& end = t.end;
    const Vec6 a = pos_;
    const double out = a[0] > end[0] ? 1.0 : -1.0;   // OD: the crest lies outwards of the root
    const double dir = end[2] < a[2] ? -1.0 : 1.0;  // the cut's direction along Z
    if (end[2] == a[2]) fail(code::cycle_bad_value, "PS0062 ILLEGAL COMMAND IN G71-G76: G76 with no length along Z", col);
    const double flank = std::tan(t.angle * 3.14159265358979323846 / 360);
    auto go = [&](MotionKind k, Vec6 p, double f) {
        if (p != pos_) straight(k, p, f);
    };
    for (const double d : t.depths) {
        count_block(col);
        const double shift = dir * d * flank;
        const double x_end = end[0] + out * (t.height - d);
        Vec6 s = a, e = a;
        s[0] = x_end + t.taper, s[2] = a[2] + shift;
        e[0] = x_end, e[2] = end[2] + shift;
        go(MotionKind::rapid, s, std::nan(""));
        thread_cut(s, e, t.chamfer, t.chamfer_angle, out);
        Vec6 o = pos_;
        o[0] = a[0];
        go(MotionKind::rapid, o, std::nan(""));
        go(MotionKind::rapid, a, std::nan(""));
    }
}

}  // namespace toolcomp::iso
