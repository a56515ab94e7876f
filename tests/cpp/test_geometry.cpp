// Arc geometry: centres from R in all four sign cases (spec §1.3), sweeps, helices, full
// circles, chording. Expected numbers are hand calculations.
#include <catch2/catch.hpp>
#include <cmath>

#include "toolcomp/geometry/arc.hpp"

using namespace toolcomp;

TEST_CASE("centre from R: the four (R, direction) cases of spec 1.3") {
    Vec2 s(40, 40), e(70, 40);
    // R+20 CW and R-20 CCW: centre below the chord; R+20 CCW and R-20 CW: above.
    auto c1 = center_from_radius(s, e, 20, -1);
    auto c2 = center_from_radius(s, e, 20, +1);
    auto c3 = center_from_radius(s, e, -20, -1);
    auto c4 = center_from_radius(s, e, -20, +1);
    REQUIRE(c1);
    REQUIRE(c2);
    REQUIRE(c3);
    REQUIRE(c4);
    const double h = std::sqrt(400.0 - 225.0);  // 13.2288
    CHECK(c1->x() == Approx(55));
    CHECK(c1->y() == Approx(40 - h));
    CHECK(c2->y() == Approx(40 + h));
    CHECK(c3->y() == Approx(40 + h));
    CHECK(c4->y() == Approx(40 - h));
    CHECK(c1->y() == Approx(26.771).margin(5e-4));
}

TEST_CASE("centre from R: chord longer than the diameter has no centre") {
    CHECK_FALSE(center_from_radius({0, 0}, {10, 0}, 4.9, 1));
    CHECK_FALSE(center_from_radius({0, 0}, {0, 0}, 5, 1));
    auto half = center_from_radius({0, 0}, {10, 0}, 5, 1);
    REQUIRE(half);
    CHECK(half->x() == Approx(5));
    CHECK(half->y() == Approx(0).margin(1e-12));
}

TEST_CASE("sweep: quarter, three quarters, full circle and extra turns") {
    Arc a{{10, 0, 0}, {0, 10, 0}, {0, 0, 0}, Plane::xy, +1, 0};
    CHECK(arc_sweep(a) == Approx(kPi / 2));
    a.dir = -1;
    CHECK(arc_sweep(a) == Approx(3 * kPi / 2));
    Arc full{{10, 0, 0}, {10, 0, 0}, {0, 0, 0}, Plane::xy, +1, 0};
    CHECK(arc_sweep(full) == Approx(2 * kPi));
    full.turns = 2;
    CHECK(arc_sweep(full) == Approx(6 * kPi));
}

TEST_CASE("plane conventions: G18 arcs are seen from +Y with (Z, X) coordinates") {
    // Quarter circle in ZX from Z=10 to X=10 about the origin, counter-clockwise seen from +Y:
    // in (a, b) = (Z, X) that is from (10, 0) to (0, 10), a +90 degree turn.
    Arc a{{0, 0, 10}, {10, 0, 0}, {0, 0, 0}, Plane::zx, +1, 0};
    CHECK(arc_sweep(a) == Approx(kPi / 2));
    Vec3 mid = arc_point(a, 0.5);
    CHECK(mid.z() == Approx(10 / std::sqrt(2.0)));
    CHECK(mid.x() == Approx(10 / std::sqrt(2.0)));
    CHECK(mid.y() == Approx(0).margin(1e-12));
    // G19: (a, b) = (Y, Z), seen from +X.
    Arc b{{0, 10, 0}, {0, 0, 10}, {0, 0, 0}, Plane::yz, +1, 0};
    CHECK(arc_sweep(b) == Approx(kPi / 2));
}

TEST_CASE("helix: the applicate moves linearly, length is the hypotenuse") {
    Arc h{{10, 0, 0}, {10, 0, -6}, {0, 0, 0}, Plane::xy, +1, 2};  // 3 full turns, 6 mm down
    CHECK(arc_sweep(h) == Approx(6 * kPi));
    CHECK(arc_length(h) == Approx(std::hypot(2 * kPi * 10 * 3, 6.0)));
    Vec3 p = arc_point(h, 0.5);
    CHECK(p.z() == Approx(-3));
    CHECK(p.x() == Approx(-10));  // half of three turns = 1.5 turns: opposite side
    CHECK(p.y() == Approx(0).margin(1e-9));
}

TEST_CASE("chording keeps the sagitta within tolerance") {
    Arc a{{10, 0, 0}, {10, 0, 0}, {0, 0, 0}, Plane::xy, +1, 0};
    int n = arc_chords(a, 0.01);
    double step = 2 * kPi / n;
    CHECK(10 * (1 - std::cos(step / 2)) <= 0.01);
    double coarser = 2 * kPi / (n - 1);
    CHECK(10 * (1 - std::cos(coarser / 2)) > 0.01);
}

TEST_CASE("in_plane and with_plane follow the plane's axes (a, b, applicate c)") {
    const Vec3 v(1, 2, 3);
    for (Plane p : {Plane::xy, Plane::zx, Plane::yz}) {
        const PlaneAxes ax = axes(p);
        const Vec2 ab = in_plane(v, p);
        CHECK(ab.x() == v[ax.a]);
        CHECK(ab.y() == v[ax.b]);
        const Vec3 w = with_plane(v, Vec2(7, 8), p);
        CHECK(w[ax.a] == 7);
        CHECK(w[ax.b] == 8);
        CHECK(w[ax.c] == v[ax.c]);
    }
    CHECK(in_plane(v, Plane::zx) == Vec2(3, 1));  // G18: a = Z, b = X
    CHECK(with_plane(v, Vec2(7, 8), Plane::yz) == Vec3(1, 7, 8));
}
