#include "toolcomp/geometry/element.hpp"

#include <cmath>

namespace toolcomp {

namespace {
Vec2 unit_or_zero(const Vec2& v) {
    double n = v.norm();
    return n > tol::length ? Vec2(v / n) : Vec2(Vec2::Zero());
}
}  // namespace

double Element2::length() const { return is_arc ? radius() * sweep() : (p1 - p0).norm(); }

Vec2 Element2::start_tangent() const {
    if (!is_arc) return unit_or_zero(p1 - p0);
    Vec2 u = unit_or_zero(p0 - c);
    return dir * left_normal(u);
}

Vec2 Element2::end_tangent() const {
    if (!is_arc) return unit_or_zero(p1 - p0);
    Vec2 u = unit_or_zero(p1 - c);
    return dir * left_normal(u);
}

double Element2::sweep() const {
    Vec2 u = p0 - c, v = p1 - c;
    double ang = std::atan2(cross2(u, v), u.dot(v));
    if (dir < 0) ang = -ang;
    if (ang <= 1e-12) ang += 2 * kPi;
    return ang + 2 * kPi * turns;
}

double turn_angle(const Vec2& t1, const Vec2& t2) { return std::atan2(cross2(t1, t2), t1.dot(t2)); }

std::optional<Element2> offset(const Element2& e, int side, double r) {
    Element2 o = e;
    if (!e.is_arc) {
        Vec2 n = side * r * left_normal(e.start_tangent());
        o.p0 += n;
        o.p1 += n;
        return o;
    }
    // Left normal of the travel tangent is -d·u (u = radial unit vector): R' = R - s·d·r.
    double R = e.radius();
    double R2 = R - side * e.dir * r;
    if (R2 <= tol::length) return std::nullopt;
    o.p0 = e.c + (e.p0 - e.c) * (R2 / R);
    double Rend = (e.p1 - e.c).norm();
    o.p1 = e.c + (e.p1 - e.c) * ((Rend - side * e.dir * r) / Rend);
    return o;
}

JointKind classify_joint(const Vec2& t1, const Vec2& t2, int side, double tangent_tol, double reversal_tol) {
    double theta = turn_angle(t1, t2);
    if (std::fabs(theta) < tangent_tol) return JointKind::tangent;
    if (kPi - std::fabs(theta) < reversal_tol) return JointKind::reversal;
    return side * theta < 0 ? JointKind::outside : JointKind::inside;
}

Crossings intersect(const Element2& a, const Element2& b) {
    Crossings out;
    if (!a.is_arc && !b.is_arc) {
        Vec2 d1 = a.p1 - a.p0, d2 = b.p1 - b.p0;
        double den = cross2(d1, d2);
        if (std::fabs(den) < 1e-15 * d1.norm() * d2.norm()) return out;
        double t = cross2(b.p0 - a.p0, d2) / den;
        out.push_back(a.p0 + t * d1);
        return out;
    }
    if (a.is_arc && b.is_arc) {
        Vec2 d = b.c - a.c;
        double D = d.norm(), r1 = a.radius(), r2 = b.radius();
        if (D < tol::length || D > r1 + r2 + 1e-12 || D < std::fabs(r1 - r2) - 1e-12) return out;
        double x = (D * D + r1 * r1 - r2 * r2) / (2 * D);
        double h2 = r1 * r1 - x * x;
        double h = h2 > 0 ? std::sqrt(h2) : 0.0;
        Vec2 ex = d / D, ey = left_normal(ex);
        out.push_back(a.c + x * ex + h * ey);
        if (h > 0) out.push_back(a.c + x * ex - h * ey);
        return out;
    }
    const Element2& ln = a.is_arc ? b : a;
    const Element2& ar = a.is_arc ? a : b;
    Vec2 d = ln.p1 - ln.p0;
    double L = d.norm();
    if (L < tol::length) return out;
    Vec2 u = d / L;
    Vec2 f = ln.p0 - ar.c;
    double proj = f.dot(u);
    Vec2 foot = ln.p0 - proj * u;  // foot of the perpendicular from the centre
    double dist2 = (foot - ar.c).squaredNorm(), R = ar.radius();
    double h2 = R * R - dist2;
    if (h2 < -1e-12 * R * R) return out;
    double h = h2 > 0 ? std::sqrt(h2) : 0.0;
    out.push_back(foot - h * u);
    if (h > 0) out.push_back(foot + h * u);
    return out;
}

}  // namespace toolcomp
