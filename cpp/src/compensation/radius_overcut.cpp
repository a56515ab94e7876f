// The radius stage's local overcut watch: distances between tool-centre elements and the
// programmed elements around them (exact for segments and arcs), one warning per element.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "radius_math.hpp"
#include "toolcomp/compensation/overcut.hpp"

namespace toolcomp {

using namespace radius_math;

namespace {

// Angle of q about the centre from the arc's start, in its direction of travel, in [0, 2π).
double arc_angle(const Element2& e, const Vec2& q) {
    double t = std::fmod(e.dir * (ang(q - e.c) - ang(e.p0 - e.c)), 2 * kPi);
    return t < 0 ? t + 2 * kPi : t;
}

// Whether the direction of q from the centre lies within the arc's sweep.
bool on_arc(const Element2& e, const Vec2& q) {
    const double sweep = e.sweep();
    return sweep >= 2 * kPi - 1e-12 || arc_angle(e, q) <= sweep + 1e-12;
}

// An arc whose end lies off its start circle (within the control's spiral tolerance) runs
// as a spiral: the radius changes linearly with the angle swept.
double radius_at(const Element2& e, const Vec2& q) {
    const double r0 = e.radius(), r1 = (e.p1 - e.c).norm(), sweep = e.sweep();
    if (r0 == r1 || sweep >= 2 * kPi - 1e-12) return r0;
    double t = arc_angle(e, q);
    if (t > sweep) t = t - sweep < 2 * kPi - t ? sweep : 0;  // off the arc: its nearer end
    return r0 + (r1 - r0) * t / sweep;
}

double point_distance(const Element2& e, const Vec2& q) {
    if (!e.is_arc) {
        const Vec2 d = e.p1 - e.p0;
        const double len2 = d.squaredNorm();
        const double t = len2 > 0 ? std::clamp((q - e.p0).dot(d) / len2, 0.0, 1.0) : 0.0;
        return (e.p0 + t * d - q).norm();
    }
    const Vec2 v = q - e.c;
    if (v.norm() > 0 && on_arc(e, q)) return std::fabs(v.norm() - radius_at(e, q));
    return std::min((q - e.p0).norm(), (q - e.p1).norm());
}

bool on_element(const Element2& e, const Vec2& q) {
    if (e.is_arc) return on_arc(e, q);
    const Vec2 d = e.p1 - e.p0;
    const double t = (q - e.p0).dot(d);
    return t >= 0 && t <= d.squaredNorm();
}

// Points of arc `a` where its normal runs along `dir` (either way).
void normal_points(const Element2& a, const Vec2& dir, const Element2& other, double& d) {
    if (dir.norm() == 0) return;
    const Vec2 n = dir.normalized();
    for (double s : {-1.0, 1.0}) {
        const Vec2 towards = a.c + s * n;
        if (on_arc(a, towards)) d = std::min(d, point_distance(other, a.c + s * radius_at(a, towards) * n));
    }
}

}  // namespace

// The smallest distance is at an end point of one element, at a crossing, or between two
// interior points on a common normal: a line's normal through an arc's centre, or the line
// through two arcs' centres.
double element_distance(const Element2& a, const Element2& b) {
    double d = std::min({point_distance(b, a.p0), point_distance(b, a.p1), point_distance(a, b.p0),
                         point_distance(a, b.p1)});
    for (const Vec2& x : intersect(a, b))
        if (on_element(a, x) && on_element(b, x)) return 0;
    if (a.is_arc && b.is_arc) {
        normal_points(a, b.c - a.c, b, d);
        normal_points(b, b.c - a.c, a, d);
    } else if (a.is_arc != b.is_arc) {
        const Element2& arc = a.is_arc ? a : b;
        const Element2& line = a.is_arc ? b : a;
        normal_points(arc, left_normal(line.p1 - line.p0), line, d);
    }
    return d;
}

// An arc whose end radius differs from its start radius is only known to within that
// difference (the control's spiral tolerance): it is allowed on both sides.
static double spiral(const Element2& e) { return e.is_arc ? std::fabs((e.p1 - e.c).norm() - e.radius()) : 0.0; }

void OvercutWatch::check(Comp& c, const Prog& p) const {
    const double d = element_distance(c.e, p.e);
    const double margin = d - (c.r - tolerance_ - p.slack - spiral(p.e) - spiral(c.e));
    if (margin < c.worst) {
        c.worst = margin;
        c.dist = d;
        c.near_line = p.line;
    }
}

void OvercutWatch::programmed(const Element2& e, int line) {
    if (neighbours_ <= 0) return;
    prog_.push_back({e, line, 0.0});
    ++count_;
    for (auto& c : comp_) check(c, prog_.back());
    while (prog_.size() > static_cast<std::size_t>(neighbours_) + 2) prog_.pop_front();
}

void OvercutWatch::tangent_slack(double slack) {
    const std::size_t n = prog_.size();
    for (std::size_t i = n >= 2 ? n - 2 : 0; i < n; ++i) prog_[i].slack = std::max(prog_[i].slack, slack);
}

void OvercutWatch::compensated(const Element2& e, int line, double r) {
    if (neighbours_ <= 0 || prog_.empty()) return;
    Comp c{e, line, r, count_, std::numeric_limits<double>::infinity(), 0, 0};
    for (const auto& p : prog_) check(c, p);
    comp_.push_back(c);
}

void OvercutWatch::report(std::vector<Diagnostic>& out, double mm, bool all) {
    while (!comp_.empty() && (all || count_ - comp_.front().seen >= static_cast<std::size_t>(neighbours_))) {
        const Comp& c = comp_.front();
        if (c.worst < 0) {
            char buf[256];
            std::snprintf(buf, sizeof buf,
                          "Overcut: the tool centre comes %.6f mm from the programmed contour of line %d, "
                          "closer than the tool radius %.6f mm (%.6f mm into the part)",
                          c.dist * mm, c.near_line, c.r * mm, (c.r - c.dist) * mm);
            out.push_back({"comp_overcut", Severity::warning, buf, {c.line, 0}});
        }
        comp_.pop_front();
    }
    if (all) {
        prog_.clear();
        count_ = 0;
    }
}

void OvercutWatch::scale(double f) {
    auto conv = [f](Element2& e) {
        e.p0 *= f;
        e.p1 *= f;
        e.c *= f;
    };
    for (auto& p : prog_) {
        conv(p.e);
        p.slack *= f;
    }
    for (auto& c : comp_) {
        conv(c.e);
        c.r *= f;
        c.worst *= f;
        c.dist *= f;
    }
    tolerance_ *= f;
}

}  // namespace toolcomp
