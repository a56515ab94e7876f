// Offsets, joint classification and intersections: the spec's worked examples (§1.2, §1.4)
// and hand calculations.
#include <catch2/catch.hpp>
#include <cmath>

#include "toolcomp/geometry/element.hpp"

using namespace toolcomp;

TEST_CASE("offset of a line, left and right") {
    auto l = Element2::line({0, 0}, {50, 0});
    auto left = offset(l, +1, 5), right = offset(l, -1, 5);
    CHECK(left->p0.isApprox(Vec2(0, 5)));
    CHECK(left->p1.isApprox(Vec2(50, 5)));
    CHECK(right->p1.isApprox(Vec2(50, -5)));
}

TEST_CASE("offset of an arc: spec 1.2 worked example") {
    // G3 from (50,0) to (0,50) about the origin, R 50, r 5.
    auto a = Element2::arc({50, 0}, {0, 50}, {0, 0}, +1);
    auto g41 = offset(a, +1, 5), g42 = offset(a, -1, 5);
    CHECK(g41->radius() == Approx(45));
    CHECK(g41->p0.isApprox(Vec2(45, 0)));
    CHECK(g41->p1.isApprox(Vec2(0, 45)));
    CHECK(g42->radius() == Approx(55));
    CHECK(g42->p1.isApprox(Vec2(0, 55)));
    // G3 R4 with r 5 on the inside: the tool does not fit.
    CHECK_FALSE(offset(Element2::arc({4, 0}, {0, 4}, {0, 0}, +1), +1, 5));
}

TEST_CASE("joints of the L-shape, spec 1.4: inside at B, outside at C") {
    // A(0,0) -> B(50,0) -> C(50,30) -> D(80,30), left compensation, r = 5.
    auto ab = Element2::line({0, 0}, {50, 0}), bc = Element2::line({50, 0}, {50, 30}),
         cd = Element2::line({50, 30}, {80, 30});
    CHECK(classify_joint(ab.end_tangent(), bc.start_tangent(), +1, 1e-6, 1e-6) == JointKind::inside);
    CHECK(classify_joint(bc.end_tangent(), cd.start_tangent(), +1, 1e-6, 1e-6) == JointKind::outside);
    auto ab5 = *offset(ab, +1, 5), bc5 = *offset(bc, +1, 5), cd5 = *offset(cd, +1, 5);
    auto b = intersect(ab5, bc5);
    REQUIRE(b.size() == 1);
    CHECK(b[0].isApprox(Vec2(45, 5)));
    // Outside joint: transition arc (45,30) to (50,35) about C, or the G451 intersection (45,35).
    CHECK(bc5.p1.isApprox(Vec2(45, 30)));
    CHECK(cd5.p0.isApprox(Vec2(50, 35)));
    auto c = intersect(bc5, cd5);
    REQUIRE(c.size() == 1);
    CHECK(c[0].isApprox(Vec2(45, 35)));
    // Reversal and tangency.
    CHECK(classify_joint({1, 0}, {-1, 0}, +1, 1e-6, 1e-6) == JointKind::reversal);
    CHECK(classify_joint({1, 0}, {1, 1e-9}, +1, 1e-6, 1e-6) == JointKind::tangent);
}

TEST_CASE("start-up example, spec 1.6.1: intersection style (type B) gives (-2.071, 5)") {
    auto entry = Element2::line({-10, -10}, {0, 0}), next = Element2::line({0, 0}, {50, 0});
    auto e5 = *offset(entry, +1, 5), n5 = *offset(next, +1, 5);
    auto v = intersect(e5, n5);
    REQUIRE(v.size() == 1);
    CHECK(v[0].x() == Approx(-2.0711).margin(1e-4));
    CHECK(v[0].y() == Approx(5));
    // LinuxCNC: perpendicular to the entry move at its end: P1 + r·nL(entry) = (-3.536, 3.536).
    CHECK(e5.p1.x() == Approx(-5 / std::sqrt(2.0)));
    CHECK(e5.p1.y() == Approx(5 / std::sqrt(2.0)));
}

TEST_CASE("intersections of line/arc and arc/arc") {
    auto circle = Element2::arc({5, 0}, {5, 0}, {0, 0}, +1);
    auto horizontal = Element2::line({-10, 3}, {10, 3});
    auto pts = intersect(horizontal, circle);
    REQUIRE(pts.size() == 2);
    CHECK(pts[0].isApprox(Vec2(-4, 3)));
    CHECK(pts[1].isApprox(Vec2(4, 3)));
    auto other = Element2::arc({11, 0}, {11, 0}, {8, 0}, +1);  // radius 3, centre (8,0)
    auto cc = intersect(circle, other);
    // x = (64 + 25 - 9) / 16 = 5 = r1: the circles touch at (5, 0).
    REQUIRE(cc.size() == 1);
    CHECK(cc[0].isApprox(Vec2(5, 0)));
    auto crossing = Element2::arc({10, 0}, {10, 0}, {6, 0}, +1);  // radius 4, centre (6,0)
    auto two = intersect(circle, crossing);
    // x = (36 + 25 - 16) / 12 = 3.75, h = sqrt(25 - 14.0625) = 3.3072
    REQUIRE(two.size() == 2);
    CHECK(two[0].isApprox(Vec2(3.75, std::sqrt(25 - 3.75 * 3.75))));
    CHECK(two[1].isApprox(Vec2(3.75, -std::sqrt(25 - 3.75 * 3.75))));
    auto miss = Element2::line({-10, 6}, {10, 6});
    CHECK(intersect(miss, circle).empty());
    CHECK(std::fabs(circle.sweep() - 2 * kPi) < 1e-12);
}
