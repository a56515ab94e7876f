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
// stored(rho * sinl(x)) bit for bit, for the corner's |x| <= 5pi/4 without sinl's slow
// argument reduction (radius_sine.cpp).
double scaled_sinl(double rho, long double x);
// LinuxCNC's distances between two points (hypot, not the square root of the squares).
inline double dist(const Vec2& a, const Vec2& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

inline double ang(const Vec2& v) { return std::atan2(v.y(), v.x()); }
inline Vec2 u(double phi) { return {std::cos(phi), std::sin(phi)}; }
// LinuxCNC's turn count of an arc: ±1 for less than a full turn, ±(n+1) with n extra turns.
// (A count saturated at INT_MAX by int_value stays there.)
inline int turn_of(const Motion& m) {
    const int n = m.turns < INT_MAX ? m.turns + 1 : INT_MAX;
    return m.kind == MotionKind::arc_ccw ? n : -n;
}

// Signed swept angle from s to e about c for a turn count: LinuxCNC's find_turn, operation
// for operation (the difference of two atan2, a full turn added as a long double where the end
// is not beyond the start: an end on the start sweeps a full turn in its arithmetic, whatever
// the last bits of the two points).
inline double find_turn(const Vec2& s, const Vec2& c, int turn, const Vec2& e) {
    if (turn == 0) return 0;
    double alpha = ang(s - c), beta = ang(e - c);
    if (turn > 0) {
        if (beta <= alpha) beta = stored(beta + 2 * kPiL);
        return stored((beta - alpha) + (turn - 1) * (2 * kPiL));
    }
    if (alpha <= beta) alpha = stored(alpha + 2 * kPiL);
    return stored((beta - alpha) + (turn + 1) * (2 * kPiL));
}

// The tool is inside the arc (its equidistant is the smaller circle).
inline bool tool_inside(int side, int turn) { return (side > 0 && turn > 0) || (side < 0 && turn < 0); }

}  // namespace toolcomp::radius_math
