#include "travel.hpp"

#include <cmath>
#include <cstdio>

#include "toolcomp/program/codes.hpp"


namespace toolcomp {

namespace {
// The points of a move whose machine coordinates bound it: its end, and for an arc the
// points of its circle where a machine axis has its extreme that it passes (the start was the
// end of the move before). An XY arc's extremes in machine X and Y lie `rotation` before the
// output's axes; an arc in another plane under a rotation is sampled every 5 degrees besides.
void bounding_points(const Motion& m, double rotation, std::vector<Vec3>& out) {
    out.assign(1, m.end);
    if (!m.is_arc()) return;
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
}
}  // namespace

std::optional<std::string> TravelCheck::beyond(const Motion& m, double rotation, const ToMachine& to_machine) {
    static constexpr char kName[3] = {'X', 'Y', 'Z'};
    bounding_points(m, rotation, points_);
    for (const Vec3& p : points_) {
        const Vec3 machine = to_machine(p);
        for (int i = 0; i < 3; ++i) {
            const AxisTravel& t = machine_.travel[static_cast<std::size_t>(i)];
            const double v = machine[i];
            if (v >= t.min - 1e-6 && v <= t.max + 1e-6) continue;
            char msg[200];
            std::snprintf(msg, sizeof msg,
                          "%c %.4f mm (machine coordinates) is beyond the travel of the machine, %c %.4g to %.4g",
                          kName[i], v, kName[i], t.min, t.max);
            return std::string(msg);
        }
    }
    return std::nullopt;
}

void TravelCheck::warn(const std::string& message, const SourcePos& at, std::vector<Diagnostic>& diags) {
    if (warnings_ < 100)
        diags.push_back({code::travel_limit, Severity::warning, message, at});
    else if (warnings_ == 100)
        diags.push_back({code::travel_limit, Severity::info,
                         "More moves beyond the travel limits follow; they are not reported one by one", at});
    ++warnings_;
}

void TravelSink::push(const Motion& m) {
    const double x_scale = machine_.kind == MachineKind::lathe ? 2.0 : 1.0;  // a lathe's machine X: a diameter
    const auto msg = check_.beyond(m, 0.0, [&](const Vec3& p) {
        Vec3 v = (p + m.tool_offset) * m.unit;
        for (int i = 0; i < 3; ++i) v[i] = v[i] * (i == 0 ? x_scale : 1.0) + machine_.work_origin[static_cast<std::size_t>(i)];
        return v;
    });
    if (msg) {
        SourcePos at{m.line, 0, {}, m.file};
        if (check_.stops()) throw ProgramError(code::travel_limit, *msg, at);
        check_.warn(*msg, at, diags_);
    }
    next_.push(m);
}

}  // namespace toolcomp
