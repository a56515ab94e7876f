// SegmentTree: hand-worked segment gaps, and the tree's nearest distance against every
// segment tried in turn (random sets, clustered and spread, with limits that cut some off).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "toolcomp/geometry/segment_tree.hpp"

using namespace toolcomp;

TEST_CASE("segment_gap by hand") {
    // crossing: (0,0)-(4,4) and (0,4)-(4,0) meet at (2,2)
    SegmentGap g = segment_gap({0, 0}, {4, 4}, {0, 4}, {4, 0});
    CHECK(g.distance == 0.0);
    CHECK(g.at.x() == Approx(2.0));
    CHECK(g.at.y() == Approx(2.0));
    // parallel, 3 apart, overlapping in x: an end point of one against the other
    g = segment_gap({0, 0}, {10, 0}, {2, 3}, {5, 3});
    CHECK(g.distance == Approx(3.0));
    CHECK(g.at.x() == Approx(2.0));
    CHECK(g.at.y() == Approx(0.0));
    // the end (0, 6) of a spike 5 from the middle of a long line y = 11
    g = segment_gap({-10, 11}, {10, 11}, {-1, 0}, {0, 6});
    CHECK(g.distance == Approx(5.0));
    CHECK(g.at.x() == Approx(0.0));
    CHECK(g.at.y() == Approx(11.0));
    // end to end: (0,0)-(1,0) and (4,4)-(5,5): the gap between (1,0) and (4,4)
    g = segment_gap({0, 0}, {1, 0}, {4, 4}, {5, 5});
    CHECK(g.distance == Approx(5.0));
    // touching at an end (a T): 0
    CHECK(segment_gap({0, 0}, {4, 0}, {2, 0}, {2, 5}).distance == 0.0);
}

TEST_CASE("SegmentTree::nearest is the nearest of all segments") {
    std::mt19937_64 rng(11);
    for (int round = 0; round < 40; ++round) {
        const double spread = round % 2 ? 100.0 : 5.0, len = round % 3 ? 2.0 : 20.0;
        std::uniform_real_distribution<double> pos(-spread, spread), step(-len, len);
        const int m = 1 + static_cast<int>(rng() % 300);
        std::vector<Vec2> from, to;
        for (int i = 0; i < m; ++i) {
            const Vec2 a(pos(rng), pos(rng));
            from.push_back(a);
            to.push_back(a + Vec2(step(rng), step(rng)));
        }
        const SegmentTree tree(from, to);
        for (int q = 0; q < 200; ++q) {
            const Vec2 a(pos(rng), pos(rng)), b = a + Vec2(step(rng), step(rng));
            const double limit = q % 4 == 0 ? INFINITY : std::fabs(step(rng));
            double best = limit;
            for (int i = 0; i < m; ++i) best = std::min(best, segment_gap(a, b, from[static_cast<std::size_t>(i)], to[static_cast<std::size_t>(i)]).distance);
            const SegmentGap g = tree.nearest(a, b, limit);
            if (best < limit) {
                REQUIRE(g.distance == best);
                // the point is on a-b, that far from some segment
                const Vec2 d = b - a;
                CHECK(std::fabs(d.x() * (g.at.y() - a.y()) - d.y() * (g.at.x() - a.x())) <= 1e-9 * (1 + d.squaredNorm() + spread * spread));
            } else {
                REQUIRE(g.distance >= limit);
            }
        }
    }
    // no segments: nothing is near
    const SegmentTree empty({}, {});
    CHECK(empty.nearest({0, 0}, {1, 1}, 5.0).distance == 5.0);
}

TEST_CASE("arc_gap against the arc sampled densely") {
    // The sampled distance is an upper bound of the exact one, within the sample spacing.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(-10, 10), ang(-M_PI, M_PI), rad(0.5, 6);
    int touching = 0;
    for (int round = 0; round < 3000; ++round) {
        const Vec2 c(pos(rng), pos(rng));
        const double r = rad(rng), t0 = ang(rng), t1 = ang(rng);
        const int dir = round % 2 ? 1 : -1;
        const bool full = round % 17 == 0;
        const PlaneArc arc{c + r * Vec2(std::cos(t0), std::sin(t0)), c + r * Vec2(std::cos(t1), std::sin(t1)), c, dir, full};
        const Vec2 b0(pos(rng), pos(rng)), b1(pos(rng), pos(rng));
        // the sweep from t0 to t1 in the arc's direction
        double sweep = dir > 0 ? t1 - t0 : t0 - t1;
        while (sweep < 0) sweep += 2 * M_PI;
        if (full) sweep = 2 * M_PI;
        const int n = 20000;
        double sampled = INFINITY;
        for (int k = 0; k <= n; ++k) {
            const double t = t0 + dir * sweep * k / n;
            const Vec2 p = c + r * Vec2(std::cos(t), std::sin(t));
            Vec2 nearest;
            const Vec2 ab = b1 - b0;
            const double u = std::clamp((p - b0).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            nearest = b0 + u * ab;
            sampled = std::min(sampled, (p - nearest).norm());
        }
        const SegmentGap g = arc_gap(arc, b0, b1);
        const double spacing = r * sweep / n;
        REQUIRE(g.distance <= sampled + 1e-9);
        REQUIRE(g.distance >= sampled - spacing);
        // the point is on the arc's circle
        REQUIRE((g.at - c).norm() == Approx(r).margin(1e-9));
        touching += g.distance == 0;
    }
    CHECK(touching > 300);
    CHECK(touching < 2700);
}

TEST_CASE("arc_gap takes an arc ending within 1e-12 rad of its start as a whole circle") {
    // a compensated full circle whose end misses its start by rounding, either way round
    for (const double miss : {1e-13, -1e-13, 0.0}) {
        for (const int dir : {1, -1}) {
            const PlaneArc arc{{1, 0}, {std::cos(miss), std::sin(miss)}, {0, 0}, dir, false};
            const SegmentGap g = arc_gap(arc, {-1.05, -5}, {-1.05, 5});
            CHECK(g.distance == Approx(0.05));
            CHECK(g.at.x() == Approx(-1.0));
        }
    }
}
