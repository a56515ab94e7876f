// The 840D's drilling cycles (CYCLE81-CYCLE89, CYCLE840; their moves in
// cycles/siemens_drilling.hpp), called directly or modally with MCALL (after every following
// block that moves an axis, until MCALL alone), and the position patterns HOLES1, HOLES2 and
// CYCLE801 that run the modal one at each position.
#include <algorithm>
#include <cmath>

#include "../../cycles/siemens_drilling.hpp"
#include "../../cycles/turning_roughing.hpp"  // CycleError, MoveLimit
#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

bool Interp::drilling_cycle_name(const std::string& name) { return cycles::siemens::is_drilling_cycle(name); }

// The arguments, evaluated where the cycle is called (MCALL: once, at the MCALL block); an
// empty one is 0, as for any omitted parameter.
std::vector<double> Interp::cycle_arguments(const std::string& name, const std::string& text, int column) {
    return evaluate_arguments(name, text, cycles::siemens::parameter_count(name), column);
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

// The cycle's moves (cycles/siemens_drilling.hpp) from where the tool stands: its drilling
// axis, the hole's centre in the other two.
void Interp::drilling_cycle(const std::string& name, const std::vector<double>& args, int column) {
    if (st_.side != 0) fail(code::alarm_10750, "10750 " + name + " with tool radius compensation (G41/G42) active", column);
    const PlaneAxes ax = axes(st_.plane);
    const int along = cycles::siemens::drilling_axis(name, args);
    const int axis = along == 1 ? ax.a : along == 2 ? ax.b : ax.c;
    const int lift_a = along == 1 ? ax.b : along == 2 ? ax.c : ax.a;  // the plane across the drilling axis
    const int lift_b = along == 1 ? ax.c : along == 2 ? ax.a : ax.b;
    const double u = unit();
    const Vec3 centre = program_pos();
    cycles::siemens::Setting s;
    s.feed = feed_;
    s.unit = u;
    s.from = centre[axis] / u;
    s.speed = speed_;
    s.feed_unit = st_.inch_feed ? kMmPerInch : 1.0;
    s.max_moves = profile_.block_limit - std::min(executed_, profile_.block_limit);
    std::vector<cycles::siemens::Step> steps;
    try {
        steps = cycles::siemens::drilling(name, args, s);
    } catch (const cycles::MoveLimit&) {
        fail(code::block_limit, "More than " + std::to_string(profile_.block_limit) +
                                    " blocks executed, cycle moves included: an endless loop? (ControlProfile.block_limit)",
             column);
    } catch (const cycles::CycleError& e) {
        fail(e.code, e.message, column);
    }
    if (name == "CYCLE83" && !steps.empty() && !(std::fabs(args.size() > 10 ? args[10] : 0.0) > 0.001))
        diags_.push_back({code::cycle_feed_factor, Severity::warning,
                          "CYCLE83 without a feed factor FRF (or FRF <= 0.001): its first stroke runs at 0.001 x F, as "
                          "the 840D's cycle does",
                          {line_, column}});
    for (const cycles::siemens::Step& st : steps)
        if (st.how != cycles::siemens::Feed::rapid && !(st.feed > 0))
            fail(code::alarm_10860, "10860 No feedrate programmed", column);
    executed_ += steps.size();
    const double caller_feed = feed_;
    for (const cycles::siemens::Step& st : steps) {
        Vec3 e = centre;
        e[axis] = st.to * u;
        e[lift_a] += st.a * u;
        e[lift_b] += st.b * u;
        const Vec3 out = actual_.apply(e) + zero_shift_;
        Motion m = motion_(st.how == cycles::siemens::Feed::rapid ? MotionKind::rapid : MotionKind::line, out);
        if (st.how == cycles::siemens::Feed::programmed) {
            feed_ = st.feed;
            m.feed = feed_rate(out);
            feed_ = caller_feed;
        } else if (st.how == cycles::siemens::Feed::per_minute) {
            m.feed = st.feed;
        }
        pos_ = out;
        ++moves_;
        sink_.push(m);
    }
}

// HOLES1(SPCA, SPCO, STA1, FDIS, DBH, NUM): NUM holes on a line from (SPCA, SPCO) at the
// angle STA1, the first FDIS from it, DBH apart, run from the end nearer the workpiece zero;
// HOLES2(CPA, CPO, RAD, STA1, INDA, NUM): NUM holes on the circle about (CPA, CPO), from STA1
// INDA apart (0: evenly on the full circle). At each hole a G0 in the plane, then the cycle
// MCALL made modal (without one: warning 62100, the positions only).
void Interp::hole_pattern(const std::string& name, const std::string& text, int column) {
    const bool grid = name == "CYCLE801";
    std::vector<double> a = evaluate_arguments(name, text, grid ? 7 : 6, column);
    a.resize(7, 0.0);
    auto count = [&](double v) {
        const double n = std::fabs(v);
        if (n != std::floor(n) || n > 100000) fail(code::cycle_bad_value, name + ": a number of holes is a whole number", column);
        return static_cast<int>(n);
    };
    const double deg = kPi / 180;
    std::vector<Vec2> holes;
    if (grid) {
        holes = grid_holes(a, count(a[5]), count(a[6]), column);
    } else {
        const int n = count(a[5]);
        if (n == 0) fail(code::alarm_61103, "61103 Number of holes is zero", column);
        if (name == "HOLES1") {
            const Vec2 dir(std::cos(a[2] * deg), std::sin(a[2] * deg));
            for (int i = 0; i < n; ++i) holes.push_back(Vec2(a[0], a[1]) + (a[3] + i * a[4]) * dir);
            if (holes.front().norm() > holes.back().norm()) std::reverse(holes.begin(), holes.end());
        } else {
            const double step = a[4] == 0 ? 360.0 / n : a[4];
            for (int i = 0; i < n; ++i)
                holes.push_back(Vec2(a[0], a[1]) + a[2] * Vec2(std::cos((a[3] + i * step) * deg), std::sin((a[3] + i * step) * deg)));
        }
    }
    if (!modal_call_)
        diags_.push_back({code::alarm_62100, Severity::warning, "62100 No drilling cycle active (" + name + " without MCALL)",
                          {line_, column}});
    const PlaneAxes ax = axes(st_.plane);
    for (const Vec2& h : holes) {
        Vec3 e = program_pos();
        e[ax.a] = h.x() * unit();
        e[ax.b] = h.y() * unit();
        const Vec3 out = actual_.apply(e) + zero_shift_;
        Motion m = motion_(MotionKind::rapid, out);
        pos_ = out;
        ++moves_;
        sink_.push(m);
        if (modal_call_) drilling_cycle(modal_call_->name, modal_call_->args, column);
    }
}

// CYCLE801(_SPCA, _SPCO, _STA, _DIS1, _DIS2, _NUM1, _NUM2): a grid of _NUM1 columns _DIS1
// apart along the abscissa turned by _STA about (_SPCA, _SPCO), and _NUM2 lines _DIS2 apart.
// Run line by line along the smaller spacing, turning back at each line's end (meander), from
// the corner nearer the tool: a line starts at the low end where the tool stands at or before
// the grid's middle, as the 840D's cycle compares them. A count of 0: warning 62105, taken as 1.
std::vector<Vec2> Interp::grid_holes(const std::vector<double>& a, int num1, int num2, int column) {
    if (num1 == 0 || num2 == 0) {
        diags_.push_back({code::alarm_62105, Severity::warning, "62105 Number of columns or lines is zero", {line_, column}});
        num1 = std::max(num1, 1);
        num2 = std::max(num2, 1);
    }
    const double dis1 = std::fabs(a[3]), dis2 = std::fabs(a[4]), rad = a[2] * kPi / 180;
    const Vec2 origin(a[0], a[1]), ex(std::cos(rad), std::sin(rad)), ey(-std::sin(rad), std::cos(rad));
    const PlaneAxes ax = axes(st_.plane);
    const Vec3 here = program_pos();
    const Vec2 tool = Vec2(here[ax.a] / unit(), here[ax.b] / unit()) - origin;
    const Vec2 t(tool.dot(ex), tool.dot(ey));  // the tool in the grid's own axes
    const bool rows = dis1 <= dis2;            // inner runs along the abscissa
    const int inner = rows ? num1 : num2, outer = rows ? num2 : num1;
    const double din = rows ? dis1 : dis2, dout = rows ? dis2 : dis1;
    const double tin = rows ? t.x() : t.y(), tout = rows ? t.y() : t.x();
    const bool out_up = (outer - 1) * dout / 2 >= tout, in_up = (inner - 1) * din / 2 >= tin;
    std::vector<Vec2> holes;
    for (int j = 0; j < outer; ++j) {
        const double v = (out_up ? j : outer - 1 - j) * dout;
        for (int i = 0; i < inner; ++i) {
            const bool up = (j % 2 == 0) == in_up;
            const double w = (up ? i : inner - 1 - i) * din;
            const Vec2 g = rows ? Vec2(w, v) : Vec2(v, w);
            holes.push_back(origin + g.x() * ex + g.y() * ey);
        }
    }
    return holes;
}

}  // namespace toolcomp::sinumerik
