// The radius stage's angle helpers without sines and with one atan2 (unit, ccw_angle,
// find_turn) against LinuxCNC's formulas they stand for: u(ang(v)), ang(b) - ang(a) brought
// into [0, 2π), and the swept angle as the difference of two atan2 (interp_arc.cc's
// find_turn). Random vectors of every size, and the ends of the ranges.
#include <catch2/catch.hpp>

#include <climits>
#include <cmath>
#include <random>

#include "compensation/radius_math.hpp"

using namespace toolcomp;
using namespace toolcomp::radius_math;

namespace {

// LinuxCNC's find_turn, as the stage had it.
double find_turn_two_atan2(const Vec2& s, const Vec2& c, int turn, const Vec2& e) {
    if (turn == 0) return 0;
    double a = ang(s - c), b = ang(e - c);
    if (turn > 0) {
        if (b <= a) b += 2 * kPi;
        return b - a + (turn - 1) * 2 * kPi;
    }
    if (a <= b) a += 2 * kPi;
    return b - a + (turn + 1) * 2 * kPi;
}

// Angles compared modulo a full turn where they sit at its ends.
double angle_gap(double x, double y) {
    const double d = std::fabs(x - y);
    return std::min(d, std::fabs(d - 2 * kPi));
}

}  // namespace

TEST_CASE("unit(v) is u(ang(v)) for vectors of every size") {
    std::mt19937_64 rng(20261203);
    std::uniform_real_distribution<double> angle(-kPi, kPi), exponent(-300, 300);
    for (int i = 0; i < 200000; ++i) {
        const double phi = angle(rng), len = std::pow(10.0, exponent(rng));
        const Vec2 v(len * std::cos(phi), len * std::sin(phi));
        const Vec2 got = unit(v), want = u(ang(v));
        REQUIRE(std::isfinite(got.x()));
        REQUIRE(std::isfinite(got.y()));
        REQUIRE((got - want).norm() < 1e-15);
    }
    CHECK(unit(Vec2(0, 0)) == Vec2(1, 0));  // atan2(0, 0) = 0
    CHECK(unit(Vec2(4.9e-324, 0)) == Vec2(1, 0));
    CHECK(unit(Vec2(0, -1e308)) == Vec2(0, -1));
    CHECK((unit(Vec2(1e308, 1e308)) - Vec2(std::sqrt(0.5), std::sqrt(0.5))).norm() < 1e-15);
}

TEST_CASE("ccw_angle(a, b) is ang(b) - ang(a) in [0, 2pi)") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> angle(-kPi, kPi), exponent(-6, 6);
    for (int i = 0; i < 200000; ++i) {
        const double pa = angle(rng), pb = angle(rng);
        const double la = std::pow(10.0, exponent(rng)), lb = std::pow(10.0, exponent(rng));
        const Vec2 a(la * std::cos(pa), la * std::sin(pa)), b(lb * std::cos(pb), lb * std::sin(pb));
        double want = ang(b) - ang(a);
        if (want < 0) want += 2 * kPi;
        const double got = ccw_angle(a, b);
        REQUIRE(got >= 0);
        REQUIRE(got < 2 * kPi);
        REQUIRE(angle_gap(got, want) < 1e-14);
    }
    CHECK(ccw_angle(Vec2(1, 0), Vec2(1, 0)) == 0);
    CHECK(ccw_angle(Vec2(1, 0), Vec2(0, 1)) == Approx(kPi / 2).epsilon(1e-15));
    CHECK(ccw_angle(Vec2(0, 1), Vec2(1, 0)) == Approx(1.5 * kPi).epsilon(1e-15));
    CHECK(ccw_angle(Vec2(1, 0), Vec2(-1, 0)) == Approx(kPi).epsilon(1e-15));
}

TEST_CASE("find_turn with one atan2 is LinuxCNC's two-atan2 swept angle") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(-kPi, kPi), radius(1e-3, 1e4), coord(-1e3, 1e3);
    for (int i = 0; i < 200000; ++i) {
        const Vec2 c(coord(rng), coord(rng));
        const double r = radius(rng), ps = angle(rng), pe = angle(rng);
        const Vec2 s = c + r * Vec2(std::cos(ps), std::sin(ps)), e = c + r * Vec2(std::cos(pe), std::sin(pe));
        for (int turn : {1, -1, 2, -3}) {
            const double got = find_turn(s, c, turn, e), want = find_turn_two_atan2(s, c, turn, e);
            // The same but where the end sits on the start (less than 1e-13 apart): one full
            // turn more or less there is a matter of rounding in both.
            REQUIRE(std::fabs(got - want) < 1e-11 * std::max(1.0, std::fabs(want)) + (angle_gap(ps, pe) < 1e-13 ? 7 : 0));
            REQUIRE((turn > 0 ? got > 0 : got < 0));
        }
    }
    // Ends on each other: a full turn, either way (and the extra turns on top).
    const Vec2 c(1, 2), s(4, 6);
    CHECK(find_turn(s, c, 1, s) == Approx(2 * kPi));
    CHECK(find_turn(s, c, -1, s) == Approx(-2 * kPi));
    CHECK(find_turn(s, c, 3, s) == Approx(6 * kPi));
    CHECK(find_turn(s, c, 0, s) == 0);
    // A quarter anticlockwise, and the other three quarters clockwise.
    CHECK(find_turn(Vec2(1, 0), Vec2(0, 0), 1, Vec2(0, 1)) == Approx(kPi / 2));
    CHECK(find_turn(Vec2(1, 0), Vec2(0, 0), -1, Vec2(0, 1)) == Approx(-1.5 * kPi));
    // A turn count saturated at INT_MAX (P2147483647 and beyond): the extra turns in double,
    // not an int overflow (found by fuzz_pipeline).
    CHECK(find_turn(Vec2(1, 0), Vec2(0, 0), INT_MAX, Vec2(0, 1)) == Approx((INT_MAX - 1.0) * 2 * kPi + kPi / 2));
    CHECK(find_turn(Vec2(1, 0), Vec2(0, 0), -INT_MAX, Vec2(0, 1)) == Approx(-(INT_MAX - 1.0) * 2 * kPi - 1.5 * kPi));
    // Radii far beyond any machine: no overflow into NaN.
    CHECK(std::isfinite(find_turn(Vec2(1e300, 0), Vec2(-1e300, 0), 1, Vec2(-1e300, 2e300))));
}
