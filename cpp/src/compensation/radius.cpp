// Cutter radius compensation: entry, joints, exit and the held-back queue. The decisions and
// formulas are those of LinuxCNC's interpreter (convert_straight_comp1/2, convert_arc_comp1/2,
// move_endpoint_and_flush), restated in plane coordinates (a, b) with applicate h.
#include "toolcomp/compensation/radius.hpp"

#include <cmath>

#include "radius_math.hpp"

namespace toolcomp {

using namespace radius_math;


Vec3 RadiusCompensation::with_plane(Vec3 v, const Vec2& ab) const {
    auto ax = axes(plane_);
    v[ax.a] = ab.x();
    v[ax.b] = ab.y();
    return v;
}

void RadiusCompensation::fail(const char* code, const std::string& msg, int line) const {
    throw CompensationError(code, msg, {line, 0});
}

// ---- output -------------------------------------------------------------------------------

void RadiusCompensation::emit(Motion m) {
    // Lathe tools: the controlled point is the imaginary tip, the nose centre shifted by the
    // nose radius per orientation (LinuxCNC numbering; only in the ZX plane).
    const int o = m.radius.orientation;
    const double r = m.radius.radius;
    if (m.plane == Plane::zx && r > 0 && o >= 1 && o <= 8) {
        double dx = (o == 1 || o == 2 || o == 6) ? -r : (o == 3 || o == 4 || o == 8) ? r : 0;
        double dz = (o == 2 || o == 3 || o == 7) ? -r : (o == 1 || o == 4 || o == 5) ? r : 0;
        m.end.x() += dx;
        m.end.z() += dz;
        if (m.is_arc()) {
            m.center.x() += dx;
            m.center.z() += dz;
        }
    }
    if (have_out_) m.start = last_out_;
    if (m.is_arc()) m.center[axes(m.plane).c] = m.start[axes(m.plane).c];
    last_out_ = m.end;
    have_out_ = true;
    out_.push(m);
}

void RadiusCompensation::passthrough(const Motion& m) {
    Motion o = m;
    if (!exit_pending_) {
        last_out_ = m.end;
        have_out_ = true;
        out_.push(o);
        return;
    }
    // The exit move runs from the last compensated point to the programmed target.
    exit_pending_ = false;
    emit(o);
}

void RadiusCompensation::hold(Motion m, const Vec2& dir, double sweep) { queue_.push_back({std::move(m), dir, sweep}); }

void RadiusCompensation::flush() {
    for (auto& h : queue_) emit(h.m);
    queue_.clear();
    endpoint_valid_ = false;
}

// Every held move gets the new in-plane end point x; a pulled-back move that would now run
// against its programmed direction (or an arc that would sweep further) gouges.
void RadiusCompensation::move_end_and_flush(const Vec2& x, int line, bool check) {
    if (queue_.empty()) return;
    for (auto& h : queue_) {
        Motion& m = h.m;
        if (m.is_arc()) {
            Vec2 c = plane2(m.center);
            double r1 = (plane2(m.end) - c).norm();
            m.end = with_plane(m.end, x);
            double r2 = (x - c).norm();
            double sweep = find_turn(endpoint_, c, turn_of(m), x);
            if (std::fabs(r1 - r2) > 0.01)
                fail("comp_invalid_arc", "BUG: cutter compensation has generated an invalid arc with mismatched radii",
                     line);
            if (check && h.sweep != 0 && endpoint_valid_ &&
                std::fabs(sweep) > std::fabs(h.sweep) + profile_.radius.arc_sweep_tolerance)
                fail("comp_gouge", profile_.radius.messages.gouge_arc, line);
        } else {
            double dot = h.dir.dot(x - endpoint_);
            if (check && endpoint_valid_ && dot < 0)
                fail("comp_gouge",
                     m.kind == MotionKind::rapid ? profile_.radius.messages.gouge_traverse
                                                 : profile_.radius.messages.gouge_feed,
                     line);
            m.end = with_plane(m.end, x);
        }
    }
    flush();
    endpoint_ = x;
    endpoint_valid_ = true;
}

// ---- entry --------------------------------------------------------------------------------

void RadiusCompensation::entry_line(const Motion& m) {
    const Vec2 c = plane2(m.start), p = plane2(m.end);
    if ((p - c).norm() <= r_)
        fail("comp_entry_too_short", profile_.radius.messages.entry_too_short, m.line);
    // Perpendicular to the entry move itself, at its programmed end.
    const double alpha = ang(p - c) + (side_ > 0 ? kHalfPi : -kHalfPi);
    const Vec2 e = p + r_ * u(alpha);
    endpoint_ = c;
    endpoint_valid_ = true;
    Motion h = m;
    h.end = with_plane(m.end, e);
    // The reversal check of an entry move compares with its normal (LinuxCNC): never fails.
    hold(h, u(alpha), 0);
    current_ = h.end;
    program_ = m.end;
}

void RadiusCompensation::entry_arc(const Motion& m) {
    const Vec2 c = plane2(m.start), p = plane2(m.end), centre = plane2(m.center);
    const int turn = turn_of(m);
    if ((p - c).norm() <= r_)
        fail("comp_entry_too_short", profile_.radius.messages.entry_arc_too_short, m.line);
    if ((centre - c).norm() <= r_ && tool_inside(side_, turn))
        fail("comp_arc_too_small", profile_.radius.messages.arc_too_small, m.line);
    const double gamma = tool_inside(side_, turn) ? ang(centre - p) : ang(p - centre);
    const Vec2 e = p + r_ * u(gamma);
    // New centre: on the line from the compensated end to the programmed centre, equally far
    // from the start (the uncompensated current point) and the compensated end.
    const double b_len = (c - e).norm() / 2;
    const double ab = ang(centre - e);
    const double a = ang(c - e) - ab;
    if (std::fabs(std::cos(a)) < 1e-6) fail("comp_arc_too_small", profile_.radius.messages.arc_too_small, m.line);
    const Vec2 cn = e + (b_len / std::cos(a)) * u(ab);
    endpoint_valid_ = false;
    const bool lathe_tool = m.radius.orientation != 0 && m.radius.orientation != 9;
    if (lathe_tool) {
        // Move the tool origin to the nose-centre start first, so the arc stays an arc.
        Motion s = m;
        s.kind = MotionKind::line;
        s.end = m.start;
        s.center = Vec3::Constant(std::nan(""));
        s.turns = 0;
        s.generated = true;
        hold(s, Vec2::Zero(), 0);
        endpoint_ = c;
        endpoint_valid_ = true;
    }
    Motion h = m;
    h.end = with_plane(m.end, e);
    h.center = with_plane(m.center, cn);
    hold(h, Vec2::Zero(), find_turn(c, cn, turn, e));
    current_ = h.end;
    program_ = m.end;
}

// ---- stream -------------------------------------------------------------------------------

void RadiusCompensation::push(const Motion& m) {
    if (m.is_arc() && arc_not_allowed_) fail("comp_exit_arc", profile_.radius.messages.exit_arc, m.line);
    if (m.radius.side == 0 || m.radius.radius <= 0) {
        if (!m.is_arc()) arc_not_allowed_ = false;
        passthrough(m);
        return;
    }
    if (!active_) {
        plane_ = m.plane;
        side_ = m.radius.side;
        r_ = m.radius.radius;
        arc_not_allowed_ = false;
        if (m.is_arc() && !profile_.radius.entry_arc) fail("comp_entry_arc", profile_.radius.messages.entry_arc, m.line);
        if (m.is_arc())
            entry_arc(m);
        else
            entry_line(m);
        entry_open_ = profile_.radius.entry == EntryStyle::perpendicular_to_next && !m.is_arc();
        active_ = true;
        exit_pending_ = false;
        return;
    }
    if (m.is_arc())
        next_arc(m);
    else
        next_line(m);
}

void RadiusCompensation::turn_off(int line) {
    if (!active_) return;
    entry_open_ = false;
    move_end_and_flush(plane2(current_), line);
    flush();
    active_ = false;
    arc_not_allowed_ = true;
    exit_pending_ = true;
}

void RadiusCompensation::control(const ControlEvent& e) {
    switch (e.kind) {
        case ControlKind::radius_off:
            turn_off(e.line);
            break;
        case ControlKind::stop:
            entry_open_ = false;
            if (active_) move_end_and_flush(plane2(current_), e.line);
            break;
        case ControlKind::program_end:
            entry_open_ = false;
            if (active_) {
                move_end_and_flush(plane2(current_), e.line);
                flush();
                active_ = false;
            }
            break;
    }
    out_.control(e);
}

void RadiusCompensation::finish() {
    flush();
    out_.finish();
}

}  // namespace toolcomp
