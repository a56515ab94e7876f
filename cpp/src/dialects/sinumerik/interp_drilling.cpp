// The 840D's drilling cycles CYCLE81 (drilling, centring) and CYCLE82 (with a dwell at the
// depth), called directly or modally with MCALL (after every following block that moves an
// axis, until MCALL alone). Their moves, as the SW6 cycles make them, along the applicate of
// the active plane: G0 to the safety plane RFP + SDIS (towards the retraction side), G1 to the
// depth at the caller's feed, (CYCLE82: the dwell DTB), G0 to the retraction plane RTP.
#include <algorithm>
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

bool Interp::drilling_cycle_name(const std::string& name) { return name == "CYCLE81" || name == "CYCLE82"; }

// The arguments, evaluated where the cycle is called (MCALL: once, at the MCALL block); an
// empty one is 0, as for any omitted parameter.
std::vector<double> Interp::cycle_arguments(const std::string& name, const std::string& text, int column) {
    return evaluate_arguments(name, text, name == "CYCLE81" ? 8 : 9, column);  // 840D sl: + GMODE, DMODE, AMODE
}

std::vector<double> Interp::evaluate_arguments(const std::string& name, const std::string& text, std::size_t most,
                                                int column) {
    std::vector<double> out;
    if (text.find_first_not_of(" \t") == std::string::npos) return out;
    for (const std::string& a : split_args(text)) out.push_back(a.empty() ? 0.0 : eval_text(a, column));
    if (out.size() > most)
        fail(code::alarm_12340, "12340 Number of parameters too high: " + name + " takes " + std::to_string(most), column);
    return out;
}

void Interp::drilling_cycle(const std::string& name, const std::vector<double>& args, int column) {
    auto arg = [&](std::size_t i) { return i < args.size() ? args[i] : 0.0; };
    const std::size_t modes = name == "CYCLE81" ? 5 : 6;  // GMODE, DMODE, AMODE follow
    if (arg(modes) != 0)
        fail(code::unsupported_word, name + " with GMODE " + shortest_number(arg(modes)) + " is not supported by toolcomp", column);
    if (arg(modes + 2) != 0 && arg(modes + 2) != 10)
        fail(code::unsupported_word, name + " with AMODE " + shortest_number(arg(modes + 2)) +
                                         " is not supported by toolcomp (0 or 10: depth from DP / DPR, dwell in seconds)",
             column);
    if (st_.side != 0) fail(code::alarm_10750, "10750 " + name + " with tool radius compensation (G41/G42) active", column);
    const double rtp = arg(0), rfp = arg(1), sdis = std::fabs(arg(2)), dpr = std::fabs(arg(4));
    double dp = arg(3);
    auto sign = [](double v) { return static_cast<double>((v > 0) - (v < 0)); };
    if (dpr != 0) {
        if (rtp == rfp) fail(code::alarm_61101, "61101 Reference plane defined incorrectly", column);
        dp = rfp - sign(rtp - rfp) * dpr;
    }
    if (rfp == dp) return;  // no depth: the cycle makes no move
    const double d = sign(rfp - dp);
    if (rtp != rfp && sign(rtp - rfp) != d) fail(code::alarm_61101, "61101 Reference plane defined incorrectly", column);
    if (!(feed_ > 0)) fail(code::alarm_10860, "10860 No feedrate programmed", column);
    const int axis = axes(st_.plane).c;
    const double u = unit();
    axis_move(axis, (rfp + d * sdis) * u, MotionKind::rapid);
    axis_move(axis, dp * u, MotionKind::line);
    axis_move(axis, rtp * u, MotionKind::rapid);
}

// HOLES1(SPCA, SPCO, STA1, FDIS, DBH, NUM): NUM holes on a line from (SPCA, SPCO) at the
// angle STA1, the first FDIS from it, DBH apart, run from the end nearer the workpiece zero;
// HOLES2(CPA, CPO, RAD, STA1, INDA, NUM): NUM holes on the circle about (CPA, CPO), from STA1
// INDA apart (0: evenly on the full circle). At each hole a G0 in the plane, then the cycle
// MCALL made modal (without one: warning 62100, the positions only).
void Interp::hole_pattern(const std::string& name, const std::string& text, int column) {
    std::vector<double> a = evaluate_arguments(name, text, 6, column);
    a.resize(6, 0.0);
    const double num = std::fabs(a[5]);
    if (num != std::floor(num) || num > 100000) fail(code::cycle_bad_value, name + ": NUM is a number of holes", column);
    const int n = static_cast<int>(num);
    if (n == 0) fail(code::alarm_61103, "61103 Number of holes is zero", column);
    const double deg = kPi / 180;
    std::vector<Vec2> holes;
    if (name == "HOLES1") {
        const Vec2 dir(std::cos(a[2] * deg), std::sin(a[2] * deg));
        for (int i = 0; i < n; ++i) holes.push_back(Vec2(a[0], a[1]) + (a[3] + i * a[4]) * dir);
        if (holes.front().norm() > holes.back().norm()) std::reverse(holes.begin(), holes.end());
    } else {
        const double step = a[4] == 0 ? 360.0 / n : a[4];
        for (int i = 0; i < n; ++i)
            holes.push_back(Vec2(a[0], a[1]) + a[2] * Vec2(std::cos((a[3] + i * step) * deg), std::sin((a[3] + i * step) * deg)));
    }
    if (!modal_call_)
        diags_.push_back({code::alarm_62100, Severity::warning, "62100 No drilling cycle active (" + name + " without MCALL)",
                          {line_, column}});
    const PlaneAxes ax = axes(st_.plane);
    for (const Vec2& h : holes) {
        Vec3 e = program_pos();
        e[ax.a] = h.x() * unit();
        e[ax.b] = h.y() * unit();
        const Vec3 out = frame_.apply(e) + zero_shift_;
        Motion m = motion_(MotionKind::rapid, out);
        pos_ = out;
        ++moves_;
        sink_.push(m);
        if (modal_call_) drilling_cycle(modal_call_->name, modal_call_->args, column);
    }
}

// A move of the tool axis alone to `to` (program coordinates, mm), the others where they are.
void Interp::axis_move(int axis, double to, MotionKind kind) {
    Vec3 e = program_pos();
    e[axis] = to;
    const Vec3 out = frame_.apply(e) + zero_shift_;
    Motion m = motion_(kind, out);
    pos_ = out;
    ++moves_;
    sink_.push(m);
}

}  // namespace toolcomp::sinumerik
