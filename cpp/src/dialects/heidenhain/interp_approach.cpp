// APPR and DEP blocks: the tool-centre paths of contour approach and departure (geometry in
// compensation/approach.hpp), joined to the compensated contour. APPR waits for the first
// contour element (its tangent at PA decides the path); DEP cancels compensation after the
// last element ends perpendicular at PE.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

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
// The feed and M functions of an APPR or DEP block (FMAX is not read there: the approach and
// departure run at F).
void Interp::approach_words(Tokens t, ApproachKind kind, bool polar) {
    // The words of the other kinds and of the other coordinates would be dropped.
    if (polar)
        refuse_plane_axes(t, "the polar kind takes its point as PR and PA", 2);
    else
        refuse_words(t, {"PR", "IPR", "PA", "IPA"}, "polar coordinates need the polar kind (APPR PLT, ...)", 2);
    if (kind == ApproachKind::LT || kind == ApproachKind::LN) refuse_words(t, {"CCA"}, "it has no arc", 2);
    if (kind == ApproachKind::CT || kind == ApproachKind::LCT) refuse_words(t, {"LEN"}, "it approaches on an arc", 2);
    if (kind == ApproachKind::LCT) refuse_words(t, {"CCA"}, "its arc ends tangent to the contour", 2);
    if (kind == ApproachKind::LT || kind == ApproachKind::LN)
        for (std::size_t i = 2; i < t.size(); ++i)
            if (t[i].is("R") && t[i].has_value && t[i].value != 0)
                fail(code::bad_word, "R is not read in " + t[0].key + " " + t[1].key + " blocks: it has no arc", t[i].column);
    for (std::size_t i = 2; i < t.size(); ++i) {
        if (t[i].is("F") && t[i].has_value) feed_ = t[i].value * (prog_.inch ? 2.54 : 1.0);
        if (t[i].is("FMAX")) fail(code::unsupported_word, t[0].key + " with FMAX is not supported by toolcomp", t[i].column);
        if (t[i].is("M") && t[i].has_value) m_function(t, t[i]);
    }
}

void Interp::approach(Tokens t) {
    if (t.size() < 2) fail(code::approach_kind, "APPR needs LT, LN, CT or LCT", t[0].column);
    refuse_scaled("APPR", t[0].column);
    bool polar = false;
    ApproachKind kind;
    try {
        kind = kind_of(t[1].key, polar);
    } catch (const std::invalid_argument&) {
        fail(code::approach_kind, "Unknown APPR function " + t[1].key, t[1].column);
    }
    const double feed_before = feed_;
    const bool rapid_before = last_rapid_;
    int side = 0;
    const Token* r0 = nullptr;
    for (const Token& k : t) {
        side = k.is("RL") ? 1 : k.is("RR") ? -1 : side;
        if (k.is("R") && k.has_value && k.value == 0) r0 = &k;
    }
    // Compensation already active (spec §2.5.1): the APPR block does not change it and is a
    // connecting element: its path is computed on the contour and compensated like any
    // other contour element (APPR LT tangential, LN perpendicular, CT/LCT a tangential arc).
    const bool connecting = side_ != 0;
    if (connecting) {
        if (r0)
            fail(code::appr_cancels_comp,
                 "APPR with R0 while radius compensation is active: cancel it with R0 in an L block first", r0->column);
        if (side != 0 && side != side_) fail(code::comp_side_change, profile_.radius.messages.side_change, t[0].column);
        side = side_;
    }
    // Feed, M functions; RL/RR are taken here, not as a start of compensation by modal_words.
    approach_words(t, kind, polar);
    if (feed_ <= 0) fail(code::no_feed, "APPR needs a feed: none programmed up to the approach block", t[0].column);
    Vec3 pa = end_point(t, 2);
    if (polar) {
        if (!pole_) fail(code::no_circle_centre, "CIRCLE CENTER UNDEFINED", t[0].column);
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
    // A connecting element: radius 0 on the active side (the compensation stage offsets it).
    p.a.side = side == 0 ? -1 : side;
    p.a.r = side == 0 || connecting ? 0 : radius_;
    p.connecting = connecting;
    p.a.len = number(t, "LEN").value_or(0);
    p.a.cca = number(t, "CCA").value_or(0);
    p.a.radius = number(t, "R").value_or(0);
    p.ps = pos_;
    p.depth = pa[axes(plane_).c];
    // TNC 426 / iTNC 530: APPR LCT with X, Y and Z all programmed moves from PS to PH in all
    // three axes, then in the plane to PA; every other APPR reaches PH in the plane first.
    if (kind == ApproachKind::LCT) {
        static constexpr std::string_view abs_axis[3] = {"X", "Y", "Z"}, inc_axis[3] = {"IX", "IY", "IZ"};
        bool given[3] = {false, false, false};
        for (std::size_t i = 2; i < t.size(); ++i)
            for (int a = 0; a < 3; ++a) given[a] = given[a] || ((t[i].is(abs_axis[a]) || t[i].is(inc_axis[a])) && t[i].has_value);
        p.depth_with_lead = given[0] && given[1] && given[2];
    }
    p.feed_arc = feed_;
    p.feed_lead = kind == ApproachKind::LCT ? feed_ : (rapid_before ? std::nan("") : feed_before);
    p.line = line_;
    approach_ = p;
    side_ = side;
    pos_ = pa;
}

// Tool-centre pieces as moves without compensation; the tool axis goes to depth h after
// piece `depth_after` (APPR: at PH, in the plane first; DEP: at the end), or with the first
// piece (kDepthWithFirst).
void Interp::emit_pieces(const std::vector<PathPiece>& pieces, double h, double feed_first, double feed_rest,
                         std::size_t depth_after) {
    auto ax = axes(plane_);
    const bool with_first = depth_after == kDepthWithFirst;
    if (with_first) depth_after = 0;
    ++moves_;  // a first piece without plane motion: straight to depth
    Vec3 at = pos_;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const PathPiece& pc = pieces[i];
        if (pc.length() < 1e-12 && !(pc.arc && pc.sweep > 0)) continue;
        Motion m = motion_to(pc.arc ? (pc.dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw) : MotionKind::line, at);
        m.start = with_plane(at, pc.start);
        m.end = with_plane(at, pc.end);
        if (with_first && i == 0 && !pc.arc) m.end[ax.c] = h;
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

namespace {
// Unit tangent at the start of a move in the plane (zero for a move without plane motion).
Vec2 start_tangent(const Motion& m, Plane plane) {
    const Vec2 s = in_plane(m.start, plane);
    Vec2 t;
    if (m.is_arc()) {
        const Vec2 u = (s - in_plane(m.center, plane)).normalized();
        t = (m.kind == MotionKind::arc_ccw ? 1.0 : -1.0) * left_normal(u);
    } else {
        t = in_plane(m.end, plane) - s;
    }
    return t.norm() < 1e-12 ? Vec2(Vec2::Zero()) : Vec2(t.normalized());
}

// The approach path of a pending APPR, now that the first contour element is known.
std::vector<PathPiece> pending_path(Approach& a, const Motion& first, Plane plane, int line,
                                    const ApproachOptions& o) {
    a.t_a = start_tangent(first, plane);
    if (a.t_a.norm() < 1e-12)
        throw ProgramError(code::approach_tangent, "The first contour element after APPR has no direction", {line, 0});
    try {
        return approach_path(a, o);
    } catch (const Error& e) {
        throw CompensationError(e.code(), e.what(), {line, 0});
    }
}
}  // namespace

void Interp::emit_approach(const Motion& first) {
    PendingApproach p = *approach_;
    approach_.reset();
    const std::vector<PathPiece> pieces = pending_path(p.a, first, plane_, p.line, approach_options());
    const Vec3 pa_programmed = pos_;
    const int line = line_;
    line_ = p.line;
    pos_ = p.ps;
    emit_pieces(pieces, p.depth, p.feed_lead, p.feed_arc, p.depth_with_lead ? kDepthWithFirst : 0);
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

// Puts APPR/DEP pieces computed on the contour (tool radius 0) as contour elements of the
// current block, compensated as the active RL/RR requests; the tool axis goes to `h` after
// piece `depth_after`, or with the first piece (kDepthWithFirst).
void Interp::put_contour_pieces(const std::vector<PathPiece>& pieces, const Vec3& from, double h,
                                double feed_first, double feed_rest, std::size_t depth_after) {
    const int c = axes(plane_).c;
    const bool with_first = depth_after == kDepthWithFirst;
    if (with_first) depth_after = 0;
    Vec3 at = from;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const PathPiece& pc = pieces[i];
        if (pc.length() > 1e-12 || (pc.arc && pc.sweep > 0)) {
            const double f = i == 0 ? feed_first : feed_rest;
            Motion m = motion_to(pc.arc ? (pc.dir > 0 ? MotionKind::arc_ccw : MotionKind::arc_cw)
                                        : (std::isnan(f) ? MotionKind::rapid : MotionKind::line),
                                 at);
            m.start = with_plane(at, pc.start);
            m.end = with_plane(at, pc.end);
            if (with_first && i == 0 && !pc.arc) m.end[c] = h;
            if (pc.arc) m.center = with_plane(at, pc.centre);
            m.feed = m.kind == MotionKind::rapid ? std::nan("") : f;
            ++plane_moves_;
            put(m);
            at = m.end;
        }
        if (i == std::min(depth_after, pieces.size() - 1) && at[c] != h) {  // then to depth in the tool axis
            Motion z = motion_to(MotionKind::line, at);
            z.start = at;
            z.end = at;
            z.end[c] = h;
            z.feed = feed_rest;
            put(z);
            at = z.end;
        }
    }
    pos_ = at;
}

// APPR while compensation is active: PS is the contour point where the previous element
// ended; the approach path is computed on the contour (radius 0, the active side for the
// direction of CT/LCT arcs and of LN) and put before the first contour element as
// compensated elements of the APPR block, so the compensation stage joins and offsets them
// like any other contour (PS -> PH with the feed rules of APPR, then PH -> PA).
void Interp::emit_connecting_approach(const Motion& first) {
    PendingApproach p = *approach_;
    approach_.reset();
    const std::vector<PathPiece> pieces = pending_path(p.a, first, plane_, p.line, approach_options());
    const Vec3 pa_programmed = pos_;
    const int line = line_;
    line_ = p.line;
    put_contour_pieces(pieces, p.ps, p.depth, p.feed_lead, p.feed_arc, p.depth_with_lead ? kDepthWithFirst : 0);
    pos_ = pa_programmed;
    line_ = line;
}

// DEP LT LEN | LN LEN | CT CCA R | LCT X Y R (and PLCT): ends compensation. With the active
// RL/RR programmed again in the DEP block, compensation stays on (spec §2.5.1): the
// departure is a connecting element computed on the contour and compensated.
void Interp::departure(Tokens t) {
    if (t.size() < 2) fail(code::departure_kind, "DEP needs LT, LN, CT or LCT", t[0].column);
    refuse_scaled("DEP", t[0].column);
    bool polar = false;
    ApproachKind kind;
    try {
        kind = kind_of(t[1].key, polar);
    } catch (const std::invalid_argument&) {
        fail(code::departure_kind, "Unknown DEP function " + t[1].key, t[1].column);
    }
    if (!pending_) fail(code::departure_without_contour, "DEP needs a contour element before it", t[0].column);
    int side = 0;
    for (const Token& k : t)
        if (k.is("RL") || k.is("RR")) {
            side = k.is("RL") ? 1 : -1;
            if (side_ == 0) fail(code::dep_starts_comp, "DEP cannot switch radius compensation on", k.column);
            if (side != side_) fail(code::comp_side_change, profile_.radius.messages.side_change, k.column);
        }
    const bool keep = side != 0;  // RL/RR programmed again: compensation stays on
    approach_words(t, kind, polar);
    if (feed_ <= 0) fail(code::no_feed, "DEP needs a feed: none programmed up to the departure block", t[0].column);
    Departure d;
    d.kind = kind;
    d.pe = plane2(pos_);
    d.t_e = end_tangent();
    d.side = side_ == 0 ? -1 : side_;
    d.r = side_ == 0 || keep ? 0 : radius_;
    d.len = number(t, "LEN").value_or(0);
    d.cca = number(t, "CCA").value_or(0);
    d.radius = number(t, "R").value_or(0);
    Vec3 pn = end_point(t, 2);
    if (polar) {
        if (!pole_) fail(code::no_circle_centre, "CIRCLE CENTER UNDEFINED", t[0].column);
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
    if (keep) {
        put_contour_pieces(pieces, pos_, pn[axes(plane_).c], feed_, feed_, pieces.size());
        return;
    }
    sink_.push(*pending_);
    pending_.reset();
    if (side_ != 0) sink_.control({ControlKind::radius_off, line_, Vec3::Zero(), file_});
    side_ = 0;
    lookahead_ = 0;
    emit_pieces(pieces, pn[axes(plane_).c], feed_, feed_, pieces.size());
}

}  // namespace toolcomp::heidenhain
