// Joints between compensated elements: where the held move ends and the next one starts.
// Tangent, outside and inside corners for lines and arcs (LinuxCNC's decisions and formulas),
// with the profile's choice of what fills an outside corner and how the entry block ends.
#include <algorithm>
#include <cmath>
#include <vector>

#include "radius_math.hpp"
#include "toolcomp/compensation/radius.hpp"
#include "toolcomp/geometry/element.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp {

using namespace radius_math;

// The held plane move as a compensated element (its start is endpoint_, its end C). A
// straight entry move is its equidistant, the entry line moved by the tool's offset at its
// end (C - P): the outside-corner rules meet that line (Fanuc start-up type B, Sinumerik
// KONT with G451), while the move itself runs from the uncompensated start.
std::optional<Element2> RadiusCompensation::held_element() const {
    if (queue_.empty() || !endpoint_valid_) return std::nullopt;
    const Held& h = queue_.front();
    const Motion& f = h.m;
    const Vec2 c = plane2(current_);
    if (f.is_arc()) return Element2::arc(endpoint_, c, plane2(f.center), f.kind == MotionKind::arc_ccw ? 1 : -1);
    const Vec2 start = h.approach ? Vec2(endpoint_ + (c - plane2(program_))) : endpoint_;
    if ((c - start).norm() < tol::length) return std::nullopt;
    return Element2::line(start, c);
}

namespace {
// A piece the compensation inserts at a corner: the move's data, no turns, no centre.
Motion corner_piece(const Motion& m) {
    Motion piece = m;
    piece.generated = true;
    piece.turns = 0;
    piece.center = Vec3::Constant(std::nan(""));
    return piece;
}
}  // namespace

// Fill the gap of an outside corner between the held element (ending at C) and the next
// element's equidistant `next` (starting at `mid`). `turn` is the turning angle (> 0). The
// strategies in the order they are tried: meet at the intersection (M97, or the profile's
// choice within its corner limit), the DISC fillet; then, the held move ending at C, the
// extension blocks, a straight rapid or the transition arc.
void RadiusCompensation::outside_corner(const Motion& m, const Vec2& P, const Element2& next, double turn,
                                        bool check_held) {
    const RadiusRules& rules = profile_.radius;
    const auto held = held_element();
    // Heidenhain M97 in the block before the corner: meet at the intersection, whatever the angle.
    const bool m97 = !queue_.empty() && queue_.front().m.radius.corner_at_intersection;
    const bool intersection = m97 || (outside_ != OutsideCorner::arc && turn <= rules.corner_limit);
    if (held && intersection && meet_at_intersection(m, P, *held, next)) return;
    const bool disc = outside_ == OutsideCorner::arc && disc_ > 0 && m.kind != MotionKind::rapid;
    if (held && disc && !held->is_arc && !next.is_arc && disc_fillet(m, P, *held, next)) return;
    if (check_held)
        move_end_and_flush(plane2(current_), m.line);
    else
        flush();
    if (outside_ == OutsideCorner::extension && held && turn > rules.corner_limit)
        extension_blocks(m, *held, next);
    else if (m.kind == MotionKind::rapid)
        hold_piece(corner_piece(m), next.p0);  // no arc traverse exists: a straight one
    else
        transition_arc(m, P, next.p0);
    flush();
    endpoint_ = next.p0;
    endpoint_valid_ = true;
}

// Where the two equidistants (extended) cross, nearest to the programmed corner P; false
// when they do not.
bool RadiusCompensation::meet_at_intersection(const Motion& m, const Vec2& P, const Element2& held,
                                              const Element2& next) {
    auto xs = intersect(held, next);
    if (xs.empty()) return false;
    Vec2 v = xs[0];
    for (const Vec2& x : xs)
        if ((x - P).norm() < (v - P).norm()) v = x;
    move_end_and_flush(v, m.line, /*check=*/false);
    return true;
}

// DISC (Sinumerik): a fillet of radius r(1 - k) between the extended equidistants of two
// lines, k = DISC/100; false when they do not cross.
bool RadiusCompensation::disc_fillet(const Motion& m, const Vec2& P, const Element2& held, const Element2& next) {
    auto xs = intersect(held, next);
    if (xs.empty()) return false;
    const Vec2 C = plane2(current_), mid = next.p0;
    const double k = std::min(disc_, 100.0) / 100;
    const Vec2 v = xs[0];
    const Vec2 t1 = C + k * (v - C), t2 = mid + k * (v - mid);
    move_end_and_flush(t1, m.line, /*check=*/false);
    if (k < 1) {
        Motion fillet = corner_piece(m);
        fillet.kind = side_ > 0 ? MotionKind::arc_cw : MotionKind::arc_ccw;
        fillet.center = with_plane(current_, t1 + (1 - k) * (P - C));
        hold_piece(fillet, t2);
        flush();
    }
    endpoint_ = t2;
    endpoint_valid_ = true;
    return true;
}

// Both elements extended by r along their tangents and the extensions joined (Fanuc type
// C); a middle block shorter than the minimum in both axes is dropped, the last block then
// running from the first extension straight to the next element's start.
void RadiusCompensation::extension_blocks(const Motion& m, const Element2& held, const Element2& next) {
    const Vec2 C = plane2(current_), mid = next.p0;
    const Vec2 e1 = C + r_ * held.end_tangent(), e2 = mid - r_ * next.start_tangent();
    Motion piece = corner_piece(m);
    if (m.kind != MotionKind::rapid) piece.kind = MotionKind::line;
    const double min_len = profile_.radius.extension_min_length / m.unit;
    const bool drop_middle = min_len > 0 && std::fabs(e2.x() - e1.x()) < min_len && std::fabs(e2.y() - e1.y()) < min_len;
    std::vector<Vec2> points{e1, e2, mid};
    if (drop_middle) points.erase(points.begin() + 1);
    for (const Vec2& pt : points) hold_piece(piece, pt);
}

// The transition arc of the tool radius about the programmed corner P (LinuxCNC).
void RadiusCompensation::transition_arc(const Motion& m, const Vec2& P, const Vec2& mid) {
    Motion arc = corner_piece(m);
    arc.kind = side_ > 0 ? MotionKind::arc_cw : MotionKind::arc_ccw;
    arc.center = with_plane(current_, P);
    hold_piece(arc, mid);
}

// Holds `piece` ending at `at` (in the plane; off it where the move stands).
void RadiusCompensation::hold_piece(Motion piece, const Vec2& at) {
    piece.end = with_plane(current_, at);
    hold(piece, Vec2::Zero(), 0);
}

// Heidenhain M98 on the held move: both elements end and start perpendicular to themselves
// and a straight line joins them, so an open contour's corners are machined fully.
bool RadiusCompensation::open_corner(const Motion& m, const Vec2& mid) {
    if (queue_.empty() || !queue_.front().m.radius.open_corner) return false;
    flush();
    Motion link = m;
    link.kind = m.kind == MotionKind::rapid ? MotionKind::rapid : MotionKind::line;
    link.center = Vec3::Constant(std::nan(""));
    link.turns = 0;
    link.generated = true;
    link.end = with_plane(current_, mid);
    hold(link, Vec2::Zero(), 0);
    flush();
    endpoint_ = mid;
    endpoint_valid_ = true;
    return true;
}

// Type A entry: the activation block ends where the next element's equidistant starts.
bool RadiusCompensation::close_open_entry(const Vec2& mid) {
    if (!entry_open_) return false;
    entry_open_ = false;
    if (entry_ == EntryStyle::around_start_when_behind && !queue_.empty()) {
        // Behind: the start point and the new element's equidistant lie on opposite sides of
        // the element's line through the contour start.
        const Vec2 S = plane2(program_), A = plane2(queue_.front().m.start);
        if ((A - S).dot(mid - S) < 0) {
            if (!profile_.radius.messages.around_start.empty() && (A - S).norm() < r_)
                fail(code::comp_around_start, profile_.radius.messages.around_start, queue_.front().m.line);
            return false;
        }
    }
    for (auto& h : queue_) h.m.end = with_plane(h.m.end, mid);
    flush();
    endpoint_ = mid;
    endpoint_valid_ = true;
    return true;
}

// Arcs left out because the tool does not fit into them (skip reaction): the held element
// and the next one meet where their equidistants cross.
void RadiusCompensation::bridge(const Element2& next, int line) {
    const std::string lines = bridge_lines_;
    bridge_lines_.clear();
    if (auto held = held_element()) {
        bool found = false;
        Vec2 x = Vec2::Zero();
        for (const Vec2& cand : intersect(*held, next)) {
            const bool ahead = held->is_arc ? true : (cand - held->p0).dot(held->p1 - held->p0) > 0;
            const bool before = next.is_arc ? true : (next.p1 - cand).dot(next.p1 - next.p0) > 0;
            if (ahead && before && (!found || (cand - held->p1).norm() < (x - held->p1).norm())) {
                x = cand;
                found = true;
            }
        }
        if (!found && !held->is_arc && !next.is_arc) {
            // On one line (a notch in a straight edge): the held move runs on to the next start.
            const Vec2 d = held->p1 - held->p0, q = next.p0 - held->p0;
            if (std::fabs(cross2(d.normalized(), q)) < 1e-9 && d.dot(next.p1 - next.p0) > 0 && d.dot(q) > 0) {
                x = next.p0;
                found = true;
            }
        }
        if (found) {
            move_end_and_flush(x, line, /*check=*/false);
            warn(code::comp_skipped,
                 "Elements of line(s) " + lines + " cannot be reached by the tool and are left out (at line " +
                     std::to_string(line) + ")",
                 line);
            return;
        }
    }
    if (!skip_unreachable(next, line)) fail(code::comp_arc_too_small, profile_.radius.messages.arc_too_small, line);
}

void RadiusCompensation::count_non_plane_block(int line) {
    const RadiusRules& rr = profile_.radius;
    if (rr.max_non_plane_moves < 0 || ++non_plane_run_ <= rr.max_non_plane_moves) return;
    if (rr.non_plane_reaction == NonPlaneReaction::error) fail(code::comp_non_plane_moves, rr.messages.too_many_non_plane, line);
    // The control stops looking ahead: the held move ends perpendicular to its programmed
    // end, which can leave material or cut into an inside corner.
    if (!queue_.empty()) {
        diags_.push_back({code::comp_overcut, Severity::warning,
                          "Too many blocks without plane motion: the previous move ends perpendicular "
                          "to its end point, which may overcut",
                          {line, 0, {}, file_of(line)}});
        flush();
    }
}

void RadiusCompensation::next_line(const Motion& m) {
    const RadiusRules& rules = profile_.radius;
    const double small = rules.corner_tolerance;
    const Vec2 P = plane2(program_), C = plane2(current_), p = plane2(m.end);
    if (p == P) {  // no motion in the plane: held at the compensated point
        count_non_plane_block(m.line);
        current_ = hold(m, Vec2::Zero(), 0).m.end = with_plane(m.end, C);
        program_ = m.end;
        return;
    }
    non_plane_run_ = 0;
    watch_programmed(Element2::line(P, p), m.line);
    // LinuxCNC's convert_straight_comp2, operation for operation: theta, the direction of the
    // tool's offset C - P at the corner; alpha, of the new move; gamma = ±90° (the tool's
    // side); beta = theta - alpha - 90° (its mirror on the right), the turn at the corner in
    // [-90°, 270°), > 0 outside.
    double theta = ang(C - P), alpha = ang(p - P), beta;
    double gamma;
    if (side_ > 0) {
        if (theta < alpha) theta = stored(theta + 2 * kPiL);
        beta = stored((theta - alpha) - kHalfPiL);
        gamma = kHalfPi;
    } else {
        if (alpha < theta) alpha = stored(alpha + 2 * kPiL);
        beta = stored((alpha - theta) - kHalfPiL);
        gamma = -kHalfPi;
    }
    const Vec2 offset = r_ * u(alpha + gamma);  // the tool's offset along the new move
    const Vec2 e = p + offset;
    const Vec2 mid = P + offset;  // compensated start of the new move
    const bool front_arc = !queue_.empty() && queue_.front().m.is_arc();
    bool concave = beta < -small || beta > kPiL + small;
    if (!concave && beta > kPiL - small && front_arc && !tool_inside(side_, turn_of(queue_.front().m)))
        concave = true;  // 180 degrees off an arc the tool was outside of ("h" shape)

    const Element2 next = Element2::line(mid, e);  // the new move's equidistant
    if (open_corner(m, mid)) {
        // M98: the corner is left open
    } else if (!bridge_lines_.empty()) {
        bridge(next, m.line);
    } else if (joint_free_) {
        joint_free_ = false;  // a side change already placed the tool at the new start
    } else if (close_open_entry(mid)) {
        // the entry block already ends at the new element's start
    } else if (!concave && beta > small) {
        outside_corner(m, P, next, beta, /*check_held=*/true);
    } else if (!concave) {  // tangent: the new move starts where the last one ended
        overcut_.tangent_slack(r_ * (1 - std::cos(beta)));
        flush();
        endpoint_ = C;
        endpoint_valid_ = true;
    } else if (!front_arc) {  // inside corner after a line: pull it back to the intersection
        const double halfcorner = stored((beta + kPiL) / 2.0);
        if (halfcorner == 0.0)
            fail(code::comp_zero_corner, "Zero degree inside corner is invalid for cutter compensation", m.line);
        const double retreat = r_ / std::tan(halfcorner);
        move_end_and_flush(C + retreat * u(theta + gamma), m.line, true, &next);
    } else {  // inside corner after an arc: intersect the compensated circle and the new line
        const Motion& prev = queue_.front().m;
        const int pturn = turn_of(prev);
        const Vec2 cp = plane2(prev.center);
        const double rho = dist(cp, plane2(prev.end));
        const double base = ang(p - P);
        const double th = stored(pturn > 0 ? base + kHalfPiL : base - kHalfPiL);
        const double phi = ang(cp - P);
        const bool inside = tool_inside(side_, pturn);
        const double d = (inside ? rho + r_ : rho - r_) * std::cos(th - phi);
        const double l = inside ? (d - r_) / rho : (d + r_) / rho;
        if (l > 1 || l < -1) {
            no_intersection(next, m.line, rules.messages.arc_to_line);
        } else {
            const double ac =
                inside ? (pturn > 0 ? -std::acos(l) : std::acos(l)) : (pturn > 0 ? std::acos(l) : -std::acos(l));
            move_end_and_flush(cp + rho * u(stored(ac + th + kPiL)), m.line, true, &next);
        }
    }
    current_ = hold(m, p - P, 0).m.end = with_plane(m.end, e);
    program_ = m.end;
}

void RadiusCompensation::next_arc(const Motion& m) {
    const RadiusRules& rules = profile_.radius;
    const double small = rules.corner_tolerance;
    const Vec2 P = plane2(program_), C = plane2(current_), p = plane2(m.end), centre = plane2(m.center);
    const int turn = turn_of(m);
    const bool ccw = turn > 0;
    const double rho0 = dist(centre, p);
    non_plane_run_ = 0;
    watch_programmed(Element2::arc(P, p, centre, ccw ? 1 : -1, m.turns), m.line);
    // LinuxCNC's convert_arc_comp2, operation for operation: theta, the end direction of the
    // previous element (the tool's offset C - P turned back by 90°); alpha, the arc's start
    // direction (delta, towards its centre, turned by 90°); beta = theta - alpha (mirrored on
    // the right) brought into [-90°, 270°], the turn at the corner.
    double theta = ang(C - P);
    theta = stored(side_ > 0 ? theta - kHalfPiL : theta + kHalfPiL);
    double delta = ang(centre - P);
    const double alpha = stored(ccw ? delta - kHalfPiL : delta + kHalfPiL);
    double beta = side_ > 0 ? theta - alpha : alpha - theta;
    beta = beta > 1.5L * kPiL ? stored(beta - 2 * kPiL) : (beta < -kHalfPiL ? stored(beta + 2 * kPiL) : beta);
    const bool inside = tool_inside(side_, turn);
    double gamma;  // the direction the arc's end moves in
    if (inside) {
        gamma = ang(centre - p);
        if (rho0 <= r_) {
            if (gouge_ != GougeReaction::skip) fail(code::comp_arc_too_small, rules.messages.arc_too_small, m.line);
            // The tool does not fit into the arc: leave it out, the next element decides.
            bridge_lines_ += (bridge_lines_.empty() ? "" : ", ") + std::to_string(m.line);
            program_ = m.end;
            return;
        }
    } else {
        gamma = ang(p - centre);
        delta = stored(delta + kPiL);
    }
    const Vec2 e = p + r_ * u(gamma);
    const Vec2 mid = P + r_ * u(delta);  // compensated start of the arc
    const bool concave = beta < -small || beta > kPiL + small || (std::fabs(beta - kPiL) < small && !inside);
    const bool front_arc = !queue_.empty() && queue_.front().m.is_arc();
    const Element2 next = Element2::arc(mid, e, centre, ccw ? 1 : -1, m.turns);  // the arc's equidistant
    if (open_corner(m, mid)) {
        hold_arc_and_advance(m, e, centre, turn, P, p);
        return;
    }
    if (!bridge_lines_.empty()) {
        bridge(next, m.line);
        hold_arc_and_advance(m, e, centre, turn, P, p);
        return;
    }
    if (joint_free_) {
        joint_free_ = false;  // a side change already placed the tool at the new start
        hold_arc_and_advance(m, e, centre, turn, P, p);
        return;
    }

    if (close_open_entry(mid)) {
        // the entry block already ends at the arc's start
    } else if (concave && !front_arc) {  // inside corner after a line
        const double y = scaled_sinl(rho0, beta - kHalfPiL);  // stored(rho0 * sinl(...))
        const double from_centre = inside ? rho0 - r_ : rho0 + r_;  // the arc's equidistant
        const double l = inside ? (y + r_) / from_centre : (y - r_) / from_centre;
        if (l > 1 || l < -1) {
            no_intersection(next, m.line, rules.messages.gouge_arc);
        } else {
            const double ac = inside ? (ccw ? theta + std::asin(l) : theta - std::asin(l))
                                     : stored(ccw ? theta + kPiL - std::asin(l) : theta + kPiL + std::asin(l));
            move_end_and_flush(centre + from_centre * u(ac), m.line, true, &next);
        }
    } else if (concave) {  // inside corner after an arc: intersect the two compensated circles
        const Motion& prev = queue_.front().m;
        const int pturn = turn_of(prev);
        const Vec2 pc = plane2(prev.center);
        const double rp = dist(pc, plane2(prev.end));
        const double rn = inside ? rho0 - r_ : rho0 + r_;
        const double dcc = dist(pc, centre);
        // Concentric arcs, compared exactly as LinuxCNC does (in inch programs its inch
        // arithmetic and toolcomp's millimetres can round differently: message only).
        if (rp == 0 || dcc == 0)
            fail(code::comp_same_center, "Arc to arc motion is invalid because the arcs have the same center", m.line);
        const double a = (rp * rp + dcc * dcc - rn * rn) / (2 * rp * dcc);
        if (a > 1 || a < -1) {
            no_intersection(next, m.line, rules.messages.arc_to_arc);
        } else {
            const double pull = std::acos(a), ccd = ang(centre - pc);
            const double dir =
                tool_inside(side_, pturn) ? (ccw ? ccd + pull : ccd - pull) : (ccw ? ccd - pull : ccd + pull);
            move_end_and_flush(pc + rp * u(dir), m.line, true, &next);
        }
    } else if (beta > small) {
        outside_corner(m, P, next, beta, /*check_held=*/false);
    } else {  // tangent
        overcut_.tangent_slack(r_ * (1 - std::cos(beta)));
        flush();
        endpoint_ = C;
        endpoint_valid_ = true;
    }
    hold_arc_and_advance(m, e, centre, turn, P, p);
}

void RadiusCompensation::hold_arc_and_advance(const Motion& m, const Vec2& e, const Vec2& centre, int turn,
                                              const Vec2& P, const Vec2& p) {
    current_ = hold(m, Vec2::Zero(), find_turn(P, centre, turn, p)).m.end = with_plane(m.end, e);
    program_ = m.end;
}

}  // namespace toolcomp
