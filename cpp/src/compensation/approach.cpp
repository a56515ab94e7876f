// Heidenhain APPR / DEP geometry (spec §2.5.3). See the header for the conventions.
#include "toolcomp/compensation/approach.hpp"
#include "toolcomp/program/codes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {
namespace {

constexpr double kTwoPi = 2.0 * kPi;

[[noreturn]] void fail(const char* code, const std::string& msg) { throw CompensationError(code, msg, {}); }

const char* kind_name(ApproachKind k) {
    switch (k) {
        case ApproachKind::LT: return "LT";
        case ApproachKind::LN: return "LN";
        case ApproachKind::CT: return "CT";
        case ApproachKind::LCT: return "LCT";
    }
    return "?";
}

Vec2 rotate(const Vec2& v, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

// Common validation; returns the normalised tangent.
Vec2 check_common(const char* fn, ApproachKind kind, const Vec2& t, int side, double r) {
    const std::string what = std::string(fn) + " " + kind_name(kind);
    if (side != 1 && side != -1) fail(code::approach_bad_side, what + ": compensation side must be RL or RR");
    if (!std::isfinite(r) || r < 0) fail(code::approach_bad_tool_radius, what + ": effective tool radius must be >= 0");
    const double n = finite(t) ? t.norm() : 0.0;
    if (!(n > 1e-12)) fail(code::approach_no_tangent, what + ": the contour element has no direction");
    return t / n;
}

void check_len(const char* fn, ApproachKind kind, double len) {
    if (!std::isfinite(len) || len <= 0)
        fail(code::approach_len_not_positive, std::string(fn) + " " + kind_name(kind) + ": LEN must be > 0");
}

void check_cca(const char* fn, double cca) {
    if (!std::isfinite(cca) || cca <= 0 || cca > 360.0 + 1e-9)
        fail(code::approach_cca_out_of_range, std::string(fn) + " CT: CCA must be > 0 and <= 360 degrees");
}

void check_radius(const char* fn, ApproachKind kind, double radius) {
    if (kind == ApproachKind::LCT) {
        if (!std::isfinite(radius) || radius <= 0)
            fail(code::approach_lct_radius_not_positive, std::string(fn) + " LCT: R must be > 0");
    } else if (!std::isfinite(radius) || radius == 0) {
        fail(code::approach_radius_zero, std::string(fn) + " CT: R must not be 0");
    }
}

// The tool-centre circle of a CT/LCT arc tangent to the contour at P (programmed point) whose
// tool-centre point is P_tool = P + r·n.
struct ToolCircle {
    Vec2 c;
    double rho;  // tool arc radius
    int dir;
};

ToolCircle tool_circle(const Vec2& p, const Vec2& n, int side, double r, double radius, const ApproachOptions& o) {
    ToolCircle tc;
    tc.dir = approach_arc_dir(side, radius);
    if (o.ct_radius_on_contour) {
        tc.c = p + radius * n;
        tc.rho = radius > 0 ? radius - r : -radius + r;
    } else {
        tc.c = p + r * n + radius * n;
        tc.rho = std::fabs(radius);
    }
    if (!(tc.rho > tol::length)) fail(code::tool_radius_too_large, "TOOL RADIUS TOO LARGE");
    return tc;
}

// Angle swept from a to b (both radius vectors) in direction dir, in [0, 2π).
double sweep_between(const Vec2& a, const Vec2& b, int dir, double rho) {
    double s = dir * std::atan2(cross2(a, b), a.dot(b));
    if (s < 0) s += kTwoPi;
    if (s * rho < tol::length || (kTwoPi - s) * rho < tol::length) s = 0;
    return s;
}

// Tangent point on circle (c, rho) of a line through p. `dir` is the required sense of the line
// direction (from p towards the point when `towards` is true, from the point towards p otherwise)
// relative to the circle: it continues the arc direction `dir`.
Vec2 tangent_point(const Vec2& p, const Vec2& c, double rho, int dir, bool towards, const char* code,
                   const std::string& msg) {
    const Vec2 v = p - c;
    const double dist = v.norm();
    if (dist < rho - tol::length) fail(code, msg);
    if (dist <= rho + tol::length) return c + v * (rho / dist);  // p on the circle
    const Vec2 u = v / dist;
    const double alpha = std::acos(rho / dist);
    const Vec2 t1 = c + rho * rotate(u, alpha);
    const Vec2 t2 = c + rho * rotate(u, -alpha);
    auto ok = [&](const Vec2& t) {
        const Vec2 line = towards ? Vec2(t - p) : Vec2(p - t);
        return dir * cross2(t - c, line) > 0;
    };
    return ok(t1) ? t1 : t2;
}

// LCT tangent point on the tool-centre circle, in tool space or (alternative) contour space.
Vec2 lct_point(const Vec2& p, const ToolCircle& tc, double r, bool towards, const ApproachOptions& o,
               const char* code, const std::string& msg) {
    if (o.lct_tangency_tool_space || r == 0) return tangent_point(p, tc.c, tc.rho, tc.dir, towards, code, msg);
    const double rc = tc.rho + r;  // contour circle
    const Vec2 ph_c = tangent_point(p, tc.c, rc, tc.dir, towards, code, msg);
    return tc.c + (ph_c - tc.c) * (tc.rho / rc);
}

PathPiece line(const Vec2& a, const Vec2& b, bool tin, bool tout) {
    PathPiece p;
    p.arc = false;
    p.start = a;
    p.end = b;
    p.tangent_in = tin;
    p.tangent_out = tout;
    return p;
}

PathPiece arc(const Vec2& a, const Vec2& b, const Vec2& c, int dir, double sweep, bool tin, bool tout) {
    PathPiece p;
    p.arc = true;
    p.start = a;
    p.end = b;
    p.centre = c;
    p.dir = dir;
    p.sweep = sweep;
    p.tangent_in = tin;
    p.tangent_out = tout;
    return p;
}

}  // namespace

std::vector<PathPiece> approach_path(const Approach& a, const ApproachOptions& o) {
    const Vec2 t = check_common("APPR", a.kind, a.t_a, a.side, a.r);
    const Vec2 n = a.side * left_normal(t);
    const Vec2 pa_tool = a.pa + a.r * n;
    switch (a.kind) {
        case ApproachKind::LT: {
            check_len("APPR", a.kind, a.len);
            const Vec2 ph = a.pa - a.len * t + a.r * n;
            return {line(a.ps, ph, false, false), line(ph, pa_tool, false, true)};
        }
        case ApproachKind::LN: {
            check_len("APPR", a.kind, a.len);
            const Vec2 ph = a.pa + (a.len + a.r) * n;
            return {line(a.ps, ph, false, false), line(ph, pa_tool, false, false)};
        }
        case ApproachKind::CT: {
            check_cca("APPR", a.cca);
            check_radius("APPR", a.kind, a.radius);
            const ToolCircle tc = tool_circle(a.pa, n, a.side, a.r, a.radius, o);
            const double sweep = std::min(a.cca, 360.0) * kPi / 180.0;
            // PH: PA_tool rotated about C against the arc direction.
            const Vec2 ph = tc.c + rotate(pa_tool - tc.c, -tc.dir * sweep);
            return {line(a.ps, ph, false, false), arc(ph, pa_tool, tc.c, tc.dir, sweep, false, true)};
        }
        case ApproachKind::LCT: {
            check_radius("APPR", a.kind, a.radius);
            const ToolCircle tc = tool_circle(a.pa, n, a.side, a.r, a.radius, o);
            const Vec2 ph = lct_point(a.ps, tc, a.r, true, o, code::approach_start_inside_circle,
                                      "APPR LCT: starting point PS lies inside the approach circle (no tangent)");
            const double sweep = sweep_between(ph - tc.c, pa_tool - tc.c, tc.dir, tc.rho);
            const bool smooth = o.lct_tangency_tool_space || a.r == 0;
            return {line(a.ps, ph, false, smooth), arc(ph, pa_tool, tc.c, tc.dir, sweep, smooth, true)};
        }
    }
    fail(code::approach_bad_kind, "APPR: unknown approach function");
}

std::vector<PathPiece> departure_path(const Departure& d, const ApproachOptions& o) {
    const Vec2 t = check_common("DEP", d.kind, d.t_e, d.side, d.r);
    const Vec2 n = d.side * left_normal(t);
    const Vec2 pe_tool = d.pe + d.r * n;
    switch (d.kind) {
        case ApproachKind::LT: {
            check_len("DEP", d.kind, d.len);
            return {line(pe_tool, pe_tool + d.len * t, true, false)};
        }
        case ApproachKind::LN: {
            check_len("DEP", d.kind, d.len);
            return {line(pe_tool, d.pe + (d.len + d.r) * n, false, false)};
        }
        case ApproachKind::CT: {
            check_cca("DEP", d.cca);
            check_radius("DEP", d.kind, d.radius);
            const ToolCircle tc = tool_circle(d.pe, n, d.side, d.r, d.radius, o);
            const double sweep = std::min(d.cca, 360.0) * kPi / 180.0;
            // PN: PE_tool rotated about C in the arc direction.
            const Vec2 pn = tc.c + rotate(pe_tool - tc.c, tc.dir * sweep);
            return {arc(pe_tool, pn, tc.c, tc.dir, sweep, true, false)};
        }
        case ApproachKind::LCT: {
            check_radius("DEP", d.kind, d.radius);
            if (!finite(d.pn)) fail(code::departure_bad_end_point, "DEP LCT: end point PN is undefined");
            const ToolCircle tc = tool_circle(d.pe, n, d.side, d.r, d.radius, o);
            const Vec2 ph = lct_point(d.pn, tc, d.r, false, o, code::departure_end_inside_circle,
                                      "DEP LCT: end point PN lies inside the departure circle (no tangent)");
            const double sweep = sweep_between(pe_tool - tc.c, ph - tc.c, tc.dir, tc.rho);
            const bool smooth = o.lct_tangency_tool_space || d.r == 0;
            return {arc(pe_tool, ph, tc.c, tc.dir, sweep, true, smooth), line(ph, d.pn, smooth, false)};
        }
    }
    fail(code::approach_bad_kind, "DEP: unknown departure function");
}

}  // namespace toolcomp
