#pragma once
// Small angle helpers shared by the radius compensation files (plane coordinates).
#include <cmath>

#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/motion/motion.hpp"

namespace toolcomp::radius_math {

constexpr double kHalfPi = kPi / 2;

inline double ang(const Vec2& v) { return std::atan2(v.y(), v.x()); }
inline Vec2 u(double phi) { return {std::cos(phi), std::sin(phi)}; }

// LinuxCNC's turn count of an arc: ±1 for less than a full turn, ±(n+1) with n extra turns.
inline int turn_of(const Motion& m) { return (m.kind == MotionKind::arc_ccw ? 1 : -1) * (m.turns + 1); }

// Signed swept angle from s to e about c for a turn count.
inline double find_turn(const Vec2& s, const Vec2& c, int turn, const Vec2& e) {
    if (turn == 0) return 0;
    double a = ang(s - c), b = ang(e - c);
    if (turn > 0) {
        if (b <= a) b += 2 * kPi;
        return b - a + (turn - 1) * 2 * kPi;
    }
    if (a <= b) a += 2 * kPi;
    return b - a + (turn + 1) * 2 * kPi;
}

// The tool is inside the arc (its equidistant is the smaller circle).
inline bool tool_inside(int side, int turn) { return (side > 0 && turn > 0) || (side < 0 && turn < 0); }

}  // namespace toolcomp::radius_math
