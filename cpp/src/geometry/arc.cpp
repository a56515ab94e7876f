#include "toolcomp/geometry/arc.hpp"
#include "toolcomp/program/codes.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

double arc_start_radius(const Arc& a) {
    return (in_plane(a.start, a.plane) - in_plane(a.center, a.plane)).norm();
}
double arc_end_radius(const Arc& a) {
    return (in_plane(a.end, a.plane) - in_plane(a.center, a.plane)).norm();
}

double arc_sweep(const Arc& a) {
    Vec2 c = in_plane(a.center, a.plane);
    Vec2 u = in_plane(a.start, a.plane) - c, v = in_plane(a.end, a.plane) - c;
    double ang = std::atan2(cross2(u, v), u.dot(v));  // (-π, π]
    if (a.dir < 0) ang = -ang;
    if (ang <= 1e-12) ang += 2 * kPi;  // start == end (or nearly): a full circle
    return ang + 2 * kPi * a.turns;
}

Vec3 arc_point(const Arc& a, double u) {
    auto ax = axes(a.plane);
    Vec2 c = in_plane(a.center, a.plane);
    Vec2 s = in_plane(a.start, a.plane) - c;
    double r0 = s.norm(), r1 = arc_end_radius(a);
    double phi0 = std::atan2(s.y(), s.x());
    double phi = phi0 + a.dir * arc_sweep(a) * u;
    double r = r0 + (r1 - r0) * u;
    Vec3 p;
    p[ax.a] = c.x() + r * std::cos(phi);
    p[ax.b] = c.y() + r * std::sin(phi);
    p[ax.c] = a.start[ax.c] + (a.end[ax.c] - a.start[ax.c]) * u;
    if (u >= 1.0) p = a.end;  // exact end point, no round-off drift
    return p;
}

double arc_length(const Arc& a) {
    auto ax = axes(a.plane);
    double r = 0.5 * (arc_start_radius(a) + arc_end_radius(a));
    double planar = r * arc_sweep(a);
    double h = a.end[ax.c] - a.start[ax.c];
    return std::hypot(planar, h);
}

const char* arc_defect(const Arc& a, double unit) {
    const Vec2 c = in_plane(a.center, a.plane);
    const Vec2 u = in_plane(a.start, a.plane) - c;
    const double r = std::hypot(u.x(), u.y()) * unit, sweep = arc_sweep(a);
    if (!std::isfinite(r) || !std::isfinite(sweep) || !std::isfinite(r * sweep))
        return "its radius, sweep or length is not a finite number";
    // The ends' gap across the start's ray: a slight spiral that ends on that ray is a full
    // circle (LinuxCNC cuts one), an end beside it that the angle cannot see is not.
    const Vec2 gap = in_plane(a.end, a.plane) - in_plane(a.start, a.plane);
    const double across = std::fabs(cross2(u / std::hypot(u.x(), u.y()), gap));
    if (a.turns == 0 && sweep >= 2 * kPi && across * unit > 1e-6)
        return "its start and end are distinct points that its circle cannot tell apart (it would be "
               "taken as a full circle)";
    return nullptr;
}

int arc_chords(const Arc& a, double tolerance) {
    double r = std::max(arc_start_radius(a), arc_end_radius(a));
    double sweep = arc_sweep(a);
    double n = 0;
    if (r <= tolerance || tolerance <= 0) {
        n = std::ceil(sweep / (kPi / 8));
    } else {
        double step = 2 * std::acos(1 - tolerance / r);
        n = std::ceil(sweep / step);
    }
    // A helix of a million turns sampled at 1 µm would need more points than memory holds
    // (and more than an int counts): refuse it instead (also a NaN count).
    constexpr double kMaxChords = 50'000'000;
    if (!(n <= kMaxChords))
        throw Error(ErrorKind::generic, code::sample_too_fine,
                    "An arc would need more than 50 million chords at tolerance " + std::to_string(tolerance) +
                        " (sweep " + std::to_string(sweep) + " rad, radius " + std::to_string(r) +
                        "): sample with a coarser tolerance");
    return std::max(1, static_cast<int>(n));
}

std::optional<Vec2> center_from_radius(const Vec2& s, const Vec2& e, double R, int dir) {
    Vec2 chord = e - s;
    double c = chord.norm();
    double absR = std::fabs(R);
    if (c < tol::length || c > 2 * absR) return std::nullopt;
    Vec2 mid = 0.5 * (s + e);
    // h = sqrt(R² - (c/2)²), scaled by R before squaring: R² overflows for |R| > 1e154, and
    // a radius of 1e300 (a nearly straight arc) still has a finite centre.
    const double q = 0.5 * c / absR;
    double h = absR * std::sqrt(std::max(0.0, (1 - q) * (1 + q)));
    // For a CCW arc of at most 180° the centre lies left of the chord (spec §1.3).
    double sigma = (dir > 0 ? 1.0 : -1.0) * (R > 0 ? 1.0 : -1.0);
    return mid + sigma * h * left_normal(chord / c);
}

}  // namespace toolcomp
