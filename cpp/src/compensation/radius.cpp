// Cutter radius compensation: entry, joints, exit and the held-back queue. The decisions and
// formulas are those of LinuxCNC's interpreter (convert_straight_comp1/2, convert_arc_comp1/2,
// move_endpoint_and_flush), restated in plane coordinates (a, b) with applicate h.
#include "toolcomp/compensation/radius.hpp"
#include "toolcomp/program/codes.hpp"

#include <cmath>

#include "radius_math.hpp"

namespace toolcomp {

using namespace radius_math;


Vec3 RadiusCompensation::with_plane(const Vec3& v, const Vec2& ab) const { return toolcomp::with_plane(v, ab, plane_); }

void RadiusCompensation::fail(const char* code, const std::string& msg, int line) const {
    throw CompensationError(code, msg, {line, 0, {}, file_of(line)});
}

int RadiusCompensation::file_of(int line) const {
    // The stage names the line of the move it is given, or of a move it holds: the move given
    // decides when it has that line (a called file's line 2 while line 2 of the caller is held).
    if (line == in_line_) return in_file_;
    int file = -1;
    auto seen = [&](int l, int f) {
        if (l != line) return true;
        if (file >= 0 && file != f) return false;
        file = f;
        return true;
    };
    for (const auto& h : queue_)
        if (!seen(h.m.line, h.m.file)) return -1;
    for (const auto& e : window_)
        if (!seen(e.m.line, e.m.file)) return -1;
    return file;
}

// ---- entry --------------------------------------------------------------------------------

void RadiusCompensation::entry_line(const Motion& m) {
    const Vec2 c = plane2(m.start), p = plane2(m.end);
    if (profile_.radius.entry_length_check && dist(p, c) <= r_)
        fail(code::comp_entry_too_short, profile_.radius.messages.entry_too_short, m.line);
    // Perpendicular to the entry move itself, at its programmed end (LinuxCNC's
    // convert_straight_comp1, its arithmetic).
    const double alpha = stored(ang(p - c) + (side_ > 0 ? kHalfPiL : -kHalfPiL));
    const Vec2 e = p + r_ * u(alpha);
    endpoint_ = c;
    endpoint_valid_ = true;
    Motion h = m;
    h.end = with_plane(m.end, e);
    // The reversal check of an entry move compares with its normal (LinuxCNC): never fails.
    hold(h, u(alpha), 0);
    queue_.back().approach = true;
    current_ = h.end;
    program_ = m.end;
}

void RadiusCompensation::entry_arc(const Motion& m) {
    const Vec2 c = plane2(m.start), p = plane2(m.end), centre = plane2(m.center);
    const int turn = turn_of(m);
    if (profile_.radius.entry_length_check && dist(p, c) <= r_)
        fail(code::comp_entry_too_short, profile_.radius.messages.entry_arc_too_short, m.line);
    if (dist(centre, c) <= r_ && tool_inside(side_, turn))
        fail(code::comp_arc_too_small, profile_.radius.messages.arc_too_small, m.line);
    const double gamma = tool_inside(side_, turn) ? ang(centre - p) : ang(p - centre);
    const Vec2 e = p + r_ * u(gamma);
    // New centre: on the line from the compensated end to the programmed centre, equally far
    // from the start (the uncompensated current point) and the compensated end.
    const double b_len = dist(c, e) / 2.0;  // LinuxCNC's convert_arc_comp1, its arithmetic
    const double ab = ang(centre - e);
    const double a = ang(c - e) - ab;
    if (std::fabs(std::cos(a)) < 1e-6) fail(code::comp_arc_too_small, profile_.radius.messages.arc_too_small, m.line);
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
        queue_.back().approach = true;
        endpoint_ = c;
        endpoint_valid_ = true;
    }
    Motion h = m;
    h.end = with_plane(m.end, e);
    h.center = with_plane(m.center, cn);
    hold(h, Vec2::Zero(), find_turn(c, cn, turn, e));
    queue_.back().approach = true;
    current_ = h.end;
    program_ = m.end;
}

// ---- stream -------------------------------------------------------------------------------

// G20/G21 while moves are held: everything kept is converted to the new program unit (the
// control rescales its queue the same way).
void RadiusCompensation::rescale(double new_unit) {
    const double f = unit_ / new_unit;
    unit_ = new_unit;
    if (f == 1.0) return;
    auto conv = [f, new_unit](Motion& m) {
        m.start *= f;
        m.end *= f;
        m.center *= f;
        m.tool_offset *= f;
        m.radius.radius *= f;
        m.unit = new_unit;
    };
    for (auto& h : queue_) conv(h.m);
    for (auto& w : window_) conv(w.m);
    overcut_.scale(f);
    program_ *= f;
    current_ *= f;
    endpoint_ *= f;
    last_ *= f;
    last_out_ *= f;
    r_ *= f;
}

void RadiusCompensation::push(const Motion& m) {
    in_line_ = m.line;
    in_file_ = m.file;
    rescale(m.unit);
    checks_ = m.radius.checks;
    lookahead_ = m.radius.lookahead;
    const RadiusRules& rules = profile_.radius;
    entry_ = m.radius.entry.value_or(rules.entry);
    outside_ = m.radius.outside.value_or(rules.outside_corner);
    gouge_ = m.radius.gouge.value_or(rules.gouge);
    disc_ = m.radius.disc ? *m.radius.disc : rules.disc;
    if (active_ && m.radius.side != 0 && m.radius.radius <= 0) turn_off(m.line, /*cancel=*/false);  // radius 0 (T00)
    if (m.is_arc() && (arc_not_allowed_ || exit_open_))
        fail(code::comp_exit_arc, profile_.radius.messages.exit_arc, m.line);
    if (exit_open_ && exit_when_behind_ && m.radius.side == 0) {
        const Vec2 P = plane2(program_), E = plane2(m.end);
        if ((E - P).dot(plane2(current_) - P) >= 0) {
            // KONT with the end point in front of the contour: the NORM exit.
            exit_open_ = false;
            turn_off(exit_line_);
        } else if (!profile_.radius.messages.around_end.empty() && (E - P).norm() < r_) {
            fail(code::comp_around_end, profile_.radius.messages.around_end, m.line);
        }
    }
    if (exit_open_ && m.radius.side == 0 && (plane2(m.end) - plane2(program_)).norm() > tol::length) {
        // Type B cancel: the cancel move is joined like a compensated move, then runs to its
        // programmed (uncompensated) end point.
        exit_open_ = false;
        Motion c = m;
        c.radius = {static_cast<std::int8_t>(side_), r_, exit_orientation_};
        next_line(c);
        queue_.back().m.end = m.end;
        queue_.back().m.radius = m.radius;
        flush();
        release(0);
        overcut_.report(diags_, unit_, /*all=*/true);
        active_ = false;
        arc_not_allowed_ = true;
        exit_pending_ = false;
        return;
    }
    if (m.radius.side == 0 || m.radius.radius <= 0) {
        if (!m.is_arc()) arc_not_allowed_ = false;
        passthrough(m);
        return;
    }
    if (!active_) {
        plane_ = m.plane;
        overcut_.configure(profile_.radius.overcut_neighbours, profile_.radius.overcut_tolerance / unit_);
        side_ = m.radius.side;
        r_ = m.radius.radius;
        arc_not_allowed_ = false;
        if (m.is_arc() && !profile_.radius.entry_arc) fail(code::comp_entry_arc, profile_.radius.messages.entry_arc, m.line);
        if (m.is_arc())
            entry_arc(m);
        else
            entry_line(m);
        entry_open_ = entry_ != EntryStyle::perpendicular_to_entry && !m.is_arc();
        active_ = true;
        exit_pending_ = false;
        return;
    }
    // A new side or radius (9/Series: G41/G42 or a T word while active), or a jump of the
    // programmed path (a new length offset from that T word): end the held move
    // perpendicular, link to the new start.
    if (m.radius.side != side_ || m.radius.radius != r_ || (m.start - program_).norm() > tol::length) change_side(m);
    if (m.is_arc())
        next_arc(m);
    else
        next_line(m);
}

// G41 <-> G42 (or a new radius) without G40: the held move ends perpendicular at its end,
// the next element starts perpendicular at its start with the new side, joined by a line.
void RadiusCompensation::change_side(const Motion& m) {
    const Vec2 P = plane2(m.start), C = plane2(current_);
    side_ = m.radius.side;
    r_ = m.radius.radius;
    Vec2 start;
    if (m.is_arc()) {
        const Vec2 centre = plane2(m.center);
        const double R = (P - centre).norm();
        const int dir = m.kind == MotionKind::arc_ccw ? 1 : -1;
        start = centre + (P - centre) * ((R - side_ * dir * r_) / R);
    } else {
        const Vec2 d = plane2(m.end) - P;
        if (d.norm() < tol::length) return;  // decided at the next plane move
        start = P + side_ * r_ * left_normal(d.normalized());
    }
    program_ = m.start;
    move_end_and_flush(C, m.line);
    flush();
    Motion link = m;
    link.kind = m.kind == MotionKind::rapid ? MotionKind::rapid : MotionKind::line;
    link.center = Vec3::Constant(std::nan(""));
    link.turns = 0;
    link.generated = true;
    link.end = with_plane(current_, start);
    hold(link, Vec2::Zero(), 0);
    flush();
    current_ = link.end;
    endpoint_ = start;
    endpoint_valid_ = true;
    joint_free_ = true;
}

void RadiusCompensation::turn_off(int line, bool cancel) {
    if (!active_) return;
    entry_open_ = false;
    move_end_and_flush(plane2(current_), line);
    flush();
    release(0);
    overcut_.report(diags_, unit_, /*all=*/true);
    active_ = false;
    arc_not_allowed_ = cancel && profile_.radius.exit_must_be_straight;  // after G40 the next move must be straight
    exit_pending_ = true;
}

void RadiusCompensation::control(const ControlEvent& e) {
    in_line_ = e.line;
    in_file_ = e.file;
    switch (e.kind) {
        case ControlKind::radius_off: {
            if (active_ && e.direction.squaredNorm() > 0 && !queue_.empty()) {
                // Let the last move end as if the contour went on in the given direction.
                Motion v = queue_.front().m;
                v.kind = MotionKind::line;
                v.generated = true;
                v.turns = 0;
                v.center = Vec3::Constant(std::nan(""));
                v.start = program_;
                v.end = program_ + e.direction;
                v.line = e.line;
                if ((plane2(v.end) - plane2(v.start)).norm() > tol::length) {
                    next_line(v);
                    queue_.pop_back();  // the virtual element itself is not cut
                }
            }
            const ExitStyle exit = !queue_.empty() && queue_.front().m.radius.exit ? *queue_.front().m.radius.exit
                                                                                   : profile_.radius.exit;
            if (active_ && exit != ExitStyle::perpendicular_to_last && !queue_.empty()) {
                exit_open_ = true;  // settled by the cancel move
                exit_when_behind_ = exit == ExitStyle::around_end_when_behind;
                exit_line_ = e.line;
                exit_orientation_ = queue_.front().m.radius.orientation;
                break;
            }
            turn_off(e.line);
            break;
        }
        case ControlKind::stop:
            if (exit_open_) {
                exit_open_ = false;
                turn_off(e.line);
            }
            entry_open_ = false;
            if (active_) move_end_and_flush(plane2(current_), e.line);
            release(0);
            break;
        case ControlKind::no_motion:
            if (active_ && !exit_open_) count_non_plane_block(e.line);
            break;
        case ControlKind::program_end:
            if (exit_open_) {
                exit_open_ = false;
                turn_off(e.line);
            }
            entry_open_ = false;
            if (active_) {
                move_end_and_flush(plane2(current_), e.line);
                flush();
                active_ = false;
            }
            release(0);
            overcut_.report(diags_, unit_, /*all=*/true);
            break;
    }
    out_.control(e);
}

void RadiusCompensation::finish() {
    if (exit_open_) {
        exit_open_ = false;
        turn_off(0);
    }
    flush();
    release(0);
    overcut_.report(diags_, unit_, /*all=*/true);
    settle();
    out_.finish();
}

}  // namespace toolcomp
