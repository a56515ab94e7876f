#pragma once
// Plane geometry shared by the lathe cycles' pass planning: angles and sweeps of arcs, and
// the alarm of a contour that turns back.
#include <cmath>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/program/codes.hpp"
#include "turning_roughing.hpp"

namespace toolcomp::cycles {

inline constexpr double kContourEps = 1e-9;  // program units
inline constexpr double kPi = 3.14159265358979323846;

inline double sign_of(double x) { return x > kContourEps ? 1.0 : x < -kContourEps ? -1.0 : 0.0; }

// The angle of p about c, and the sweep from angle a0 to a in direction dir, in [0, 2 pi).
inline double angle_of(const Vec2& p, const Vec2& c) { return std::atan2(p.y() - c.y(), p.x() - c.x()); }
inline double swept(double a0, double a, int dir) {
    double d = dir > 0 ? a - a0 : a0 - a;
    d = std::fmod(d, 2 * kPi);
    return d < 0 ? d + 2 * kPi : d;
}

[[noreturn]] inline void not_monotonic(int line) {
    throw CycleError{code::cycle_not_monotonic, "PS0064 THE FINISHING SHAPE IS NOT A MONOTONOUS CHANGE", line};
}

// The depth, the retract and the contour a roughing cycle needs (CycleError otherwise).
void check_roughing(const Contour& contour, const Roughing& r);

}  // namespace toolcomp::cycles
