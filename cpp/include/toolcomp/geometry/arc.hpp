#pragma once
// Circular arcs and helices in a working plane; the applicate moves linearly.
#include <optional>
#include <vector>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

struct Arc {
    Vec3 start, end, center;  // center: its applicate coordinate is the start's
    Plane plane = Plane::xy;
    int dir = 1;    // +1 counter-clockwise (G3), -1 clockwise (G2), seen from +applicate
    int turns = 0;  // extra full turns (LinuxCNC P word minus one)
};

double arc_start_radius(const Arc& a);
double arc_end_radius(const Arc& a);
// Swept angle in radians, > 0: the angle from start to end in the arc's direction, in
// (0, 2π] (start == end is a full circle), plus 2π per extra turn.
double arc_sweep(const Arc& a);
// Point at parameter u ∈ [0, 1] (angle and applicate linear in u, radius blending linearly
// from the start radius to the end radius, as controls do for slightly spiral arcs).
Vec3 arc_point(const Arc& a, double u);
// Length of the (possibly helical) arc.
double arc_length(const Arc& a);
// Number of chords so that no chord deviates more than `tolerance` from the arc; throws
// Error("sample_too_fine") beyond 50 million chords.
int arc_chords(const Arc& a, double tolerance);

// Centre of the arc of signed radius R from s to e (plane coordinates), direction dir:
// R > 0 takes the arc of at most 180°, R < 0 the one of more than 180° (ISO/LinuxCNC).
// nullopt when |e − s| > 2|R| (the caller decides about tolerance) or s == e.
std::optional<Vec2> center_from_radius(const Vec2& s, const Vec2& e, double R, int dir);

}  // namespace toolcomp
