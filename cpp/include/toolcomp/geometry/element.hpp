#pragma once
// Planar contour elements (the projection of a move on the working plane) and their offsets.
//
// Vocabulary of spec §0.2/§1: unit tangent t, left normal nL(t) = (-t_b, t_a), side s = +1
// left (G41/RL) and -1 right (G42/RR), arc direction d = +1 CCW and -1 CW.
#include <cstddef>
#include <optional>
#include <vector>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp {

struct Element2 {
    bool is_arc = false;
    Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();  // start and end
    Vec2 c = Vec2::Zero();                      // arc centre
    int dir = 1;                                // arc direction
    int turns = 0;                              // arc: extra full turns

    static Element2 line(const Vec2& a, const Vec2& b) { return {false, a, b, Vec2::Zero(), 1, 0}; }
    static Element2 arc(const Vec2& a, const Vec2& b, const Vec2& centre, int dir, int turns = 0) {
        return {true, a, b, centre, dir, turns};
    }
    double radius() const { return (p0 - c).norm(); }
    double length() const;
    // Unit tangent of travel at the start / end (for a zero-length line: zero).
    Vec2 start_tangent() const;
    Vec2 end_tangent() const;
    // Swept angle of an arc, > 0, in (0, 2π] plus 2π per extra turn.
    double sweep() const;
};

// Signed turning angle from t1 to t2 in (-π, π] (> 0: left turn).
double turn_angle(const Vec2& t1, const Vec2& t2);

// The equidistant at distance r on side s (spec §1.1, §1.2). An arc keeps its centre and
// gets radius R - s·d·r; nullopt when that radius is not positive (the tool does not fit).
std::optional<Element2> offset(const Element2& e, int side, double r);

enum class JointKind { tangent, outside, inside, reversal };
// Classification of the joint between an element ending with tangent t1 and one starting
// with tangent t2, for side s (spec §1.4): s·θ < 0 outside (a gap to fill), > 0 inside
// (offsets overlap), |θ| ≈ π reversal. `tangent_tol` and `reversal_tol` in radians.
JointKind classify_joint(const Vec2& t1, const Vec2& t2, int side, double tangent_tol, double reversal_tol);

// Up to two points, without a heap allocation (intersections are taken on every joint).
struct Crossings {
    Vec2 p[2];
    int n = 0;
    void push_back(const Vec2& v) { p[n++] = v; }
    bool empty() const { return n == 0; }
    std::size_t size() const { return static_cast<std::size_t>(n); }
    const Vec2& operator[](std::size_t i) const { return p[i]; }
    const Vec2* begin() const { return p; }
    const Vec2* end() const { return p + n; }
};

// Intersections of the supporting line / full circle of two elements (0, 1 or 2 points).
Crossings intersect(const Element2& a, const Element2& b);

}  // namespace toolcomp
