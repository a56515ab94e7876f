// Cutter radius compensation: entry, joints, exit and the held-back queue. The decisions and
// formulas are those of LinuxCNC's interpreter (convert_straight_comp1/2, convert_arc_comp1/2,
// move_endpoint_and_flush), restated in plane coordinates (a, b) with applicate h.
#include "toolcomp/compensation/radius.hpp"

#include <cmath>

namespace toolcomp {

namespace {
constexpr double kHalfPi = kPi / 2;

double ang(const Vec2& v) { return std::atan2(v.y(), v.x()); }
Vec2 u(double phi) { return {std::cos(phi), std::sin(phi)}; }

int turn_of(const Motion& m) { return (m.kind == MotionKind::arc_ccw ? 1 : -1) * (m.turns + 1); }

// Signed swept angle from s to e about c for a LinuxCNC turn count (±1 = less than a turn).
double find_turn(const Vec2& s, const Vec2& c, int turn, const Vec2& e) {
    if (turn == 0) return 0;
    double a = ang(s - c), b = ang(e - c);
    if (turn > 0) {
        if (b <= a) b += 2 * kPi;
        return b - a + (turn - 1) * 2 * kPi;
    }
    if (a <= b) a += 2 * kPi;
    return b - a + (turn + 1) * 2 * kPi;
}

bool tool_inside(int side, int turn) { return (side > 0 && turn > 0) || (side < 0 && turn < 0); }
}  // namespace

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
void RadiusCompensation::move_end_and_flush(const Vec2& x, int line) {
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
            if (h.sweep != 0 && endpoint_valid_ && std::fabs(sweep) > std::fabs(h.sweep) + profile_.arc_sweep_tolerance)
                fail("comp_gouge", "Arc move in concave corner cannot be reached by the tool without gouging", line);
        } else {
            double dot = h.dir.dot(x - endpoint_);
            if (endpoint_valid_ && dot < 0)
                fail("comp_gouge",
                     m.kind == MotionKind::rapid
                         ? "Straight traverse in concave corner cannot be reached by the tool without gouging"
                         : "Straight feed in concave corner cannot be reached by the tool without gouging",
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
        fail("comp_entry_too_short", "Length of cutter compensation entry move is not greater than the tool radius",
             m.line);
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
        fail("comp_entry_too_short", "Radius of cutter compensation entry arc is not greater than the tool radius",
             m.line);
    if ((centre - c).norm() <= r_ && tool_inside(side_, turn))
        fail("comp_arc_too_small", "Tool radius not less than arc radius with comp", m.line);
    const double gamma = tool_inside(side_, turn) ? ang(centre - p) : ang(p - centre);
    const Vec2 e = p + r_ * u(gamma);
    // New centre: on the line from the compensated end to the programmed centre, equally far
    // from the start (the uncompensated current point) and the compensated end.
    const double b_len = (c - e).norm() / 2;
    const double ab = ang(centre - e);
    const double a = ang(c - e) - ab;
    if (std::fabs(std::cos(a)) < 1e-6) fail("comp_arc_too_small", "Tool radius not less than arc radius with comp", m.line);
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

// ---- joints -------------------------------------------------------------------------------

void RadiusCompensation::next_line(const Motion& m) {
    const double small = profile_.corner_tolerance;
    const Vec2 P = plane2(program_), C = plane2(current_), p = plane2(m.end);
    if (p == P) {  // no motion in the plane: held at the compensated point
        Motion h = m;
        h.end = with_plane(m.end, C);
        hold(h, Vec2::Zero(), 0);
        current_ = h.end;
        program_ = m.end;
        return;
    }
    double theta = ang(C - P), alpha = ang(p - P), beta, gamma;
    if (side_ > 0) {
        if (theta < alpha) theta += 2 * kPi;
        beta = theta - alpha - kHalfPi;
        gamma = kHalfPi;
    } else {
        if (alpha < theta) alpha += 2 * kPi;
        beta = alpha - theta - kHalfPi;
        gamma = -kHalfPi;
    }
    const Vec2 e = p + r_ * u(alpha + gamma);
    const Vec2 mid = P + r_ * u(alpha + gamma);  // compensated start of the new move
    const bool front_arc = !queue_.empty() && queue_.front().m.is_arc();
    bool concave = beta < -small || beta > kPi + small;
    if (!concave && beta > kPi - small && front_arc && !tool_inside(side_, turn_of(queue_.front().m)))
        concave = true;  // 180 degrees off an arc the tool was outside of ("h" shape)

    if (!concave && beta > small) {  // outside corner: transition arc about the corner
        move_end_and_flush(C, m.line);
        Motion corner = m;
        corner.generated = true;
        corner.end = with_plane(current_, mid);
        if (m.kind == MotionKind::rapid) {
            corner.center = Vec3::Constant(std::nan(""));
        } else {
            corner.kind = side_ > 0 ? MotionKind::arc_cw : MotionKind::arc_ccw;
            corner.turns = 0;
            corner.center = with_plane(current_, P);
        }
        hold(corner, Vec2::Zero(), 0);
        flush();
        endpoint_ = mid;
        endpoint_valid_ = true;
    } else if (!concave) {  // tangent: the new move starts where the last one ended
        flush();
        endpoint_ = C;
        endpoint_valid_ = true;
    } else if (!front_arc) {  // inside corner after a line: pull it back to the intersection
        const double halfcorner = (beta + kPi) / 2;
        if (halfcorner == 0.0)
            fail("comp_zero_corner", "Zero degree inside corner is invalid for cutter compensation", m.line);
        const double retreat = r_ / std::tan(halfcorner);
        move_end_and_flush(C + retreat * u(theta + gamma), m.line);
    } else {  // inside corner after an arc: intersect the compensated circle and the new line
        const Motion& prev = queue_.front().m;
        const int pturn = turn_of(prev);
        const Vec2 cp = plane2(prev.center);
        const double rho = (cp - plane2(prev.end)).norm();
        const double base = ang(p - P);
        const double th = pturn > 0 ? base + kHalfPi : base - kHalfPi;
        const double phi = ang(cp - P);
        const bool inside = tool_inside(side_, pturn);
        const double d = (inside ? rho + r_ : rho - r_) * std::cos(th - phi);
        const double l = inside ? (d - r_) / rho : (d + r_) / rho;
        if (l > 1 || l < -1)
            fail("comp_gouge", "Arc to straight motion makes a corner the compensated tool can't fit in without gouging",
                 m.line);
        const double ac = inside ? (pturn > 0 ? -std::acos(l) : std::acos(l)) : (pturn > 0 ? std::acos(l) : -std::acos(l));
        move_end_and_flush(cp + rho * u(ac + th + kPi), m.line);
    }
    Motion h = m;
    h.end = with_plane(m.end, e);
    hold(h, p - P, 0);
    current_ = h.end;
    program_ = m.end;
}

void RadiusCompensation::next_arc(const Motion& m) {
    const double small = profile_.corner_tolerance;
    const Vec2 P = plane2(program_), C = plane2(current_), p = plane2(m.end), centre = plane2(m.center);
    const int turn = turn_of(m);
    const bool ccw = turn > 0;
    const double rho0 = (centre - p).norm();
    double theta = ang(C - P);
    theta = side_ > 0 ? theta - kHalfPi : theta + kHalfPi;  // end direction of the previous element
    double delta = ang(centre - P);
    const double alpha = ccw ? delta - kHalfPi : delta + kHalfPi;  // start direction of the arc
    double beta = side_ > 0 ? theta - alpha : alpha - theta;
    beta = beta > 1.5 * kPi ? beta - 2 * kPi : (beta < -kHalfPi ? beta + 2 * kPi : beta);
    const bool inside = tool_inside(side_, turn);
    double gamma;
    if (inside) {
        gamma = ang(centre - p);
        if (rho0 <= r_) fail("comp_arc_too_small", "Tool radius not less than arc radius with comp", m.line);
    } else {
        gamma = ang(p - centre);
        delta += kPi;
    }
    const Vec2 e = p + r_ * u(gamma);
    const bool concave = beta < -small || beta > kPi + small || (std::fabs(beta - kPi) < small && !inside);
    const bool front_arc = !queue_.empty() && queue_.front().m.is_arc();

    if (concave && !front_arc) {  // inside corner after a line
        const double y = rho0 * std::sin(beta - kHalfPi);
        const double dist = inside ? rho0 - r_ : rho0 + r_;
        const double l = inside ? (y + r_) / dist : (y - r_) / dist;
        if (l > 1 || l < -1)
            fail("comp_gouge", "Arc move in concave corner cannot be reached by the tool without gouging", m.line);
        const double ac = inside ? (ccw ? theta + std::asin(l) : theta - std::asin(l))
                                 : (ccw ? theta + kPi - std::asin(l) : theta + kPi + std::asin(l));
        move_end_and_flush(centre + dist * u(ac), m.line);
    } else if (concave) {  // inside corner after an arc: intersect the two compensated circles
        const Motion& prev = queue_.front().m;
        const int pturn = turn_of(prev);
        const Vec2 pc = plane2(prev.center);
        const double rp = (pc - plane2(prev.end)).norm();
        const double rn = inside ? rho0 - r_ : rho0 + r_;
        const double dcc = (pc - centre).norm();
        if (rp == 0 || dcc == 0)
            fail("comp_same_center", "Arc to arc motion is invalid because the arcs have the same center", m.line);
        const double a = (rp * rp + dcc * dcc - rn * rn) / (2 * rp * dcc);
        if (a > 1 || a < -1)
            fail("comp_gouge", "Arc to arc motion makes a corner the compensated tool can't fit in without gouging",
                 m.line);
        const double pull = std::acos(a), ccd = ang(centre - pc);
        const double dir = tool_inside(side_, pturn) ? (ccw ? ccd + pull : ccd - pull) : (ccw ? ccd - pull : ccd + pull);
        move_end_and_flush(pc + rp * u(dir), m.line);
    } else if (beta > small) {  // outside corner: transition arc about the corner
        const Vec2 mid = P + r_ * u(delta);
        flush();
        Motion corner = m;
        corner.generated = true;
        corner.kind = side_ > 0 ? MotionKind::arc_cw : MotionKind::arc_ccw;
        corner.turns = 0;
        corner.end = with_plane(current_, mid);
        corner.center = with_plane(current_, P);
        hold(corner, Vec2::Zero(), 0);
        flush();
        endpoint_ = mid;
        endpoint_valid_ = true;
    } else {  // tangent
        flush();
        endpoint_ = C;
        endpoint_valid_ = true;
    }
    Motion h = m;
    h.end = with_plane(m.end, e);
    hold(h, Vec2::Zero(), find_turn(P, centre, turn, p));
    current_ = h.end;
    program_ = m.end;
}

// ---- stream -------------------------------------------------------------------------------

void RadiusCompensation::push(const Motion& m) {
    if (m.is_arc() && arc_not_allowed_)
        fail("comp_exit_arc", "The move just after exiting cutter compensation mode must be straight, not an arc",
             m.line);
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
        if (m.is_arc())
            entry_arc(m);
        else
            entry_line(m);
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
            if (active_) move_end_and_flush(plane2(current_), e.line);
            break;
        case ControlKind::program_end:
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
