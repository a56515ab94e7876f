// The machine a program runs on (control/machine.hpp): the tool change position and the
// travel limits, in machine coordinates. Its origins are placed at start (interp.cpp).
#include <cmath>
#include <cstdio>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::iso {

// M6 on a machine with a tool change position: the axes it names go there at rapid first
// (Haas mill: Z to machine zero), the others stay. (A lathe's machine X is a diameter, as the
// control shows it; the interpreter keeps radii.)
void Interp::to_tool_change_position(int column) {
    const Machine& mc = *opts_.machine;
    Vec6 m = to_machine(pos_);
    bool any = false;
    for (int i = 0; i < 3; ++i)
        if (const auto& v = mc.tool_change[static_cast<std::size_t>(i)]) {
            m[i] = *v / machine_scale(i);
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
        std::string name = c.program;  // LinuxCNC folds a sub's name to lower case, as o<MySub> call
        for (char& ch : name) ch = ascii_lower(ch);
        s.label = "<" + name + ">";
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
// points of its circle where a machine axis has its extreme that it passes (the start was the
// end of the move before). `rotation`: the XY rotation of the coordinate system (radians):
// an XY arc's extremes in machine X and Y lie that much before the program's axes; an arc in
// another plane under a rotation is sampled every 5 degrees besides.
int bounding_points(const Motion& m, double rotation, std::vector<Vec3>& out) {
    out.assign(1, m.end);
    if (!m.is_arc()) return 1;
    const Arc a = m.arc();
    const PlaneAxes ax = axes(a.plane);
    const Vec2 c = in_plane(a.center, a.plane), s = in_plane(a.start, a.plane) - c;
    const double r = s.norm(), phi0 = std::atan2(s.y(), s.x()), sweep = arc_sweep(a);
    const double shift = a.plane == Plane::xy ? -rotation : 0.0;
    const int steps = rotation != 0 && a.plane != Plane::xy ? 72 : 4;
    for (int k = 0; k < steps; ++k) {
        const double theta = k * 2 * kPi / steps + shift;
        // The angle from the start to theta in the arc's direction, in [0, 2 pi).
        double d = a.dir > 0 ? theta - phi0 : phi0 - theta;
        d = std::fmod(d, 2 * kPi);
        if (d < 0) d += 2 * kPi;
        if (d > sweep) continue;
        Vec3 p = a.start;
        p[ax.a] = c.x() + r * std::cos(theta);
        p[ax.b] = c.y() + r * std::sin(theta);
        p[ax.c] = a.start[ax.c] + (a.end[ax.c] - a.start[ax.c]) * (d / sweep);
        out.push_back(p);
    }
    return static_cast<int>(out.size());
}
}  // namespace

void Interp::check_travel(const Motion& m) {
    const Machine& mc = *opts_.machine;
    const int n = bounding_points(m, rotation_[st_.coord_system - 1] * kPi / 180, travel_points_);
    const std::vector<Vec3>& points = travel_points_;
    static constexpr char kName[3] = {'X', 'Y', 'Z'};
    for (int k = 0; k < n; ++k) {
        Vec6 q = pos_;
        q.head<3>() = points[k];
        const Vec6 machine = to_machine(q);
        for (int i = 0; i < 3; ++i) {
            const AxisTravel& t = mc.travel[static_cast<std::size_t>(i)];
            const double v = machine[i] * machine_scale(i);
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
