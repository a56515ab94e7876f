// Klartext contour elements: circle centre / pole (CC), arcs (C, CR, CT), polar moves (LP, CTP, CP
// with helix), and the corner elements RND and CHF, which change the elements on both sides
// (so the last element is held back until the next one is known).
#include <algorithm>
#include <cmath>
#include <optional>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/geometry/arc.hpp"
#include "toolcomp/geometry/element.hpp"
#include "toolcomp/geometry/fillet.hpp"

namespace toolcomp::heidenhain {

namespace {
constexpr double kArcTolerance = 0.016;  // mm: start and end radius of C blocks (TNC)
double deg(double rad) { return rad * 180 / kPi; }
double rad(double deg) { return deg * kPi / 180; }
}  // namespace

Element2 Interp::plane_element(const Motion& m) const {
    if (!m.is_arc()) return Element2::line(plane2(m.start), plane2(m.end));
    return Element2::arc(plane2(m.start), plane2(m.end), plane2(m.center), m.kind == MotionKind::arc_ccw ? 1 : -1,
                         m.turns);
}

Vec2 Interp::end_tangent() const {
    if (!pending_) fail(code::no_previous_element, "No preceding contour element to be tangent to");
    const Motion& m = *pending_;
    const Vec2 s = plane2(m.start), e = plane2(m.end);
    if (!m.is_arc()) return (e - s).normalized();
    const Vec2 u = (e - plane2(m.center)).normalized();
    return (m.kind == MotionKind::arc_ccw ? 1.0 : -1.0) * left_normal(u);
}

void Interp::settle_pending() {
    if ((pending_round_ > 0 || pending_chamfer_ > 0))
        throw ProgramError(code::corner_without_element, "RND and CHF need a contour element after them",
                           {pending_corner_line_, 0});
}

// Emits the held element (after a RND or CHF between it and m has cut it back) and holds m.
void Interp::put(Motion m) {
    ++moves_;
    if (approach_ && approach_->connecting) {
        emit_connecting_approach(m);  // puts the approach pieces first (approach_ is reset)
    } else if (approach_) {
        if (pending_) {
            sink_.push(*pending_);
            pending_.reset();
        }
        emit_approach(m);
    }
    if (pending_ && (pending_round_ > 0 || pending_chamfer_ > 0)) {
        Motion& prev = *pending_;
        const bool round = pending_round_ > 0;
        const int at = pending_corner_line_;
        const char* what = round ? "RND" : "CHF";
        if (prev.kind == MotionKind::rapid || m.kind == MotionKind::rapid)
            throw ProgramError(code::corner_next_to_rapid, std::string(what) + " needs feed moves on both sides (not FMAX)",
                               {at, 0});
        if (prev.surface.active() || m.surface.active())
            throw ProgramError(code::corner_between_ln, std::string(what) + " is not allowed next to an LN block", {at, 0});
        // A chamfer joins two straight lines only (TNC: "chamfer between two straight lines").
        if (!round && (prev.is_arc() || m.is_arc()))
            throw ProgramError(code::chamfer_next_to_arc, "CHAMFER NOT PERMITTED", {at, 0});
        const int c = axes(plane_).c;
        for (const Motion* e : {&prev, &m})
            if (e->is_arc() && (e->turns != 0 || e->start[c] != e->end[c]))
                throw ProgramError(code::rounding_next_to_helix, "RND is not allowed next to a helix", {at, 0});
        const Element2 e1 = plane_element(prev), e2 = plane_element(m);
        if (e1.length() < 1e-9 || e2.length() < 1e-9)
            throw ProgramError(code::corner_without_element, std::string(what) + " needs moves in the working plane on both sides",
                               {at, 0});
        Motion corner = prev;
        corner.line = at;
        corner.feed = pending_corner_feed_;
        if (round) {
            const auto f = fillet(e1, e2, pending_round_);
            if (!f) throw ProgramError(code::rounding_too_large, "ROUNDING-OFF RADIUS TOO LARGE", {at, 0});
            corner.kind = f->dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw;
            corner.turns = 0;
            corner.start = with_plane(prev.end, f->t1);
            corner.end = with_plane(prev.end, f->t2);
            corner.center = with_plane(prev.end, f->centre);
        } else {
            const Vec2 p = plane2(prev.end);
            const Vec2 t1 = e1.end_tangent(), t2 = e2.start_tangent();
            const double d = pending_chamfer_;
            if (d > e1.length() || d > e2.length() || std::fabs(turn_angle(t1, t2)) < 1e-12)
                throw ProgramError(code::chamfer_not_permitted, "CHAMFER NOT PERMITTED", {at, 0});
            corner.kind = MotionKind::line;
            corner.center = Vec3::Constant(std::nan(""));
            corner.start = with_plane(prev.end, p - d * t1);
            corner.end = with_plane(prev.end, p + d * t2);
        }
        prev.end = corner.start;
        m.start = corner.end;
        sink_.push(prev);
        pending_ = corner;
        pending_round_ = pending_chamfer_ = 0;
    }
    if (pending_) sink_.push(*pending_);
    pending_ = m;
}

// CC: the pole, in the plane of the two axes it names (CC X.. Y.. under TOOL CALL Z; CC X..
// Z.. the ZX plane and CC Y.. Z.. the YZ plane, where CAM posts put lead-in and lead-out
// arcs): the C, CP, LP and CTP blocks about it move in that plane. One axis: the working
// plane, the other coordinate where the tool is.
void Interp::circle_centre(Tokens t) {
    static constexpr std::string_view names[3] = {"X", "Y", "Z"};
    static constexpr std::string_view inc[3] = {"IX", "IY", "IZ"};
    bool named[3] = {false, false, false};
    for (const Token& k : t)
        for (int i = 0; i < 3; ++i) named[i] = named[i] || k.key == names[i] || k.key == inc[i];
    Plane p = plane_;
    if (named[0] + named[1] + named[2] == 2) p = !named[2] ? Plane::xy : !named[1] ? Plane::zx : Plane::yz;
    const auto ax = axes(p);
    for (const Token& k : t)
        if (k.key == names[ax.c] || k.key == inc[ax.c])
            fail(code::cc_outside_plane,
                 "CC " + std::string(k.key) + ": the pole names " +
                     (named[0] + named[1] + named[2] == 3 ? "three axes" : "one axis outside the working plane") +
                     "; name the two axes of the pole's plane",
                 k.column);
    Vec2 c = in_plane(pos_, p);
    for (const Token& k : t)
        for (int i : {ax.a, ax.b}) {
            double& v = i == ax.a ? c.x() : c.y();
            if (k.key == names[i] && k.has_value) v = k.value;
            if (k.key == inc[i] && k.has_value) v = pos_[i] + k.value;
        }
    pole_ = c;
    pole_plane_ = p;
}

// A block about a pole outside the working plane moves in the pole's plane; the tool axis
// stays. Radius compensation acts in the working plane only: there it is refused.
class PolePlane {
public:
    PolePlane(Interp& in, std::span<const Token> t) : in_(in) {
        if (in.pole_plane_ == in.plane_) return;
        if (in.side_ != 0)
            in.fail(code::comp_plane, "RL/RR with " + std::string(t[0].key) +
                                          " about a pole outside the working plane: not supported by toolcomp",
                    t[0].column);
        in.working_plane_ = in.plane_;
        in.plane_ = in.pole_plane_;
    }
    ~PolePlane() {
        if (!in_.working_plane_) return;
        in_.plane_ = *in_.working_plane_;
        in_.working_plane_.reset();
    }
    PolePlane(const PolePlane&) = delete;
    PolePlane& operator=(const PolePlane&) = delete;

private:
    Interp& in_;
};

// RND, CHF and CT join elements in the working plane: next to one in another plane they are
// refused.
void Interp::refuse_other_plane(Tokens t) const {
    if (pending_ && pending_->plane != plane_)
        fail(code::unsupported_block, std::string(t[0].key) + " next to an arc outside the working plane: not supported by toolcomp",
             t[0].column);
}

namespace {
int arc_direction(std::span<const Token> t) {
    for (const Token& k : t)
        if (k.is("DR") && k.sign_only) return k.value > 0 ? 1 : -1;
    return 0;
}
}  // namespace

// Arc blocks may keep RL/RR but not switch compensation on or off.
// In a CR block the first R is the radius; an R0 after it would end compensation.
static void check_arc_comp(std::span<const Token> t, int side, const ControlProfile& p, int line) {
    bool radius_word = t[0].is("CR");
    for (const Token& k : t) {
        if ((k.is("RL") || k.is("RR")) && side == 0)
            throw ProgramError(code::comp_entry_arc, p.radius.messages.entry_arc, {line, k.column});
        if (!k.is("R") || !k.has_value) continue;
        if (radius_word) {
            radius_word = false;
            continue;
        }
        if (k.value == 0 && side != 0) throw ProgramError(code::comp_exit_arc, p.radius.messages.exit_arc, {line, k.column});
        if (t[0].is("CR"))
            throw ProgramError(code::bad_word, "Word R given twice in one CR block (R is its radius)", {line, k.column});
    }
}

void Interp::arc_about_pole(Tokens t) {
    if (!pole_) fail(code::no_circle_centre, "CIRCLE CENTER UNDEFINED", t[0].column);
    const PolePlane in_pole_plane(*this, t);
    check_arc_comp(t, side_, profile_, line_);
    modal_words(t, 1);
    const int dir = arc_direction(t);
    if (dir == 0) fail(code::arc_direction_missing, "C needs DR+ or DR-", t[0].column);
    const Vec3 end = end_point(t, 1);
    const double r1 = (plane2(pos_) - *pole_).norm(), r2 = (plane2(end) - *pole_).norm();
    if (std::fabs(r1 - r2) > kArcTolerance / unit_) fail(code::arc_end_incorrect, "ARC END POS. INCORRECT", t[0].column);
    // Start or end on the centre: a circle of radius 0, or no direction to start or end in.
    if (std::min(r1, r2) < tol::length / unit_) fail(code::arc_end_incorrect, "ARC END POS. INCORRECT (circle of radius 0)", t[0].column);
    if (feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    Motion m = motion_to(dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
    m.center = with_plane(pos_, *pole_);
    ++plane_moves_;
    put(m);
    pos_ = end;
}

void Interp::arc_radius(Tokens t) {
    check_arc_comp(t, side_, profile_, line_);
    modal_words(t, 1);
    const int dir = arc_direction(t);
    if (dir == 0) fail(code::arc_direction_missing, "CR needs DR+ or DR-", t[0].column);
    const auto R = number(t, "R");
    if (!R || *R == 0) fail(code::arc_radius_missing, "CR needs a radius R", t[0].column);
    const Vec3 end = end_point(t, 1);
    const Vec2 s = plane2(pos_), e = plane2(end);
    if (s == e) fail(code::arc_end_incorrect, "ARC END POS. INCORRECT", t[0].column);
    const double half = (e - s).norm() / 2;
    double Ruse = *R;
    if (half > std::fabs(Ruse)) {
        if (half - std::fabs(Ruse) > 1e-9 / unit_) fail(code::arc_end_incorrect, "ARC END POS. INCORRECT", t[0].column);
        Ruse = std::copysign(half, Ruse);
    }
    auto c = center_from_radius(s, e, Ruse, dir);
    if (feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    Motion m = motion_to(dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
    m.center = with_plane(pos_, c ? *c : 0.5 * (s + e));
    ++plane_moves_;
    put(m);
    pos_ = end;
}

void Interp::arc_tangential(Tokens t, bool polar) {
    if (polar && !pole_) fail(code::no_circle_centre, "CIRCLE CENTER UNDEFINED", t[0].column);
    refuse_other_plane(t);
    std::optional<PolePlane> in_pole_plane;
    if (polar) in_pole_plane.emplace(*this, t);
    check_arc_comp(t, side_, profile_, line_);
    modal_words(t, 1);
    if (plane_moves_ < 1 || !pending_)
        fail(code::ct_without_element, std::string(polar ? "CTP" : "CT") + " needs a preceding contour element", t[0].column);
    const Vec2 t0 = end_tangent();
    const Vec3 end = polar ? polar_end(t) : end_point(t, 1);
    const Vec2 s = plane2(pos_), v = plane2(end) - s;
    const double den = 2 * v.dot(left_normal(t0));
    if (std::fabs(den) < 1e-12) fail(code::arc_end_incorrect, "ARC END POS. INCORRECT", t[0].column);
    const double rho = v.squaredNorm() / den;
    if (feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    Motion m = motion_to(rho > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
    m.center = with_plane(pos_, s + rho * left_normal(t0));
    ++plane_moves_;
    put(m);
    pos_ = end;
}

// The plane's axes (X, Y in XY; absolute and incremental) of a block that takes its point
// in polar coordinates.
void Interp::refuse_plane_axes(Tokens t, const char* why, std::size_t from) const {
    static constexpr std::string_view names[3] = {"X", "Y", "Z"};
    static constexpr std::string_view inc[3] = {"IX", "IY", "IZ"};
    const auto ax = axes(plane_);
    refuse_words(t, {names[ax.a], names[ax.b], inc[ax.a], inc[ax.b]}, why, from);
}

Vec3 Interp::polar_end(Tokens t) const {
    refuse_plane_axes(t, "its end point in the plane is PR and PA about the pole");
    const Vec2 rel = plane2(pos_) - *pole_;
    double pr = rel.norm(), pa = deg(std::atan2(rel.y(), rel.x()));
    if (auto v = number(t, "PR")) pr = *v;
    if (auto v = number(t, "IPR")) pr += *v;
    if (auto v = number(t, "PA")) pa = *v;
    if (auto v = number(t, "IPA")) pa += *v;
    return with_plane(end_point(t, 1), *pole_ + pr * Vec2(std::cos(rad(pa)), std::sin(rad(pa))));
}

void Interp::polar_line(Tokens t) {
    if (!pole_) fail(code::no_circle_centre, "CIRCLE CENTER UNDEFINED", t[0].column);
    const PolePlane in_pole_plane(*this, t);
    modal_words(t, 1);
    const Vec3 end = polar_end(t);
    if (end == pos_) return;
    if (!rapid_ && feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    ++plane_moves_;
    put(motion_to(rapid_ ? MotionKind::rapid : MotionKind::line, end));
    pos_ = end;
}

void Interp::polar_arc(Tokens t) {
    if (!pole_) fail(code::no_circle_centre, "CIRCLE CENTER UNDEFINED", t[0].column);
    const PolePlane in_pole_plane(*this, t);
    check_arc_comp(t, side_, profile_, line_);
    modal_words(t, 1);
    const int dir = arc_direction(t);
    if (dir == 0) fail(code::arc_direction_missing, "CP needs DR+ or DR-", t[0].column);
    refuse_plane_axes(t, "its end point is PA (and the tool axis) about the pole");
    refuse_words(t, {"PR", "IPR"}, "its radius is the distance from the pole");
    const Vec2 rel = plane2(pos_) - *pole_;
    const double r = rel.norm(), a0 = deg(std::atan2(rel.y(), rel.x()));
    if (r < 1e-9) fail(code::arc_end_incorrect, "ARC END POS. INCORRECT", t[0].column);
    double pa = a0;
    int turns = 0;
    if (auto v = number(t, "PA")) pa = *v;
    if (auto v = number(t, "IPA")) {
        pa = a0 + *v;
        if (std::fabs(*v) > 5400) fail(code::helix_angle, "The helix angle is limited to 5400 degrees", t[0].column);
        turns = std::max(0, int_value_truncated(std::floor((std::fabs(*v) - 1e-9) / 360)));
    }
    Vec3 end = end_point(t, 1);
    end = with_plane(end, *pole_ + r * Vec2(std::cos(rad(pa)), std::sin(rad(pa))));
    if (feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    Motion m = motion_to(dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, end);
    m.center = with_plane(pos_, *pole_);
    m.turns = turns;
    ++plane_moves_;
    put(m);
    pos_ = end;
}

void Interp::check_surface_line(Tokens raw) const {
    for (const Token& k : raw)
        if ((k.is("TX") || k.is("TY") || k.is("TZ")) && k.param > 0)
            fail(code::ln_block_format, "LN block format: TX, TY and TZ must be numbers, not Q parameters", k.column);
}

// LN X Y Z NX NY NZ [TX TY TZ]: a line to the datum point PT computed by CAM, with the surface
// normal N; the tool is displaced along N by the deltas of the tool called (3D compensation).
void Interp::surface_line(Tokens t) {
    refuse_scaled("LN", t[0].column);
    static const char* order[9] = {"X", "Y", "Z", "NX", "NY", "NZ", "TX", "TY", "TZ"};
    std::size_t i = 1;
    double v[9] = {0};
    for (int k = 0; k < 9; ++k) {
        if (i < t.size() && t[i].key == order[k] && t[i].has_value) {
            v[k] = t[i++].value;
        } else if (k < 6 || (k > 6 && i > 7 && t[i - 1].key[0] == 'T')) {
            fail(code::ln_block_format,
                 "LN block format: X Y Z NX NY NZ [TX TY TZ] must all be given, in this order",
                 i < t.size() ? t[i].column : t[0].column);
        } else {
            break;
        }
    }
    modal_words(t, i);
    const Vec3 pt(v[0], v[1], v[2]);
    Vec3 n(v[3], v[4], v[5]);
    const bool has_t = i >= 10;
    const double n_len = n.stableNorm();  // no overflow of the squares for large components
    if (!(n_len >= 1e-12) || !std::isfinite(n_len)) fail(code::ln_normal_zero, "LN: the normal vector is zero", t[0].column);
    if (has_t && m128_) {
        const double t_len = Vec3(v[6], v[7], v[8]).stableNorm();
        if (!(t_len >= 1e-12) || !std::isfinite(t_len))
            fail(code::ln_tool_axis_zero, "LN: the tool orientation TX TY TZ is zero", t[0].column);
    }
    if (!warned_normal_ && std::fabs(n_len - 1) > 1e-3) {
        diags_.push_back({code::ln_normal_not_unit, Severity::warning,
                          "LN normal vectors are not of unit length (|N| = " + std::to_string(n_len) +
                              "); they are normalised",
                          {line_, t[0].column}});
        warned_normal_ = true;
    }
    if ((sum_dr_ > 0 || sum_dr2_ > 0) && !m107_)
        fail(code::positive_delta_3d, "Positive tool deltas are not allowed with 3D compensation (M107 allows them)",
             t[0].column);
    if (!rapid_ && feed_ <= 0) fail(code::no_feed, "No feed rate programmed");
    Motion m = motion_to(rapid_ ? MotionKind::rapid : MotionKind::line, pt);
    m.surface.normal = n.stableNormalized();
    m.surface.d_r = sum_dr_;
    m.surface.d_r2 = sum_dr2_;
    if (m128_) m.tool_axis = has_t ? Vec3(Vec3(v[6], v[7], v[8]).stableNormalized()) : m.surface.normal;  // T only with M128
    put(m);
    pos_ = pt;
}

// An F in an RND or CHF block is the feed of the rounding or chamfer only (TNC); the
// contour goes on at the feed before it.
void Interp::corner_feed(Tokens t) {
    const double before = feed_;
    modal_words(t, 1);
    pending_corner_feed_ = feed_;
    feed_ = before;
}

void Interp::rounding(Tokens t) {
    refuse_other_plane(t);
    corner_feed(t);
    const auto r = number(t, "R");
    if (!r || *r <= 0) fail(code::rounding_radius, "RND needs a radius R > 0", t[0].column);
    if (!pending_) fail(code::corner_without_element, "RND cannot be the first element of a contour", t[0].column);
    pending_round_ = *r;
    pending_corner_line_ = line_;
}

void Interp::chamfer(Tokens t) {
    refuse_other_plane(t);
    corner_feed(t);
    double n = t[0].has_value ? t[0].value : (t.size() > 1 && t[1].key.empty() && t[1].has_value ? t[1].value : 0);
    if (n <= 0) fail(code::chamfer_length, "CHF needs a length > 0", t[0].column);
    if (!pending_) fail(code::chamfer_not_permitted, "CHAMFER NOT PERMITTED", t[0].column);
    pending_chamfer_ = n;
    pending_corner_line_ = line_;
}

}  // namespace toolcomp::heidenhain
