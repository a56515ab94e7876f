#pragma once
// Circular arcs and helices in a working plane; the applicate moves linearly.
#include <optional>
#include <vector>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

// Extra full turns an arc may make: the Sinumerik's TURN limit (0..999999). A count beyond it
// no control runs, and the Path's turns column (int32) could not hold every count a program
// can write; every dialect refuses it at its block.
inline constexpr int kMaxArcTurns = 999'999;

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
// Why an arc cannot be cut as written, or nullptr. `unit`: mm per program unit. Its radius,
// sweep or length in mm is not a finite number (an absurd R word: R1e300 for a 1 mm chord),
// or its end lies more than 1e-6 mm beside the start's ray from the centre and yet the angle
// cannot tell it from the start, so that it would be taken as a full circle (a radius of
// kilometres for a chord of microns: only radii beyond 1 km reach this). An end on that ray
// (a slight spiral of a full circle) is a full circle, as LinuxCNC cuts it.
const char* arc_defect(const Arc& a, double unit);
// Number of chords so that no chord deviates more than `tolerance` from the arc; throws
// Error("sample_too_fine") beyond 50 million chords.
int arc_chords(const Arc& a, double tolerance);

// Centre of the arc of signed radius R from s to e (plane coordinates), direction dir:
// R > 0 takes the arc of at most 180°, R < 0 the one of more than 180° (ISO/LinuxCNC).
// nullopt when |e − s| > 2|R| (the caller decides about tolerance) or s == e.
std::optional<Vec2> center_from_radius(const Vec2& s, const Vec2& e, double R, int dir);

}  // namespace toolcomp
