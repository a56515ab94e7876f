// The machine a program runs on (control/machine.hpp): the tool change position and the
// travel limits, in machine coordinates. Its origins are placed at start (interp.cpp).
#include <cmath>
#include "toolcomp/program/codes.hpp"
#include <cstdio>

#include "interp.hpp"

namespace toolcomp::iso {

// M6 on a machine with a tool change position: the axes it names go there at rapid first
// (Haas mill: Z to machine zero), the others stay.
void Interp::to_tool_change_position(int column) {
    const Machine& mc = *opts_.machine;
    const double u = scale();  // mm per program unit
    Vec6 m = to_machine(pos_);
    bool any = false;
    for (int i = 0; i < 3; ++i)
        if (const auto& v = mc.tool_change[static_cast<std::size_t>(i)]) {
            m[i] = *v / u;
            any = true;
        }
    if (!any) return;
    if (comp_on()) fail(code::comp_tool_change, "Cannot change tools with cutter radius compensation on", column);
    const Vec6 end = from_machine(m);
    if (end != pos_) straight(MotionKind::rapid, end, std::nan(""));
}

// A builder M code that runs a subprogram, after the rest of its block: LinuxCNC as
// o<program> call (a remap to an O-word sub), Fanuc as M98 P<number>.
void Interp::machine_subprogram(const MachineCode& c, int column) {
    if (prog_.dialect == Dialect::linuxcnc) {
        Statement s;
        s.kind = Stmt::o_call;
        s.column = column;
        s.label = "<" + c.program + ">";
        call_sub(s);
        return;
    }
    const std::string n = c.program[0] == 'O' || c.program[0] == 'o' ? c.program.substr(1) : c.program;
    WordSlot p;
    p.value = std::stod(n);
    p.column = column;
    p.set = true;
    call_program(Frame::m98, p, WordSlot{}, column);
}

namespace {
// The points of a move whose machine coordinates bound it: its end, and for an arc the
// points of its circle at 0, 90, 180 and 270 degrees that it passes (the extremes of each
// plane axis; the start was the end of the move before).
int bounding_points(const Motion& m, Vec3 (&out)[5]) {
    out[0] = m.end;
    if (!m.is_arc()) return 1;
    const Arc a = m.arc();
    const PlaneAxes ax = axes(a.plane);
    const Vec2 c = in_plane(a.center, a.plane), s = in_plane(a.start, a.plane) - c;
    const double r = s.norm(), phi0 = std::atan2(s.y(), s.x()), sweep = arc_sweep(a);
    int n = 1;
    for (int k = 0; k < 4; ++k) {
        const double theta = k * kPi / 2;
        // The angle from the start to theta in the arc's direction, in [0, 2 pi).
        double d = a.dir > 0 ? theta - phi0 : phi0 - theta;
        d = std::fmod(d, 2 * kPi);
        if (d < 0) d += 2 * kPi;
        if (d > sweep) continue;
        Vec3 p = a.start;
        p[ax.a] = c.x() + r * std::cos(theta);
        p[ax.b] = c.y() + r * std::sin(theta);
        p[ax.c] = a.start[ax.c] + (a.end[ax.c] - a.start[ax.c]) * (d / sweep);
        out[n++] = p;
    }
    return n;
}
}  // namespace

void Interp::check_travel(const Motion& m) {
    const Machine& mc = *opts_.machine;
    Vec3 points[5];
    const int n = bounding_points(m, points);
    static constexpr char kName[3] = {'X', 'Y', 'Z'};
    for (int k = 0; k < n; ++k) {
        Vec6 q = pos_;
        q.head<3>() = points[k];
        const Vec6 machine = to_machine(q) * scale();
        for (int i = 0; i < 3; ++i) {
            const AxisTravel& t = mc.travel[static_cast<std::size_t>(i)];
            const double v = machine[i];
            if (v >= t.min - 1e-6 && v <= t.max + 1e-6) continue;
            char msg[200];
            std::snprintf(msg, sizeof msg,
                          "%c %.4f mm (machine coordinates) is beyond the travel of the machine, %c %.4g to %.4g",
                          kName[i], v, kName[i], t.min, t.max);
            if (!mc.travel_limit_warning) fail(code::travel_limit, msg);
            if (travel_warnings_ < 100)
                diags_.push_back({code::travel_limit, Severity::warning, msg, {line_, 0, file_name()}});
            else if (travel_warnings_ == 100)
                diags_.push_back({code::travel_limit, Severity::info,
                                  "More moves beyond the travel limits follow; they are not reported one by one",
                                  {line_, 0, file_name()}});
            ++travel_warnings_;
            return;  // one report a move
        }
    }
}

}  // namespace toolcomp::iso
