// The radius stage's angle helpers in LinuxCNC's arithmetic (radius_math.hpp): the swept
// angle of find_turn, the long-double constants and where their results are stored, hypot
// distances. Hand-worked values, and the cases where the arithmetic decides: an end on the
// start (a full turn), points a bit apart, turn counts at the int limit.
#include <catch2/catch.hpp>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "compensation/radius_math.hpp"

using namespace toolcomp;
using namespace toolcomp::radius_math;

TEST_CASE("find_turn: swept angles of quarters, halves and full turns") {
    const Vec2 c(0, 0);
    CHECK(find_turn(Vec2(1, 0), c, 1, Vec2(0, 1)) == Approx(kPi / 2).epsilon(1e-15));
    CHECK(find_turn(Vec2(1, 0), c, -1, Vec2(0, 1)) == Approx(-1.5 * kPi).epsilon(1e-15));
    CHECK(find_turn(Vec2(0, 1), c, 1, Vec2(1, 0)) == Approx(1.5 * kPi).epsilon(1e-15));
    CHECK(find_turn(Vec2(1, 0), c, 1, Vec2(-1, 0)) == Approx(kPi).epsilon(1e-15));
    CHECK(find_turn(Vec2(1, 0), c, 0, Vec2(0, 1)) == 0);
    // Extra turns: a full turn each.
    CHECK(find_turn(Vec2(1, 0), c, 3, Vec2(0, 1)) == Approx(4.5 * kPi).epsilon(1e-15));
    CHECK(find_turn(Vec2(1, 0), c, -2, Vec2(0, 1)) == Approx(-3.5 * kPi).epsilon(1e-15));
}

TEST_CASE("find_turn: an end on the start is a full turn, decided on the two atan2 alone") {
    const Vec2 c(1, 2), s(4, 6);
    CHECK(find_turn(s, c, 1, s) == Approx(2 * kPi).epsilon(1e-15));
    CHECK(find_turn(s, c, -1, s) == Approx(-2 * kPi).epsilon(1e-15));
    CHECK(find_turn(s, c, 3, s) == Approx(6 * kPi).epsilon(1e-15));
    // An end 1e-17 anticlockwise of the start: both atan2 round to pi/2, so the arc sweeps a
    // full turn in LinuxCNC's arithmetic, not the 1e-17 of the geometry (a vector formula
    // would say 1e-17, and a gouge check comparing sweeps would decide the other way).
    const Vec2 o(0, 0), s2(2e-17, 1), e2(1e-17, 1);
    REQUIRE(ang(s2) == ang(e2));
    CHECK(find_turn(s2, o, 1, e2) == Approx(2 * kPi).epsilon(1e-15));
    CHECK(find_turn(e2, o, -1, s2) == Approx(-2 * kPi).epsilon(1e-15));
}

TEST_CASE("find_turn: the full turn is added as a long double and the sum rounded once") {
    // beta <= alpha: beta + 2 pi in long double, stored; then (beta - alpha) + 0 * 2 pi.
    const Vec2 c(0, 0), s(0, 1), e(1, 0);  // alpha = pi/2, beta = 0: three quarters anticlockwise
    const double alpha = std::atan2(1.0, 0.0), beta = 0.0;
    const double stored_beta = static_cast<double>(beta + 2 * 3.141592653589793238462643383279502884L);
    const double want = static_cast<double>((stored_beta - alpha) + 0 * (2 * 3.141592653589793238462643383279502884L));
    const double got = find_turn(s, c, 1, e);
    CHECK(std::memcmp(&got, &want, sizeof got) == 0);
    // Turn counts at the int limit (P2147483647): no int overflow, finite.
    CHECK(find_turn(Vec2(1, 0), c, INT_MAX, Vec2(0, 1)) == Approx((INT_MAX - 1.0) * 2 * kPi + kPi / 2));
    CHECK(find_turn(Vec2(1, 0), c, -INT_MAX, Vec2(0, 1)) == Approx(-(INT_MAX - 1.0) * 2 * kPi - 1.5 * kPi));
    CHECK(std::isfinite(find_turn(Vec2(1e300, 0), Vec2(-1e300, 0), 1, Vec2(-1e300, 2e300))));
}

TEST_CASE("the long-double constants are M_PIl and M_PI_2l, stored rounded to nearest") {
    CHECK(static_cast<double>(kPiL) == kPi);
    CHECK(static_cast<double>(kHalfPiL) == kHalfPi);
    CHECK(kHalfPiL * 2 == kPiL);
    // theta - M_PI_2l stored can differ from theta - (double)(pi/2) by one bit: here it does
    // (numbers from numpy's longdouble).
    const double theta = 2.223575916398289;
    CHECK(stored(theta - kHalfPiL) == 0.6527795896033924);
    CHECK(theta - kHalfPi == 0.6527795896033926);
    CHECK(dist(Vec2(3, 0), Vec2(0, 4)) == 5);
    CHECK(dist(Vec2(1e300, 0), Vec2(-1e300, 0)) == 2e300);  // no overflow (hypot)
}

// LinuxCNC's y = rho * sin(beta - M_PI_2l) at a concave line->arc corner: sinl of a long
// double, stored in a double. scaled_sinl must give that double bit for bit.
namespace {
double linuxcnc_y(double rho, long double x) { return static_cast<double>(rho * ::sinl(x)); }
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST_CASE("scaled_sinl: bit for bit LinuxCNC's rho * sinl(beta - M_PI_2l) over the corner's range") {
    std::uint64_t state = 0x9E3779B97F4A7C15ull;  // splitmix64: the same samples on every run
    const auto next = [&state] {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    };
    const auto unit = [&next] { return static_cast<double>(next() >> 11) * 0x1p-53; };
    int mismatches = 0;
    const auto check = [&](double rho, long double x) {
        if (!same_bits(scaled_sinl(rho, x), linuxcnc_y(rho, x))) {
            ++mismatches;
            UNSCOPED_INFO("rho " << rho << " x " << static_cast<double>(x));
        }
    };
    // beta anywhere in LinuxCNC's [-90°, 270°], a radius from 1 µm to 10 m.
    for (int i = 0; i < 200000; ++i) {
        const double beta = -kHalfPi + 2 * kPi * unit();
        check(std::exp(std::log(1e-3) + std::log(1e7) * unit()), beta - kHalfPiL);
    }
    // Corners a few ulps from straight, reversed and square, where the sine cancels or is 1.
    for (const double c : {-kHalfPi, 0.0, kHalfPi, kPi, 1.5 * kPi}) {
        double b = c;
        for (int k = 0; k < 64; ++k) b = std::nextafter(b, -10.0);
        for (int k = 0; k < 128; ++k, b = std::nextafter(b, 10.0)) {
            check(5.0, b - kHalfPiL);
            check(1.0 + unit(), b - kHalfPiL);
        }
    }
    // Long doubles next to +-pi/2 and +-pi themselves (the closest a long double gets to a
    // multiple of pi/2), and to pi/4 and 3pi/4 where the reduction changes its quadrant.
    for (const long double c : {kHalfPiL, kPiL, -kHalfPiL, -kPiL, kPiL / 4, 3 * kPiL / 4, -3 * kPiL / 4}) {
        long double x = c;
        for (int k = 0; k < 200; ++k) x = std::nextafter(x, -10.0L);
        for (int k = 0; k < 400; ++k, x = std::nextafter(x, 10.0L)) check(1.0 + 99 * unit(), x);
    }
    CHECK(mismatches == 0);
    // Outside the reduced range and NaN: sinl's own answer.
    CHECK(same_bits(scaled_sinl(2.0, 10.0L), linuxcnc_y(2.0, 10.0L)));
    CHECK(std::isnan(scaled_sinl(2.0, std::numeric_limits<long double>::quiet_NaN())));
}
