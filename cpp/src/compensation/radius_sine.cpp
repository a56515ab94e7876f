// stored(rho * sinl(x)), LinuxCNC's `rho * sin(beta - M_PI_2l)`, without glibc's long-double
// argument reduction. Beyond pi/4 sinl reduces through its general multi-precision kernel
// (__kernel_rem_pio2, about 1 400 instructions a call); the joint's argument never exceeds
// 5pi/4, where a two-part pi/2 reduces it exactly enough:
//   x - n*P1 is exact (Sterbenz: x and n*P1 are within a factor of 2 of each other),
//   n*P2 carries pi/2 on to 2^-130, while |x - n*pi/2| >= 2.5e-20 (2^-65) for every long
//   double x near a multiple of pi/2 (M_PI_2l and M_PIl are the closest),
// so the reduced y is within about 1 ulp (long double) of the true one, and sinl / cosl of y
// (|y| <= pi/4: their kernels, no reduction) within about 2 ulp of glibc's sinl(x), which is
// itself within 1 ulp of the sine. The product is rounded to double: unless the long-double
// value lies within 2^-58 (relative) of a rounding boundary between two doubles, the double is
// the one LinuxCNC stores, bit for bit. Near a boundary (3.4 % of random corners), sinl itself.
#include <cmath>

#include "radius_math.hpp"

namespace toolcomp::radius_math {

namespace {
// pi/2 = P1 + P2 + O(2^-130): P1 is M_PI_2l (kHalfPiL), P2 the rest rounded to a long double.
constexpr long double kP2 = -2.5082788063341660117786635401653785069e-20L;
constexpr long double kTwoOverPi = 0.636619772367581343075535053490057448L;
}  // namespace

double scaled_sinl(double rho, long double x) {
    const long double ax = std::fabs(x);
    // Inside pi/4 glibc does not reduce either (and NaN or a far argument: its own way).
    if (!(ax > 0.78L && ax < 3.9L)) return stored(rho * std::sin(x));
    const long double n = std::nearbyint(x * kTwoOverPi);  // -2 .. 2
    const long double y = (x - n * kHalfPiL) - n * kP2;
    long double s;
    switch (static_cast<int>(n)) {
    case 1: s = std::cos(y); break;
    case -1: s = -std::cos(y); break;
    case 2:
    case -2: s = -std::sin(y); break;
    default: s = std::sin(y); break;  // n == 0 (x between 0.78 and pi/4)
    }
    const long double v = rho * s;
    constexpr long double margin = 0x1p-58L;
    const double lo = stored(v - std::fabs(v) * margin), hi = stored(v + std::fabs(v) * margin);
    if (lo != hi) return stored(rho * std::sin(x));  // near a rounding boundary: sinl itself
    return lo;
}

}  // namespace toolcomp::radius_math
