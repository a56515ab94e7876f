// Centres from R across the range of a double: R is scaled before it is squared, so a huge
// radius (a nearly straight arc, CR=1EX300) still has a finite centre. Hand calculations:
// chord (0,0)-(10,0), mid (5,0), h = R·sqrt(1 - (5/R)²).
#include <catch2/catch.hpp>
#include <cmath>

#include "toolcomp/geometry/arc.hpp"

using namespace toolcomp;

TEST_CASE("centre from R: R = 1e300 gives a finite centre at distance R") {
    auto cw = center_from_radius({0, 0}, {10, 0}, 1e300, -1);
    REQUIRE(cw);
    CHECK(std::isfinite(cw->x()));
    CHECK(std::isfinite(cw->y()));
    CHECK(cw->x() == Approx(5));
    CHECK(cw->y() == Approx(-1e300));  // CW, R > 0: below the chord
    auto ccw = center_from_radius({0, 0}, {10, 0}, -1e300, -1);
    REQUIRE(ccw);
    CHECK(ccw->y() == Approx(1e300));
}

TEST_CASE("centre from R: R = 1e200 and a chord of 1e150 stay finite") {
    const double R = 1e200, c = 1e150;
    auto p = center_from_radius({0, 0}, {c, 0}, R, 1);
    REQUIRE(p);
    CHECK(p->x() == Approx(c / 2));
    CHECK(p->y() == Approx(R));
}
