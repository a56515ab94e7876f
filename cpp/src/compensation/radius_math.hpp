#pragma once
// Small angle helpers shared by the radius compensation files (plane coordinates).
#include <climits>
#include <cmath>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/motion/motion.hpp"

namespace toolcomp::radius_math {

constexpr double kHalfPi = kPi / 2;

// LinuxCNC writes its angle constants as long doubles (M_PIl, M_PI_2l): an expression with one
// of them is worked out in long double and rounded where it is stored in a double. The joints
// repeat that operation for operation (`stored`): at an exactly tangent concave corner the
// verdict, reached or gouging, turns on the last bit of the corner angle.
constexpr long double kPiL = 3.141592653589793238462643383279502884L;
constexpr long double kHalfPiL = kPiL / 2;
inline double stored(long double x) { return static_cast<double>(x); }
// LinuxCNC's distances between two points (hypot, not the square root of the squares).
inline double dist(const Vec2& a, const Vec2& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

inline double ang(const Vec2& v) { return std::atan2(v.y(), v.x()); }
inline Vec2 u(double phi) { return {std::cos(phi), std::sin(phi)}; }
// u(ang(v)) without the angle: v's direction ((1, 0) for the zero vector, as atan2(0, 0) = 0).
// The square root of the squared length unless that under- or overflows (then hypot).
inline Vec2 unit(const Vec2& v) {
    const double n2 = v.squaredNorm();
    const double n = n2 > 1e-290 && n2 < 1e290 ? std::sqrt(n2) : std::hypot(v.x(), v.y());
    return n > 0 ? Vec2(v / n) : Vec2(1, 0);
}
// The angle from a to b, anticlockwise, in [0, 2π): ang(b) - ang(a) brought into that range,
// with one atan2 (a and b of moderate size: the products must not overflow).
inline double ccw_angle(const Vec2& a, const Vec2& b) {
    const double t = std::atan2(cross2(a, b), a.dot(b));
    return t < 0 ? t + 2 * kPi : t;
}

// LinuxCNC's turn count of an arc: ±1 for less than a full turn, ±(n+1) with n extra turns.
// (A count saturated at INT_MAX by int_value stays there.)
inline int turn_of(const Motion& m) {
    const int n = m.turns < INT_MAX ? m.turns + 1 : INT_MAX;
    return m.kind == MotionKind::arc_ccw ? n : -n;
}

// Signed swept angle from s to e about c for a turn count.
// LinuxCNC takes it as ang(e - c) - ang(s - c), brought into (0, 2π] anticlockwise and
// [-2π, 0) clockwise (the same ends: a full turn); here with one atan2.
inline double find_turn(const Vec2& s, const Vec2& c, int turn, const Vec2& e) {
    if (turn == 0) return 0;
    const Vec2 a = unit(s - c), b = unit(e - c);
    if (turn > 0) {
        const double t = ccw_angle(a, b);
        return (t == 0 ? 2 * kPi : t) + (static_cast<double>(turn) - 1) * 2 * kPi;  // no int overflow
    }
    const double t = ccw_angle(b, a);
    return -(t == 0 ? 2 * kPi : t) + (static_cast<double>(turn) + 1) * 2 * kPi;
}

// The tool is inside the arc (its equidistant is the smaller circle).
inline bool tool_inside(int side, int turn) { return (side > 0 && turn > 0) || (side < 0 && turn < 0); }

}  // namespace toolcomp::radius_math
