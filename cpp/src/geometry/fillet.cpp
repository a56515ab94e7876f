// Rounding a corner between two elements (see fillet.hpp).
#include "toolcomp/geometry/fillet.hpp"

#include <algorithm>
#include <cmath>

namespace toolcomp {

namespace {

// The point of the element's line / circle nearest to f (the tangent point of a circle about
// f that touches the element).
std::optional<Vec2> foot(const Element2& e, const Vec2& f) {
    if (e.is_arc) {
        const Vec2 u = f - e.c;
        if (u.norm() < 1e-12) return std::nullopt;
        return Vec2(e.c + e.radius() * u.normalized());
    }
    const Vec2 t = e.start_tangent();
    return Vec2(e.p0 + (f - e.p0).dot(t) * t);
}

// How much of e lies between q (on e's line / circle) and its end (from_end) or its start:
// the length cut off when e is shortened to q; < 0 when q is not on the element.
double cut_length(const Element2& e, const Vec2& q, bool from_end) {
    constexpr double eps = 1e-9;
    const double len = e.length();
    double cut;
    if (!e.is_arc) {
        const Vec2 t = e.start_tangent();
        cut = from_end ? (e.p1 - q).dot(t) : (q - e.p0).dot(t);
    } else {
        const double R = e.radius();
        const Vec2 a = (from_end ? q : e.p0) - e.c, b = (from_end ? e.p1 : q) - e.c;
        double ang = e.dir * std::atan2(cross2(a, b), a.dot(b));
        if (ang < 0) ang += 2 * kPi;
        if ((2 * kPi - ang) * R < eps) ang = 0;  // q at the end point, numerically just beyond it
        cut = ang * R;
    }
    if (cut < -eps || cut > len + eps) return -1;
    return std::clamp(cut, 0.0, len);
}

}  // namespace

std::optional<Fillet> fillet(const Element2& e1, const Element2& e2, double rho) {
    const double theta = turn_angle(e1.end_tangent(), e2.start_tangent());
    if (std::fabs(theta) < 1e-9) return std::nullopt;  // a tangent joint: no corner to round
    const int s = theta > 0 ? 1 : -1;                  // left turn: the rounding lies on the left
    const auto o1 = offset(e1, s, rho), o2 = offset(e2, s, rho);
    if (!o1 || !o2) return std::nullopt;  // an arc of radius <= rho on the inner side
    std::optional<Fillet> best;
    double best_cut = 0;
    for (const Vec2& f : intersect(*o1, *o2)) {
        const auto q1 = foot(e1, f), q2 = foot(e2, f);
        if (!q1 || !q2) continue;
        const double c1 = cut_length(e1, *q1, /*from_end=*/true), c2 = cut_length(e2, *q2, /*from_end=*/false);
        if (c1 < 0 || c2 < 0) continue;
        if (!best || c1 + c2 < best_cut) {
            best = Fillet{*q1, *q2, f, s};
            best_cut = c1 + c2;
        }
    }
    return best;
}

}  // namespace toolcomp
