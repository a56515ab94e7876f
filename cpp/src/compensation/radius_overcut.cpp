// The radius stage's local overcut watch: distances between tool-centre elements and the
// programmed elements around them (exact for segments and arcs), one warning per element.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "radius_math.hpp"
#include "toolcomp/compensation/overcut.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp {

using namespace radius_math;

namespace {

// Whether the direction of q from the centre lies within the arc's sweep: cross products
// against the start and end radius vectors (no angles).
bool on_arc(const Swept& a, const Vec2& q) {
    if (a.full) return true;
    const Vec2 v = q - a.e.c;
    const double eps = 1e-12 * a.r0 * v.norm();
    const double from_start = a.e.dir * cross2(a.u, v), to_end = a.e.dir * cross2(v, a.w);
    // A minor arc: between start and end; a major one: anywhere but strictly inside the
    // minor arc from its end back to its start.
    return a.major ? from_start >= -eps || to_end >= -eps : from_start >= -eps && to_end >= -eps;
}

// A spiral's radius changes linearly with the angle swept; radius differences at rounding
// level are left out (they are within the allowance the watch makes for spirals).
double radius_at(const Swept& a, const Vec2& q) {
    if (a.sweep == 0 || a.full) return a.r0;
    double t = std::fmod(a.e.dir * (ang(q - a.e.c) - ang(a.u)), 2 * kPi);
    if (t < 0) t += 2 * kPi;
    if (t > a.sweep) t = t - a.sweep < 2 * kPi - t ? a.sweep : 0;  // off the arc: its nearer end
    return a.r0 + (a.r1 - a.r0) * t / a.sweep;
}

double segment_point(const Element2& l, const Vec2& q) {
    const Vec2 d = l.p1 - l.p0;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((q - l.p0).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (l.p0 + t * d - q).norm();
}

double point_distance(const Swept& a, const Vec2& q) {
    const Element2& e = a.e;
    if (!e.is_arc) return segment_point(e, q);
    const double v = (q - e.c).norm();
    if (v > 0 && on_arc(a, q)) return std::fabs(v - radius_at(a, q));
    return std::sqrt(std::min((q - e.p0).squaredNorm(), (q - e.p1).squaredNorm()));
}

bool on_element(const Swept& a, const Vec2& q) {
    if (a.e.is_arc) return on_arc(a, q);
    const Vec2 d = a.e.p1 - a.e.p0;
    const double t = (q - a.e.p0).dot(d);
    return t >= 0 && t <= d.squaredNorm();
}

// Points of arc `a` where its normal runs along `dir` (either way).
void normal_points(const Swept& a, const Vec2& dir, const Swept& other, double& d) {
    const double n2 = dir.squaredNorm();
    if (n2 == 0) return;
    const Vec2 n = dir / std::sqrt(n2);
    for (double s : {-1.0, 1.0}) {
        const Vec2 towards = a.e.c + s * n;
        if (on_arc(a, towards)) d = std::min(d, point_distance(other, a.e.c + s * radius_at(a, towards) * n));
    }
}


double beyond_line(const Swept& l, const Element2& o) {
    if (l.len == 0) return 0;
    const Vec2 d = l.e.p1 - l.e.p0;
    const double s0 = cross2(d, o.p0 - l.e.p0), s1 = cross2(d, o.p1 - l.e.p0);
    return s0 * s1 > 0 ? std::min(std::fabs(s0), std::fabs(s1)) / l.len : 0.0;
}

// Whether every point of `a` lies on the closed side n.(x - o) <= 0 of the line through o.
bool within_half_plane(const Swept& a, const Vec2& o, const Vec2& n) {
    if (n.dot(a.e.p0 - o) > 0 || n.dot(a.e.p1 - o) > 0) return false;
    if (!a.e.is_arc) return true;
    // An arc reaches furthest along n at an end or where it points along n.
    return !on_arc(a, a.e.c + n) || n.dot(a.e.c - o) + std::max(a.r0, a.r1) * n.norm() <= 0;
}

// The distance of `a` from the arc `b` when b is a circular arc of at most half a turn and
// `a` lies wholly before its start or after its end (on the far side of the line through
// its centre and that end): from a point off an arc's sweep the nearest point of the arc is
// an end (the distance to a point of the circle grows with the angle between them), so the
// distance is a's from b's nearer end. 0: not so.
double off_sweep(const Swept& a, const Swept& b) {
    if (!b.e.is_arc || b.full || b.major || b.sweep != 0) return 0;
    const Vec2 before = b.e.dir * left_normal(b.u), after = -b.e.dir * left_normal(b.w);
    if (!within_half_plane(a, b.e.c, before) && !within_half_plane(a, b.e.c, after)) return 0;
    return std::min(point_distance(a, b.e.p0), point_distance(a, b.e.p1));
}

}  // namespace

double distance_lower_bound(const Swept& a, const Swept& b, double enough) {
    const auto rmin = [](const Swept& s) { return std::min(s.r0, s.r1); };
    const auto rmax = [](const Swept& s) { return std::max(s.r0, s.r1); };
    if (!a.e.is_arc && !b.e.is_arc) {
        const double first = beyond_line(a, b.e);
        return first >= enough ? first : std::max(first, beyond_line(b, a.e));
    }
    if (a.e.is_arc && b.e.is_arc) {
        const double D = (a.e.c - b.e.c).norm();
        const double ring = std::max(std::max(D - rmax(a) - rmax(b), rmin(a) - D - rmax(b)), rmin(b) - D - rmax(a));
        if (ring >= enough) return ring;
        // a corner arc about an end of the next or last arc, turning away from it
        return std::max({ring, off_sweep(a, b), off_sweep(b, a)});
    }
    const Swept& arc = a.e.is_arc ? a : b;
    const Element2& line = a.e.is_arc ? b.e : a.e;
    const double far = std::sqrt(std::max((line.p0 - arc.e.c).squaredNorm(), (line.p1 - arc.e.c).squaredNorm()));
    double bound = segment_point(line, arc.e.c) - rmax(arc);
    if (bound >= enough) return bound;
    bound = std::max(bound, rmin(arc) - far);
    if (bound >= enough) return bound;
    // An arc about an end E of the segment (a corner arc about its programmed corner) that
    // turns away from the segment: seen along the segment from E, every direction of the arc
    // points backwards, so E is the nearest point of the segment to every point of the arc
    // moved by E - centre. The largest component along the segment is at an end of the arc,
    // or where the arc points along it.
    for (int end = 0; end < 2; ++end) {
        const Vec2& E = end ? line.p1 : line.p0;
        const Vec2 along = (end ? line.p0 : line.p1) - E;
        if (arc.u.dot(along) <= 0 && arc.w.dot(along) <= 0 && !on_arc(arc, arc.e.c + along))
            bound = std::max(bound, rmin(arc) - (arc.e.c - E).norm());
    }
    if (bound >= enough) return bound;
    // the segment off the arc's sweep (a line after the arc it joins, on the tool's side)
    return std::max(bound, off_sweep(a.e.is_arc ? b : a, arc));
}

Swept::Swept(const Element2& el) : e(el) {
    lo = e.p0.cwiseMin(e.p1);
    hi = e.p0.cwiseMax(e.p1);
    if (!e.is_arc) {
        len = (e.p1 - e.p0).norm();
        return;
    }
    u = e.p0 - e.c;
    w = e.p1 - e.c;
    r0 = u.norm();
    r1 = w.norm();
    spiral = std::fabs(r1 - r0);
    // Element2::sweep's classification without its atan2 (taken only for true spirals): a
    // whole circle when the end comes back to within 1e-12 rad of the start.
    const double turn = e.dir * cross2(u, w), along = u.dot(w);
    full = e.turns > 0 || (along > 0 && std::fabs(turn) <= 1e-12 * along);
    major = !full && turn < 0;
    if (spiral > 1e-9 * (1 + r0)) sweep = e.sweep();
    // The points where the arc runs along an axis, where it passes them (a spiral: all four,
    // at its larger radius: it lies within the ring of its start and end radii). `passes` is
    // on_arc() for an axis direction d (|d| = 1): the cross products with d are components
    // of u and w.
    const double rm = std::max(r0, r1), eps = 1e-12 * r0;
    const auto passes = [&](double from_start, double to_end) {
        if (full || sweep != 0) return true;
        from_start *= e.dir;
        to_end *= e.dir;
        return major ? from_start >= -eps || to_end >= -eps : from_start >= -eps && to_end >= -eps;
    };
    // cross2(u, d) and cross2(d, w) for d = +x, -x, +y, -y
    if (passes(-u.y(), w.y())) hi.x() = std::max(hi.x(), e.c.x() + rm);
    if (passes(u.y(), -w.y())) lo.x() = std::min(lo.x(), e.c.x() - rm);
    if (passes(u.x(), -w.x())) hi.y() = std::max(hi.y(), e.c.y() + rm);
    if (passes(-u.x(), w.x())) lo.y() = std::min(lo.y(), e.c.y() - rm);
}

// The smallest distance is at an end point of one element, at a crossing, or between two
// interior points on a common normal: a line's normal through an arc's centre, or the line
// through two arcs' centres.
double element_distance(const Swept& a, const Swept& b) {
    double d = std::min({point_distance(b, a.e.p0), point_distance(b, a.e.p1), point_distance(a, b.e.p0),
                         point_distance(a, b.e.p1)});
    for (const Vec2& x : intersect(a.e, b.e))
        if (on_element(a, x) && on_element(b, x)) return 0;
    if (a.e.is_arc && b.e.is_arc) {
        normal_points(a, b.e.c - a.e.c, b, d);
        normal_points(b, b.e.c - a.e.c, a, d);
    } else if (a.e.is_arc != b.e.is_arc) {
        const Swept& arc = a.e.is_arc ? a : b;
        const Swept& line = a.e.is_arc ? b : a;
        normal_points(arc, left_normal(line.e.p1 - line.e.p0), line, d);
    }
    return d;
}

inline void OvercutWatch::check(Comp& c, const Prog& p) const {
    const double closest = c.r - tolerance_ - p.slack - p.e.spiral - c.e.spiral;
    if (closest <= 0 || box_gap2(c.e, p.e) >= closest * closest) return;  // apart: no warning from it
    check_close(c, p, closest);
}

[[gnu::noinline]] void OvercutWatch::check_close(Comp& c, const Prog& p, double closest) const {
    if (distance_lower_bound(c.e, p.e, closest) >= closest) return;  // cannot come closer: no warning from it
    const double d = element_distance(c.e, p.e);
    const double margin = d - closest;
    if (margin < c.worst) {
        c.worst = margin;
        c.dist = d;
        c.near_line = p.line;
    }
}

void OvercutWatch::programmed(const Element2& e, int line) {
    if (neighbours_ <= 0) return;
    // Kept from neighbours + 2 before the last compensated element's `settled` on (the next
    // one's window starts there or later): the ones before are dropped in bulk now and then
    // (not one at a time from the front of the vector).
    const std::size_t keep = static_cast<std::size_t>(neighbours_) + 2 + std::min(count_ + 1 - settled_, kLag);
    if (prog_.size() >= keep + 32) prog_.erase(prog_.begin(), prog_.end() - static_cast<std::ptrdiff_t>(keep - 1));
    prog_.push_back({Swept(e), line, 0.0});
    ++count_;
    const Prog& p = prog_.back();
    for (std::size_t i = comp_head_, n = comp_.size(); i < n; ++i) check(comp_[i], p);
}

void OvercutWatch::tangent_slack(double slack) {
    const std::size_t n = prog_.size();
    for (std::size_t i = n >= 2 ? n - 2 : 0; i < n; ++i) prog_[i].slack = std::max(prog_[i].slack, slack);
}

void OvercutWatch::compensated(const Element2& e, int line, int file, double r, std::size_t settled) {
    if (neighbours_ <= 0 || prog_.empty()) return;
    settled = std::min(settled, count_);
    settled_ = settled;
    // An arc is no shorter than its chord: its length is worked out only for short chords.
    if ((e.p1 - e.p0).norm() <= tol::length && e.length() <= tol::length) return;
    comp_.push_back({Swept(e), line, file, r, settled, std::numeric_limits<double>::infinity(), 0, 0});
    Comp& c = comp_.back();
    // The programmed elements from neighbours + 2 before `settled` on, as far as seen (the
    // rest are met as they come, up to neighbours after `settled`).
    const std::size_t before = static_cast<std::size_t>(neighbours_) + 2 + (count_ - settled);
    const std::size_t n = prog_.size();
    for (std::size_t i = n > before ? n - before : 0; i < n; ++i) check(c, prog_[i]);
}

void OvercutWatch::report(std::vector<Diagnostic>& out, double mm, bool all) {
    std::size_t done = comp_head_;
    for (; done < comp_.size() && (all || count_ - comp_[done].seen >= static_cast<std::size_t>(neighbours_)); ++done) {
        const Comp& c = comp_[done];
        if (c.worst < 0) {
            char buf[256];
            std::snprintf(buf, sizeof buf,
                          "Overcut: the tool centre comes %.6f mm from the programmed contour of line %d, "
                          "closer than the tool radius %.6f mm (%.6f mm into the part)",
                          c.dist * mm, c.near_line, c.r * mm, (c.r - c.dist) * mm);
            out.push_back({code::comp_overcut, Severity::warning, buf, {c.line, 0, {}, c.file}});
        }
    }
    comp_head_ = done;
    if (comp_head_ == comp_.size() || comp_head_ >= 32) {
        comp_.erase(comp_.begin(), comp_.begin() + static_cast<std::ptrdiff_t>(comp_head_));
        comp_head_ = 0;
    }
    if (all) {
        prog_.clear();
        count_ = settled_ = 0;
    }
}

void OvercutWatch::scale(double f) {
    auto conv = [f](Swept& s) {
        Element2 e = s.e;
        e.p0 *= f;
        e.p1 *= f;
        e.c *= f;
        s = Swept(e);
    };
    for (auto& p : prog_) {
        conv(p.e);
        p.slack *= f;
    }
    for (auto& c : comp_) {  // reported ones too: harmless
        conv(c.e);
        c.r *= f;
        c.worst *= f;
        c.dist *= f;
    }
    tolerance_ *= f;
}

}  // namespace toolcomp
