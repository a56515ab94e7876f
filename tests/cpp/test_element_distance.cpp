// The overcut watch's element distance against dense sampling of both elements: random
// line segments, minor and major arcs, full circles and slight spirals (the radius changing
// linearly with the angle swept), in both directions. The sampled distance is an upper bound
// of the exact one and comes within the sample spacing of it (spirals: within their radius
// change).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "toolcomp/compensation/overcut.hpp"

using namespace toolcomp;

namespace {

std::vector<Vec2> samples(const Element2& e, int n) {
    std::vector<Vec2> out;
    if (!e.is_arc) {
        for (int i = 0; i <= n; ++i) out.push_back(e.p0 + (e.p1 - e.p0) * (double(i) / n));
        return out;
    }
    const double r0 = (e.p0 - e.c).norm(), r1 = (e.p1 - e.c).norm(), sweep = e.sweep();
    const double a0 = std::atan2(e.p0.y() - e.c.y(), e.p0.x() - e.c.x());
    for (int i = 0; i <= n; ++i) {
        const double t = double(i) / n;
        const double a = a0 + e.dir * sweep * t, r = r0 + (r1 - r0) * t;
        out.push_back(e.c + r * Vec2(std::cos(a), std::sin(a)));
    }
    return out;
}

double sampled_distance(const Element2& a, const Element2& b, int n) {
    const auto sa = samples(a, n), sb = samples(b, n);
    double d = INFINITY;
    for (const auto& p : sa)
        for (const auto& q : sb) d = std::min(d, (p - q).norm());
    return d;
}

double spiral_of(const Element2& e) { return e.is_arc ? std::fabs((e.p1 - e.c).norm() - (e.p0 - e.c).norm()) : 0.0; }

Element2 random_element(std::mt19937& rng) {
    std::uniform_real_distribution<double> pos(-5, 5), unit(0, 1);
    const Vec2 a(pos(rng), pos(rng));
    if (unit(rng) < 0.35) return Element2::line(a, Vec2(pos(rng), pos(rng)));
    const Vec2 c(pos(rng), pos(rng));
    const double r0 = (a - c).norm();
    const double a0 = std::atan2(a.y() - c.y(), a.x() - c.x());
    const double u = unit(rng);
    const double sweep = u < 0.1 ? 2 * kPi : u * 2 * kPi;  // a full circle, minor and major arcs
    const int dir = unit(rng) < 0.5 ? 1 : -1;
    const double r1 = unit(rng) < 0.2 ? r0 * (1 + 0.01 * (unit(rng) - 0.5)) : r0;  // slight spirals
    const double a1 = a0 + dir * sweep;
    const Vec2 b = sweep == 2 * kPi ? a : Vec2(c + r1 * Vec2(std::cos(a1), std::sin(a1)));
    return Element2::arc(a, b, c, dir);
}

}  // namespace

TEST_CASE("element distance: exact against dense sampling of random lines, arcs and spirals") {
    std::mt19937 rng(20261201);
    const int n = 600;
    for (int k = 0; k < 400; ++k) {
        const Element2 a = random_element(rng), b = random_element(rng);
        const double exact = element_distance(a, b), sampled = sampled_distance(a, b, n);
        // Sample spacing: the longer element's length over n (arcs up to 10 mm radius).
        const double spacing = std::max(a.length(), b.length()) / n;
        // A spiral is taken within its radius change (the watch allows for that on both sides).
        const double spiral = spiral_of(a) + spiral_of(b);
        INFO("case " << k << ": exact " << exact << ", sampled " << sampled << ", spiral " << spiral);
        CHECK(exact >= 0);
        CHECK(exact <= sampled + spiral + 1e-9);
        CHECK(sampled - exact <= spacing + spiral + 1e-9);
        const double bound = distance_lower_bound(Swept(a), Swept(b));
        CHECK(bound <= exact + spiral + 1e-9);
        CHECK(bound <= sampled + 1e-9);
        // Stopping at a partial bound still gives a lower bound.
        CHECK(distance_lower_bound(Swept(a), Swept(b), 0.5 * exact) <= exact + spiral + 1e-9);
    }
}

TEST_CASE("element distance: arcs about an end of a segment (corner arcs), against sampling") {
    std::mt19937 rng(1202);
    std::uniform_real_distribution<double> pos(-5, 5), unit(0, 1);
    int settled = 0;
    for (int k = 0; k < 400; ++k) {
        const Element2 seg = Element2::line(Vec2(pos(rng), pos(rng)), Vec2(pos(rng), pos(rng)));
        const Vec2 c = (unit(rng) < 0.5 ? seg.p0 : seg.p1) + 1e-3 * (unit(rng) - 0.5) * Vec2(1, 1);
        const double r = 0.5 + 2 * unit(rng), a0 = 2 * kPi * unit(rng), sweep = kPi * unit(rng);
        const int dir = unit(rng) < 0.5 ? 1 : -1;
        const Element2 arc = Element2::arc(c + r * Vec2(std::cos(a0), std::sin(a0)),
                                           c + r * Vec2(std::cos(a0 + dir * sweep), std::sin(a0 + dir * sweep)), c, dir);
        const double sampled = sampled_distance(arc, seg, 2000);
        const double bound = distance_lower_bound(Swept(arc), Swept(seg));
        INFO("case " << k << ": bound " << bound << ", sampled " << sampled);
        CHECK(bound <= sampled + 1e-9);
        CHECK(bound <= element_distance(arc, seg) + 1e-9);
        settled += bound > r - 2e-3;
    }
    CHECK(settled > 50);  // the arcs that turn away from the segment are settled by the bound
}

TEST_CASE("element distance: corner arcs and segments off an arc's sweep, against sampling") {
    // A minor arc, and at one of its ends a corner arc of radius r (or a segment from there)
    // turning any way: the bound never passes the sampled distance, and it settles those that
    // lie off the arc's sweep (the distance is then the corner's radius).
    std::mt19937 rng(1204);
    std::uniform_real_distribution<double> pos(-5, 5), unit(0, 1);
    int settled = 0, checked = 0;
    for (int k = 0; k < 600; ++k) {
        const Vec2 o(pos(rng), pos(rng));
        const double R = 1 + 4 * unit(rng), b0 = 2 * kPi * unit(rng), bs = kPi * unit(rng);
        const int bdir = unit(rng) < 0.5 ? 1 : -1;
        const Element2 arc = Element2::arc(o + R * Vec2(std::cos(b0), std::sin(b0)),
                                           o + R * Vec2(std::cos(b0 + bdir * bs), std::sin(b0 + bdir * bs)), o, bdir);
        const Vec2 E = unit(rng) < 0.5 ? arc.p0 : arc.p1;
        const double r = 0.2 + unit(rng), a0 = 2 * kPi * unit(rng), sweep = kPi * unit(rng);
        const int dir = unit(rng) < 0.5 ? 1 : -1;
        const Vec2 s = E + r * Vec2(std::cos(a0), std::sin(a0)), e = E + r * Vec2(std::cos(a0 + dir * sweep), std::sin(a0 + dir * sweep));
        const Element2 other = unit(rng) < 0.7 ? Element2::arc(s, e, E, dir) : Element2::line(E + 0.5 * (s - E), s + (s - E));
        const double sampled = sampled_distance(other, arc, 2000), exact = element_distance(other, arc);
        for (const double bound : {distance_lower_bound(Swept(other), Swept(arc)), distance_lower_bound(Swept(arc), Swept(other))}) {
            INFO("case " << k << ": bound " << bound << ", exact " << exact << ", sampled " << sampled);
            CHECK(bound <= sampled + 1e-9);
            CHECK(bound <= exact + 1e-9);
            ++checked;
            settled += other.is_arc && bound > r - 1e-9;
        }
    }
    CHECK(checked == 1200);
    CHECK(settled > 100);  // the corner arcs that turn away from the arc (0 without the bound)
}

TEST_CASE("element distance: hand-calculated cases") {
    // Parallel segments 2 apart; a segment through a circle; a point of a quarter arc.
    CHECK(element_distance(Element2::line({0, 0}, {10, 0}), Element2::line({2, 2}, {8, 2})) == Approx(2));
    CHECK(element_distance(Element2::line({-5, 0}, {5, 0}), Element2::arc({3, 0}, {3, 0}, {0, 0}, 1)) == 0);
    // Quarter arc of radius 3 about the origin from (3,0) CCW to (0,3); the point (4,4) as a
    // short segment: nearest at 45 degrees, 4*sqrt(2) - 3.
    const Element2 quarter = Element2::arc({3, 0}, {0, 3}, {0, 0}, 1);
    CHECK(element_distance(quarter, Element2::line({4, 4}, {4, 4})) == Approx(4 * std::sqrt(2.0) - 3));
    // The same quarter run CW is the other three quarters: (4,4) is nearest to its ends,
    // distance to (3,0) = sqrt(1 + 16).
    const Element2 three = Element2::arc({3, 0}, {0, 3}, {0, 0}, -1);
    CHECK(element_distance(three, Element2::line({4, 4}, {4, 4})) == Approx(std::sqrt(17.0)));
    // (-4,-4) lies in the three quarters' sweep: 4*sqrt(2) - 3 again; off the quarter's, its
    // ends are sqrt(49 + 16) away.
    CHECK(element_distance(three, Element2::line({-4, -4}, {-4, -4})) == Approx(4 * std::sqrt(2.0) - 3));
    CHECK(element_distance(quarter, Element2::line({-4, -4}, {-4, -4})) == Approx(std::sqrt(65.0)));
}

TEST_CASE("distance lower bound: the cases it settles") {
    // Parallel segments 2 apart; concentric arcs of radii 3 and 5; a segment 1 outside a
    // circle of radius 3; a segment inside a circle of radius 10 (farthest end 5 from its
    // centre); crossing segments: nothing known.
    CHECK(distance_lower_bound(Swept(Element2::line({0, 0}, {10, 0})), Swept(Element2::line({2, 2}, {8, 2}))) == Approx(2));
    CHECK(distance_lower_bound(Swept(Element2::arc({3, 0}, {0, 3}, {0, 0}, 1)),
                               Swept(Element2::arc({0, 5}, {5, 0}, {0, 0}, -1))) == Approx(2));
    CHECK(distance_lower_bound(Swept(Element2::line({-5, 4}, {5, 4})), Swept(Element2::arc({3, 0}, {-3, 0}, {0, 0}, 1))) ==
          Approx(1));
    CHECK(distance_lower_bound(Swept(Element2::line({-3, 4}, {3, 4})), Swept(Element2::arc({10, 0}, {-10, 0}, {0, 0}, 1))) ==
          Approx(5));
    CHECK(distance_lower_bound(Swept(Element2::line({0, 0}, {2, 2})), Swept(Element2::line({0, 2}, {2, 0}))) <= 0);
}

TEST_CASE("element box: holds every point of the element, and is no larger for circular arcs") {
    std::mt19937 rng(4242);
    const int n = 4000;
    for (int k = 0; k < 500; ++k) {
        const Element2 e = random_element(rng);
        const Swept s(e);
        Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
        for (const Vec2& p : samples(e, n)) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        INFO("case " << k << (e.is_arc ? " arc" : " line") << ", spiral " << spiral_of(e));
        CHECK((s.lo.array() <= lo.array() + 1e-9).all());
        CHECK((s.hi.array() >= hi.array() - 1e-9).all());
        if (spiral_of(e) == 0) {  // circular: the sampled box comes within the sample spacing of it
            const double spacing = e.length() / n + 1e-9;
            CHECK(((lo - s.lo).array() <= spacing).all());
            CHECK(((s.hi - hi).array() <= spacing).all());
        }
        // Two boxes' gap is a lower bound of the elements' distance.
        const Element2 f = random_element(rng);
        CHECK(std::sqrt(box_gap2(s, Swept(f))) <= sampled_distance(e, f, 600) + 1e-9);
    }
}
