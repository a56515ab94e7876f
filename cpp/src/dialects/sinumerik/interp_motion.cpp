// The geometry of a Sinumerik block (its steps in order are in interp_execute.cpp): dimensions (G90/G91, AC()/IC(),
// G70/G71/G700/G710, DIAMON), the programmable frame (TRANS ROT SCALE MIRROR and the A...
// forms), G53/G153/SUPA, straight moves, circles (centre I J K, CR=, AR=, CIP, CT, TURN=,
// helices) and the cutter radius request (G40/G41/G42, NORM/KONT, G450/G451, DISC, CDON/CDOF,
// OFFN).
#include <cmath>

#include "interp.hpp"
#include "toolcomp/motion/spindle.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/text.hpp"
#include "toolcomp/geometry/arc.hpp"

namespace toolcomp::sinumerik {

namespace {
constexpr char kAxes[3] = {'X', 'Y', 'Z'};
constexpr char kCentre[3] = {'I', 'J', 'K'};

int plane_normal_axis(Plane p) { return p == Plane::xy ? 2 : p == Plane::zx ? 1 : 0; }
}  // namespace

bool Interp::mirrored() const {
    const PlaneAxes ax = axes(st_.plane);
    const double det = actual_.a(ax.a, ax.a) * actual_.a(ax.b, ax.b) - actual_.a(ax.a, ax.b) * actual_.a(ax.b, ax.a);
    return det < 0;
}

// The end point of a move in program (workpiece) coordinates, or with `machine` (G53,
// G153, SUPA) in machine coordinates: no frame, no work offset; the tool offset stays active
// (the tool tip goes there: SUPA Z0 D0 puts the spindle at machine Z0).
Vec3 Interp::end_point(const BlockData& b, bool machine) const {
    Vec3 p = machine ? Vec3(pos_ + work_origin_) : program_pos();
    for (int i = 0; i < 3; ++i) {
        const Value& v = b[kAxes[i]];
        if (!v.set) continue;
        double x = v.v * unit();
        const bool incremental = v.mod == 2 || (v.mod == 0 && st_.incremental);
        if (i == 0 && (st_.diameter || (diam90_ && !incremental))) x /= 2;
        if (machine && incremental) fail(code::g53_incremental, "G53/G153/SUPA with incremental dimensions", v.column);
        p[i] = incremental ? p[i] + x : x;
    }
    return p;
}

// RND=, CHF=, CHR= in a block: the corner at the end of its move (CornerSink), the size in
// the program's unit; one of them per block.
void Interp::corner_request(const BlockData& b, int column) {
    const Value* v = b.rnd.set ? &b.rnd : b.chf.set ? &b.chf : b.chr.set ? &b.chr : nullptr;
    if (!v) return;
    if (b.rnd.set + b.chf.set + b.chr.set > 1) fail(code::alarm_12190, "12190 RND=, CHF= and CHR= in one block", v->column);
    if (!(v->v > 0)) fail(code::chamfer_not_permitted, (b.rnd.set ? "RND=" : b.chf.set ? "CHF=" : "CHR=") + shortest_number(v->v) +
                                                         ": the size is above 0", v->column);
    const CornerKind k = b.rnd.set ? CornerKind::rounding : b.chf.set ? CornerKind::chamfer_length : CornerKind::chamfer_legs;
    corners_.request({k, v->v * unit(), line_, v->column ? v->column : column});
}

// DC / ACP / ACN on a modulo rotary axis: the position v (0 <= v < 360) reached the shortest
// way (half a turn: the positive way) / turning positively / negatively. The result goes on
// from where the axis stands (the path's abc counts turns, as with M126/M127 on the TNC).
double Interp::modulo_target(double from, const Value& v) const {
    if (!(v.v >= 0 && v.v < 360))
        fail(code::alarm_16830, "16830 Invalid modulo position programmed: " + shortest_number(v.v) + " (0 <= position < 360)", v.column);
    double d = v.v - (from - 360 * std::floor(from / 360));
    if (v.mod == 3) {
        if (d > 180) d -= 360;
        if (d <= -180) d += 360;
    } else if (v.mod == 4 && d < 0) {
        d += 360;
    } else if (v.mod == 5 && d > 0) {
        d -= 360;
    }
    return from + d;
}

Motion Interp::motion_(MotionKind kind, const Vec3& end) const {
    Motion m;
    m.kind = kind;
    m.plane = st_.plane;
    m.start = pos_;
    m.end = end;
    m.abc = abc_;
    m.feed = kind == MotionKind::rapid ? std::numeric_limits<double>::quiet_NaN() : feed_rate(end);
    m.line = line_;
    m.file = file();
    m.tool = tool_;
    m.tool_offset = tool_offset_;
    m.work_offset = work_origin_;  // the moves are in the machine's axes less the work origin
    m.tool_axis = tool_axis_;
    m.radius = radius_request();
    m.unit = 1.0;
    return m;
}

// G95: F (mm/rev) times S; G96: times the speed that keeps the cutting speed at the X where
// the move ends, at most LIMS. Not known (NaN) with the spindle at rest or at the axis under
// G96 without LIMS.
double Interp::feed_rate(const Vec3& end) const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    switch (st_.feed_mode) {
        case G95: return speed_ > 0 ? feed_ * speed_ : nan;
        case G96: {
            const double rpm = css_speed(end.x());
            return std::isfinite(rpm) && rpm > 0 ? feed_ * rpm : nan;
        }
        default: return feed_;
    }
}

double Interp::css_speed(double x) const {  // S in m/min; LIMS caps it (rev/min)
    const double rpm = css_rpm(cutting_speed_ * 1000, std::fabs(x));
    return lims_ > 0 && !(rpm <= lims_) ? lims_ : rpm;
}

RadiusRequest Interp::radius_request() const {
    RadiusRequest r;
    if (st_.side == 0) return r;
    r.side = static_cast<std::int8_t>(mirrored() ? -st_.side : st_.side);
    r.radius = radius_now();
    if (active_ && is_turning_type(active_->type())) {
        const int tip = int_value(active_->DP(2));
        r.orientation = static_cast<std::int8_t>(tip >= 0 && tip <= 9 ? tip : 0);
    }
    if (st_.entry) r.entry = st_.entry;
    if (r.entry == EntryStyle::around_start_when_behind) r.exit = ExitStyle::around_end_when_behind;
    if (st_.outside) r.outside = st_.outside;
    if (st_.gouge) r.gouge = st_.gouge;
    if (st_.disc >= 0) r.disc = static_cast<float>(st_.disc);
    return r;
}

void Interp::frame_statement(const BlockData& b, const std::string& which, int column) {
    const bool additive = which[0] == 'A';
    const std::string base = additive ? which.substr(1) : which;
    // Frames here act on the geometry axes X, Y, Z; a rotary axis in a frame statement (TRANS
    // A10, SCALE B2, ROT takes none) would be left out without a word: refused.
    for (const char a : {'A', 'B', 'C'})
        if (b.has(a))
            fail(code::unsupported_word, which + " on the rotary axis " + std::string(1, a) + " is not supported by toolcomp",
                 b[a].column);
    Frame f = additive ? frame_ : Frame{};
    FrameValue c;  // the statement's frame in components: TRANS the coarse part, ATRANS the fine
    if (base == "TRANS") {
        Vec3 v = Vec3::Zero();
        for (int i = 0; i < 3; ++i)
            if (b[kAxes[i]].set) v[i] = b[kAxes[i]].v * unit();
        f.t += f.a * v;
        (additive ? c.fi : c.tr) = v;
    } else if (base == "ROT") {
        Mat3 r = Mat3::Identity();
        if (b.rpl.set) {
            if (b.has('X') || b.has('Y') || b.has('Z')) fail(code::syntax_error, "ROT with RPL= and axis angles", column);
            r = rotation(plane_normal_axis(st_.plane), b.rpl.v);
            c.rt[plane_normal_axis(st_.plane)] = b.rpl.v;
        } else {
            for (int i : {2, 1, 0})  // Z, then Y, then X (RPY angles, MD10600 = 1)
                if (b[kAxes[i]].set) {
                    r = r * rotation(i, b[kAxes[i]].v);
                    c.rt[i] = b[kAxes[i]].v;
                }
        }
        f.then(r);
    } else if (base == "SCALE") {
        Mat3 s = Mat3::Identity();
        for (int i = 0; i < 3; ++i)
            if (b[kAxes[i]].set) {
                if (b[kAxes[i]].v == 0) fail(code::scale_zero, "SCALE with a factor of zero", b[kAxes[i]].column);
                s(i, i) = b[kAxes[i]].v;
                c.sc[i] = b[kAxes[i]].v;
            }
        f.then(s);
    } else if (base == "MIRROR") {
        Mat3 m = Mat3::Identity();
        for (int i = 0; i < 3; ++i)
            if (b[kAxes[i]].set) {
                m(i, i) = -1;
                c.mi[i] = 1;
            }
        f.then(m);
    }
    set_programmable(f, !additive ? std::optional<FrameValue>(c) : pframe_ ? chain(*pframe_, c) : std::nullopt);
}

void Interp::arc(const BlockData& b, const Vec3& end_prog) {
    const PlaneAxes ax = axes(st_.plane);
    const Vec3 s3 = program_pos();
    const Vec2 s = in_plane(s3, st_.plane);
    Vec3 e3 = end_prog;
    Vec2 e = in_plane(e3, st_.plane);
    const bool end_given = b.has(kAxes[ax.a]) || b.has(kAxes[ax.b]);
    int dir = st_.motion == G3 ? 1 : -1;
    Vec2 c;
    const int first = b.has('X') ? b['X'].column : b.has('Y') ? b['Y'].column : b.has('Z') ? b['Z'].column : 0;
    const double tol = 0.01;  // MD21000 CIRCLE_ERROR_CONST
    // Each circle type reads its own words; a word of another type in the block would be
    // dropped, so it is refused (the control's 14040 for a circle defined twice).
    {
        const Value& k_off = b[kCentre[ax.c]];
        if (k_off.set)
            fail(code::alarm_14040, std::string("14040 ") + kCentre[ax.c] + " is no centre coordinate in the working plane (" +
                              kCentre[ax.a] + ", " + kCentre[ax.b] + ")",
                 k_off.column);
        const bool centre = b.has(kCentre[ax.a]) || b.has(kCentre[ax.b]);
        const Value* extra = nullptr;
        const char* what = "";
        if (st_.motion == CIP || st_.motion == CT) {  // CIP, CT: by points and tangent only
            extra = b.cr.set ? &b.cr : b.ar.set ? &b.ar : centre ? &b[b.has(kCentre[ax.a]) ? kCentre[ax.a] : kCentre[ax.b]] : nullptr;
            what = st_.motion == CIP ? "CIP" : "CT";
        } else if (b.cr.set && b.ar.set) {
            extra = &b.ar;
            what = "CR=";
        }
        if (extra)
            fail(code::alarm_14040, std::string("14040 ") + what + " and another definition of the circle (CR=, AR=, I, J, K) in one block",
                 extra->column);
        if (st_.motion != CIP && (b.i1.set || b.j1.set || b.k1.set))
            fail(code::alarm_14040, "14040 I1=, J1=, K1= (the intermediate point) belong to CIP", (b.i1.set ? b.i1 : b.j1.set ? b.j1 : b.k1).column);
    }
    auto centre_words = [&]() -> std::optional<Vec2> {
        const Value& ca = b[kCentre[ax.a]];
        const Value& cb = b[kCentre[ax.b]];
        if (!ca.set && !cb.set) return std::nullopt;
        double va = ca.set ? ca.v * unit() : 0, vb = cb.set ? cb.v * unit() : 0;
        if (ax.a == 0 && ca.set && ca.mod == 1 && st_.diameter) va /= 2;
        if (ax.b == 0 && cb.set && cb.mod == 1 && st_.diameter) vb /= 2;
        return Vec2((ca.set && ca.mod == 1) ? va : s.x() + va, (cb.set && cb.mod == 1) ? vb : s.y() + vb);
    };
    if (st_.motion == CIP) {
        Vec3 m3 = s3;
        const Value* iv[3] = {&b.i1, &b.j1, &b.k1};
        for (int i = 0; i < 3; ++i) {
            if (!iv[i]->set) continue;
            double x = iv[i]->v * unit();
            if (i == 0 && st_.diameter) x /= 2;
            const bool inc = iv[i]->mod == 2 || (iv[i]->mod == 0 && st_.incremental);
            m3[i] = inc ? s3[i] + x : x;
        }
        // Three points in space make a circle in space: only one in the working plane is read.
        if (m3[ax.c] != s3[ax.c] || e3[ax.c] != s3[ax.c])
            fail(code::unsupported_word,
                 "CIP through points off the working plane (a circle in space) is not supported by toolcomp", first);
        const Vec2 m = in_plane(m3, st_.plane);
        const double cr = cross2(m - s, e - s);
        if (std::fabs(cr) < 1e-9 * std::max(1.0, (e - s).squaredNorm()))
            fail(code::alarm_14040, "14040 Error in end point of circle: CIP points on one line", first);
        // Circumcentre of s, m, e.
        const Vec2 a = m - s, bb = e - s;
        const double d = 2 * cross2(a, bb);
        c = s + Vec2(bb.y() * a.squaredNorm() - a.y() * bb.squaredNorm(), a.x() * bb.squaredNorm() - bb.x() * a.squaredNorm()) / d;
        dir = cr > 0 ? 1 : -1;
    } else if (st_.motion == CT) {
        if (!last_tangent_) fail(code::alarm_14040, "14040 CT needs a preceding move to be tangent to", first);
        const Vec2 n = left_normal(*last_tangent_);
        const Vec2 d = e - s;
        const double dn = d.dot(n);
        if (std::fabs(dn) < 1e-9) fail(code::alarm_14040, "14040 Error in end point of circle: CT end point on the tangent", first);
        const double rho = d.squaredNorm() / (2 * dn);
        c = s + n * rho;
        dir = rho > 0 ? 1 : -1;
    } else if (b.cr.set) {
        if (b.has(kCentre[ax.a]) || b.has(kCentre[ax.b]))
            fail(code::alarm_14040, "14040 CR= and the centre I, J, K in one block", b.cr.column);
        const double R = b.cr.v * unit();
        auto cc = center_from_radius(s, e, R, dir);
        if (!cc) {
            if ((e - s).norm() > 2 * std::fabs(R) + tol || (e - s).norm() < 1e-12)
                fail(code::alarm_14040, "14040 Error in end point of circle: CR= too small for the chord", b.cr.column);
            cc = (s + e) / 2;
        }
        c = *cc;
    } else if (b.ar.set) {
        const double A = b.ar.v;
        if (!(A > 0 && A < 360)) fail(code::alarm_14040, "14040 AR= must lie between 0 and 360 degrees", b.ar.column);
        const double ang = A * kPi / 180;
        if (auto cw = centre_words()) {
            if (end_given) fail(code::alarm_14040, "14040 AR= with both centre and end point", b.ar.column);
            c = *cw;
            const Vec2 r = s - c;
            const double t = dir * ang;
            e = c + Vec2(r.x() * std::cos(t) - r.y() * std::sin(t), r.x() * std::sin(t) + r.y() * std::cos(t));
            e3[ax.a] = e.x();
            e3[ax.b] = e.y();
        } else {
            const double chord = (e - s).norm();
            if (chord < 1e-12) fail(code::alarm_14040, "14040 AR= with the end point at the start", b.ar.column);
            const Vec2 u = (e - s) / chord;
            const double dist = (chord / 2) / std::tan(ang / 2);
            c = (s + e) / 2 + left_normal(u) * (dir * dist);
        }
    } else if (auto cw = centre_words()) {
        c = *cw;
    } else {
        fail(code::alarm_14040, "14040 Circle without centre, radius, opening angle or intermediate point", first);
    }
    if (!c.allFinite()) fail(code::alarm_14040, "14040 Error in end point of circle: the centre cannot be computed", first);
    const double rs = (s - c).norm(), re = (e - c).norm();
    if (rs < 1e-9) fail(code::alarm_14040, "14040 Error in end point of circle: radius zero", first);
    if (std::fabs(re - rs) > std::max(tol, 0.001 * rs))
        fail(code::alarm_14040, "14040 Error in end point of circle (start radius " + std::to_string(rs) + ", end radius " +
                          std::to_string(re) + ")", first);
    // The centre in 3D at the start's applicate; the frame must keep the working plane.
    Vec3 c3 = s3;
    c3[ax.a] = c.x();
    c3[ax.b] = c.y();
    const int n = plane_normal_axis(st_.plane);
    const Mat3& A = actual_.a;
    const double sa = std::hypot(A(ax.a, ax.a), A(ax.b, ax.a)), sb = std::hypot(A(ax.a, ax.b), A(ax.b, ax.b));
    if (std::fabs(A(n, ax.a)) > 1e-12 || std::fabs(A(n, ax.b)) > 1e-12 || std::fabs(A(ax.a, n)) > 1e-12 ||
        std::fabs(A(ax.b, n)) > 1e-12)
        fail(code::unsupported_word, "Circles in a frame rotated out of the working plane are not supported by toolcomp", first);
    if (std::fabs(sa - sb) > 1e-9 * std::max(sa, sb)) {
        if (st_.side != 0) fail(code::alarm_10761, "10761 Tool radius compensation for an ellipse (circle in a non-uniform SCALE)", first);
        fail(code::unsupported_word, "Ellipses (circles in a non-uniform SCALE) are not supported by toolcomp", first);
    }
    if (!(feed_ > 0)) fail(code::alarm_10860, "10860 No feedrate programmed", first);
    if (st_.side != 0 && std::fabs(e3[n] - s3[n]) > 1e-9) {
        Vec3 normal = Vec3::Zero();
        normal[n] = 1;
        if (tool_axis_.cross(actual_.a * normal).norm() > 1e-9)
            fail(code::alarm_10760, "10760 Helical axis is not parallel to the tool orientation", first);
    }
    int turns = 0;
    if (b.turn.set) {
        if (!(b.turn.v >= 0 && b.turn.v <= kMaxArcTurns) || b.turn.v != std::floor(b.turn.v))
            fail(code::alarm_14040, "14040 TURN= must be a whole number of turns (0..999999)", b.turn.column);
        turns = int_value(b.turn.v);
    }
    const Vec3 out_end = actual_.apply(e3) + zero_shift_;
    const Vec3 out_c = actual_.apply(c3) + zero_shift_;
    const int out_dir = mirrored() ? -dir : dir;
    Motion m = motion_(out_dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw, out_end);
    m.center = out_c;
    m.turns = turns;
    const Vec2 re2 = e - c;
    last_tangent_ = (dir > 0 ? left_normal(re2) : Vec2(-left_normal(re2))).normalized();
    pos_ = out_end;
    ++moves_;
    sink_.push(m);
}

}  // namespace toolcomp::sinumerik
