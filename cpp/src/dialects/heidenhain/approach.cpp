// APPR and DEP blocks: the tool-centre paths of contour approach and departure (geometry in
// compensation/approach.hpp), joined to the compensated contour. APPR waits for the first
// contour element (its tangent at PA decides the path); DEP cancels compensation after the
// last element ends perpendicular at PE.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "interp.hpp"

namespace toolcomp::heidenhain {

namespace {
ApproachKind kind_of(const std::string& k, bool& polar) {
    polar = k.size() > 2 && k[0] == 'P';
    const std::string base = polar ? k.substr(1) : k;
    if (base == "LT") return ApproachKind::LT;
    if (base == "LN") return ApproachKind::LN;
    if (base == "CT") return ApproachKind::CT;
    if (base == "LCT") return ApproachKind::LCT;
    throw std::invalid_argument(k);
}
}  // namespace

// APPR LT|LN|CT|LCT (and PLT, PLN, PCT, PLCT about the pole) X Y [Z] LEN|CCA R RL|RR [F] [M]
void Interp::approach(Tokens t) {
    if (t.size() < 2) fail("approach_kind", "APPR needs LT, LN, CT or LCT", t[0].column);
    bool polar = false;
    ApproachKind kind;
    try {
        kind = kind_of(t[1].key, polar);
    } catch (const std::invalid_argument&) {
        fail("approach_kind", "Unknown APPR function " + t[1].key, t[1].column);
    }
    if (side_ != 0)
        fail("unsupported_appr", "APPR while compensation is active (a connecting element) is not supported by toolcomp",
             t[0].column);
    const double feed_before = feed_;
    const bool rapid_before = last_rapid_;
    int side = 0;
    for (const Token& k : t) side = k.key == "RL" ? 1 : k.key == "RR" ? -1 : side;
    // Feed, M functions; RL/RR are taken here, not as a start of compensation by modal_words.
    for (std::size_t i = 2; i < t.size(); ++i)
        if (t[i].key == "F" && t[i].has_value) feed_ = t[i].value * (prog_.inch ? 2.54 : 1.0);
    if (kind == ApproachKind::LCT && feed_ <= 0)
        fail("no_feed", "APPR LCT needs a feed: none programmed up to the approach block", t[0].column);
    Vec3 pa = end_point(t, 2);
    if (polar) {
        if (!pole_) fail("no_circle_centre", "CIRCLE CENTER UNDEFINED", t[0].column);
        const Vec2 rel = plane2(pos_) - *pole_;
        double pr = rel.norm(), ang = std::atan2(rel.y(), rel.x()) * 180 / kPi;
        if (auto v = number(t, "PR")) pr = *v;
        if (auto v = number(t, "IPR")) pr += *v;
        if (auto v = number(t, "PA")) ang = *v;
        if (auto v = number(t, "IPA")) ang += *v;
        pa = with_plane(pa, *pole_ + pr * Vec2(std::cos(ang * kPi / 180), std::sin(ang * kPi / 180)));
    }
    PendingApproach p;
    p.a.kind = kind;
    p.a.ps = plane2(pos_);
    p.a.pa = plane2(pa);
    // APPR with R0: the path is computed for radius 0 and RR (the direction of approach).
    p.a.side = side == 0 ? -1 : side;
    p.a.r = side == 0 ? 0 : radius_;
    p.a.len = number(t, "LEN").value_or(0);
    p.a.cca = number(t, "CCA").value_or(0);
    p.a.radius = number(t, "R").value_or(0);
    p.ps = pos_;
    p.depth = pa[axes(plane_).c];
    p.feed_arc = feed_;
    p.feed_lead = kind == ApproachKind::LCT ? feed_ : (rapid_before ? std::nan("") : feed_before);
    p.line = line_;
    approach_ = p;
    side_ = side;
    pos_ = pa;
}

// Tool-centre pieces as moves without compensation; the tool axis goes to depth h after
// piece `depth_after` (APPR: at PH, in the plane first; DEP: at the end).
void Interp::emit_pieces(const std::vector<PathPiece>& pieces, double h, double feed_first, double feed_rest,
                         std::size_t depth_after) {
    auto ax = axes(plane_);
    Vec3 at = pos_;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const PathPiece& pc = pieces[i];
        if (pc.length() < 1e-12 && !(pc.arc && pc.sweep > 0)) continue;
        Motion m = motion_to(pc.arc ? (pc.dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw) : MotionKind::line, at);
        m.start = with_plane(at, pc.start);
        m.end = with_plane(at, pc.end);
        if (pc.arc) m.center = with_plane(at, pc.centre);
        const double f = i == 0 ? feed_first : feed_rest;
        if (std::isnan(f)) m.kind = MotionKind::rapid;
        m.feed = f;
        m.radius = {};
        sink_.push(m);
        at = m.end;
        if (i == std::min(depth_after, pieces.size() - 1) && at[ax.c] != h) {  // then to depth in the tool axis
            Motion z = m;
            z.kind = MotionKind::line;
            z.center = Vec3::Constant(std::nan(""));
            z.start = at;
            z.end = at;
            z.end[ax.c] = h;
            z.feed = feed_rest;
            sink_.push(z);
            at = z.end;
        }
    }
    pos_ = at;
}

void Interp::emit_approach(const Motion& first) {
    PendingApproach p = *approach_;
    approach_.reset();
    const Vec2 s = plane2(first.start);
    Vec2 ta;
    if (first.is_arc()) {
        const Vec2 u = (s - plane2(first.center)).normalized();
        ta = (first.kind == MotionKind::arc_ccw ? 1.0 : -1.0) * left_normal(u);
    } else {
        ta = plane2(first.end) - s;
    }
    if (ta.norm() < 1e-12) throw ProgramError("approach_tangent", "The first contour element after APPR has no direction", {p.line, 0});
    p.a.t_a = ta.normalized();
    std::vector<PathPiece> pieces;
    try {
        pieces = approach_path(p.a, approach_options());
    } catch (const Error& e) {
        throw CompensationError(e.code(), e.what(), {p.line, 0});
    }
    const Vec3 pa_programmed = pos_;
    const int line = line_;
    line_ = p.line;
    pos_ = p.ps;
    emit_pieces(pieces, p.depth, p.feed_lead, p.feed_arc, 0);
    // Compensation starts at PA_tool: a zero-length activation move the radius stage ends
    // where the first element's equidistant starts.
    if (side_ != 0) {
        Motion act = motion_to(MotionKind::line, pa_programmed);
        act.generated = true;
        act.feed = p.feed_arc;
        sink_.push(act);
    }
    pos_ = pa_programmed;
    line_ = line;
}

// DEP LT LEN | LN LEN | CT CCA R | LCT X Y R (and PLCT): ends compensation.
void Interp::departure(Tokens t) {
    if (t.size() < 2) fail("departure_kind", "DEP needs LT, LN, CT or LCT", t[0].column);
    bool polar = false;
    ApproachKind kind;
    try {
        kind = kind_of(t[1].key, polar);
    } catch (const std::invalid_argument&) {
        fail("departure_kind", "Unknown DEP function " + t[1].key, t[1].column);
    }
    if (!pending_) fail("departure_without_contour", "DEP needs a contour element before it", t[0].column);
    for (std::size_t i = 2; i < t.size(); ++i)
        if (t[i].key == "F" && t[i].has_value) feed_ = t[i].value * (prog_.inch ? 2.54 : 1.0);
    Departure d;
    d.kind = kind;
    d.pe = plane2(pos_);
    d.t_e = end_tangent();
    d.side = side_ == 0 ? -1 : side_;
    d.r = side_ == 0 ? 0 : radius_;
    d.len = number(t, "LEN").value_or(0);
    d.cca = number(t, "CCA").value_or(0);
    d.radius = number(t, "R").value_or(0);
    Vec3 pn = end_point(t, 2);
    if (polar) {
        if (!pole_) fail("no_circle_centre", "CIRCLE CENTER UNDEFINED", t[0].column);
        double pr = number(t, "PR").value_or(0), ang = number(t, "PA").value_or(0);
        pn = with_plane(pn, *pole_ + pr * Vec2(std::cos(ang * kPi / 180), std::sin(ang * kPi / 180)));
    }
    d.pn = plane2(pn);
    std::vector<PathPiece> pieces;
    try {
        pieces = departure_path(d, approach_options());
    } catch (const Error& e) {
        fail(e.code().c_str(), e.what(), t[0].column);
    }
    sink_.push(*pending_);
    pending_.reset();
    if (side_ != 0) sink_.control({ControlKind::radius_off, line_});
    side_ = 0;
    lookahead_ = 0;
    emit_pieces(pieces, pn[axes(plane_).c], feed_, feed_, pieces.size());
}

}  // namespace toolcomp::heidenhain
