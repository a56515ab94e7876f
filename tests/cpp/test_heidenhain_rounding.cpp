// Heidenhain RND next to arcs (line/arc, arc/line, arc/arc) and CHF next to an arc, with
// hand-computed tangent points and rounding centres (spec §2.3: a tangential arc of radius R
// between the previous and the next element, the corner point cut off).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "heidenhain_helpers.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;
using namespace tctest::hh;

namespace {

const std::string kHead = "TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\n";

}  // namespace

TEST_CASE("heidenhain RND between a line and an arc", "[heidenhain][rnd]") {
    // Line (0,0) -> (30,0) heading +X; CW arc about C = (40,0), R = 10, from P = (30,0)
    // (start tangent +Y: a left turn of 90°) to (40,10). RND R5: the centre lies 5 left of the
    // line (y = 5) and 5 outside the CW arc (|F - C| = 15): (x - 40)² + 25 = 225, x = 40 - 10√2.
    // Tangent points: T1 = (40 - 10√2, 0) on the line, T2 = C + 10 (F - C) / 15
    // = (40 - 20√2/3, 10/3) on the arc; the rounding turns left (CCW).
    const Result r = run_h(kHead + "L X+0 Y+0 Z+0 R0 F100\nL X+30 Y+0\nRND R5\nCC X+40 Y+0\nC X+40 Y+10 DR-\n");
    const Path& p = r.path;
    const double s2 = std::sqrt(2.0);
    const auto line = of_line(p, 5), rnd = of_line(p, 6), arc = of_line(p, 8);
    REQUIRE(line.size() == 1);
    REQUIRE(rnd.size() == 1);
    REQUIRE(arc.size() == 1);
    CHECK_XY(col(p.end, line[0]), 40 - 10 * s2, 0);
    CHECK(p.kind[rnd[0]] == static_cast<std::uint8_t>(MotionKind::arc_ccw));
    CHECK_XY(col(p.starts(), rnd[0]), 40 - 10 * s2, 0);
    CHECK_XY(col(p.centers(), rnd[0]), 40 - 10 * s2, 5);
    CHECK_XY(col(p.end, rnd[0]), 40 - 20 * s2 / 3, 10.0 / 3);
    // The arc is shortened to start at T2, keeps its centre, direction and end.
    CHECK(p.kind[arc[0]] == static_cast<std::uint8_t>(MotionKind::arc_cw));
    CHECK_XY(col(p.starts(), arc[0]), 40 - 20 * s2 / 3, 10.0 / 3);
    CHECK_XY(col(p.centers(), arc[0]), 40, 0);
    CHECK_XY(col(p.end, arc[0]), 40, 10);
}

TEST_CASE("heidenhain RND between an arc and a line", "[heidenhain][rnd]") {
    // CCW arc about (0,0), R = 10, from (10,0) to P = (0,10) (end tangent -X), then a line to
    // (0,30) heading +Y: a right turn of 90°. RND R3: the centre lies 3 right of the line
    // (x = 3) and 3 outside the CCW arc (|F| = 13): y = √(169 - 9) = 4√10. Tangent points
    // T1 = 10 F / 13 = (30/13, 40√10/13) on the arc, T2 = (0, 4√10) on the line; the
    // rounding turns right (CW).
    const Result r = run_h(kHead + "L X+10 Y+0 Z+0 R0 F100\nCC X+0 Y+0\nC X+0 Y+10 DR+\nRND R3\nL X+0 Y+30\n");
    const Path& p = r.path;
    const double s10 = std::sqrt(10.0);
    const auto arc = of_line(p, 6), rnd = of_line(p, 7), line = of_line(p, 8);
    REQUIRE(arc.size() == 1);
    REQUIRE(rnd.size() == 1);
    REQUIRE(line.size() == 1);
    CHECK_XY(col(p.starts(), arc[0]), 10, 0);
    CHECK_XY(col(p.end, arc[0]), 30.0 / 13, 40 * s10 / 13);
    CHECK_XY(col(p.centers(), arc[0]), 0, 0);
    CHECK(p.kind[rnd[0]] == static_cast<std::uint8_t>(MotionKind::arc_cw));
    CHECK_XY(col(p.centers(), rnd[0]), 3, 4 * s10);
    CHECK_XY(col(p.end, rnd[0]), 0, 4 * s10);
    CHECK_XY(col(p.starts(), line[0]), 0, 4 * s10);
    CHECK_XY(col(p.end, line[0]), 0, 30);
}

TEST_CASE("heidenhain RND between two arcs", "[heidenhain][rnd]") {
    // Two circles of radius 10 about (0,0) and (10,0) meet in P = (5, 5√3). Arc 1: CCW about
    // (0,0) from (10,0) to P (end tangent (-√3/2, 1/2)); arc 2: CCW about (10,0) from P to
    // (0,0) (start tangent (-√3/2, -1/2)): a left turn of 60°. RND R2: the centre lies 2 inside
    // both CCW arcs: on both circles of radius 8, x = 5, y = √(64 - 25) = √39. Tangent points
    // T1 = 10 F / 8 = (6.25, 1.25√39), T2 = (10,0) + 10 (F - (10,0)) / 8 = (3.75, 1.25√39).
    const Result r = run_h(kHead +
                           "L X+10 Y+0 Z+0 R0 F100\nCC X+0 Y+0\nC X+5 Y+8.6602540378 DR+\nRND R2\n"
                           "CC X+10 Y+0\nC X+0 Y+0 DR+\n");
    const Path& p = r.path;
    const double y = 1.25 * std::sqrt(39.0);
    const auto a1 = of_line(p, 6), rnd = of_line(p, 7), a2 = of_line(p, 9);
    REQUIRE(a1.size() == 1);
    REQUIRE(rnd.size() == 1);
    REQUIRE(a2.size() == 1);
    CHECK_XY(col(p.end, a1[0]), 6.25, y);
    CHECK(p.kind[rnd[0]] == static_cast<std::uint8_t>(MotionKind::arc_ccw));
    CHECK_XY(col(p.starts(), rnd[0]), 6.25, y);
    CHECK_XY(col(p.centers(), rnd[0]), 5, std::sqrt(39.0));
    CHECK_XY(col(p.end, rnd[0]), 3.75, y);
    CHECK_XY(col(p.starts(), a2[0]), 3.75, y);
    CHECK_XY(col(p.centers(), a2[0]), 10, 0);
    CHECK_XY(col(p.end, a2[0]), 0, 0);
}

TEST_CASE("heidenhain RND next to an arc, with radius compensation", "[heidenhain][rnd]") {
    // The line/arc case above with RL and r = 1: the tool runs on y = 1, inside the rounding
    // (radius 5 - 1 = 4 about F = (40 - 10√2, 5)), then outside the CW arc (radius 11). All
    // joints are tangent: the tool leaves the rounding at F + 4 (T2 - F) / 5
    // = (40 - 22√2/3, 11/3), which is also C + 11 (T2 - C) / 10 on the arc.
    const Result r = run_h(
        "TOOL DEF 1 L+0 R+1\nTOOL CALL 1 Z\nL X-10 Y-10 Z+0 R0 F100\nL X+0 Y+0 RL\nL X+30 Y+0\nRND R5\n"
        "CC X+40 Y+0\nC X+40 Y+10 DR-\nL X+60 Y+10 R0\n");
    const Path& p = r.path;
    const double s2 = std::sqrt(2.0);
    const auto line = of_line(p, 6), rnd = of_line(p, 7), arc = of_line(p, 9);
    REQUIRE(line.size() == 1);
    REQUIRE(rnd.size() == 1);
    REQUIRE(arc.size() == 1);
    CHECK_XY(col(p.starts(), line[0]), 0, 1);
    CHECK_XY(col(p.end, line[0]), 40 - 10 * s2, 1);
    CHECK_XY(col(p.centers(), rnd[0]), 40 - 10 * s2, 5);
    CHECK_XY(col(p.end, rnd[0]), 40 - 22 * s2 / 3, 11.0 / 3);
    CHECK_XY(col(p.starts(), arc[0]), 40 - 22 * s2 / 3, 11.0 / 3);
    CHECK_XY(col(p.end, arc[0]), 40, 11);  // the CW arc's end, 11 from its centre on the left
    for (std::size_t i : {line[0], rnd[0], arc[0]}) CHECK(p.side[i] == 1);
    for (std::size_t i = 0; i < p.size(); ++i) CHECK_FALSE(p.generated[i]);  // no corner arcs
}

TEST_CASE("heidenhain RND next to an arc: radius too large", "[heidenhain][rnd]") {
    std::string msg;
    int line = 0;
    // The two arcs of radius 10 above, rounded from the inside with R10: no room (the
    // equidistant circles have radius 0).
    CHECK(error_of(kHead + "L X+10 Y+0 Z+0 R0 F100\nCC X+0 Y+0\nC X+5 Y+8.6602540378 DR+\nRND R10\n"
                           "CC X+10 Y+0\nC X+0 Y+0 DR+\n",
                   &msg, &line) == "rounding_too_large");
    CHECK(msg == "ROUNDING-OFF RADIUS TOO LARGE");
    CHECK(line == 7);
    // Line then arc: the tangent point on the line would lie 4.142 before the corner, but the
    // line is only 2 long.
    CHECK(error_of(kHead + "L X+28 Y+0 Z+0 R0 F100\nL X+30 Y+0\nRND R5\nCC X+40 Y+0\nC X+40 Y+10 DR-\n", &msg,
                   &line) == "rounding_too_large");
    CHECK(line == 6);
    // Line then arc: the CW arc sweeps only 10° (to 170°), the tangent point lies at 160.5°.
    CHECK(error_of(kHead + "L X+0 Y+0 Z+0 R0 F100\nL X+30 Y+0\nRND R5\nCC X+40 Y+0\n"
                           "C X+30.1519224699 Y+1.7364817767 DR-\n",
                   &msg, &line) == "rounding_too_large");
}

TEST_CASE("heidenhain CHF next to an arc is refused as on the TNC", "[heidenhain][chf]") {
    // The TNC inserts chamfers between two straight lines only ("CHF: chamfer between two
    // straight lines", spec §2.3/§2.7): next to an arc it stops with CHAMFER NOT PERMITTED.
    std::string msg;
    int line = 0;
    CHECK(error_of(kHead + "L X+0 Y+0 Z+0 R0 F100\nL X+30 Y+0\nCHF 2\nCC X+40 Y+0\nC X+40 Y+10 DR-\n", &msg,
                   &line) == "chamfer_next_to_arc");
    CHECK(msg == "CHAMFER NOT PERMITTED");
    CHECK(line == 6);
    CHECK(error_of(kHead + "L X+10 Y+0 Z+0 R0 F100\nCC X+0 Y+0\nC X+0 Y+10 DR+\nCHF 2\nL X+0 Y+30\n", &msg,
                   &line) == "chamfer_next_to_arc");
    CHECK(msg == "CHAMFER NOT PERMITTED");
    CHECK(line == 7);
    // Between two lines it still cuts both back by the side length: (30,0) corner, +Y next.
    const Result r = run_h(kHead + "L X+0 Y+0 Z+0 R0 F100\nL X+30 Y+0\nCHF 2\nL X+30 Y+20\n");
    const auto chf = of_line(r.path, 6);
    REQUIRE(chf.size() == 1);
    CHECK_XY(col(r.path.starts(), chf[0]), 28, 0);
    CHECK_XY(col(r.path.end, chf[0]), 30, 2);
}

TEST_CASE("heidenhain RND next to a helix is refused", "[heidenhain][rnd]") {
    CHECK(error_of(kHead + "L X+0 Y+0 Z+0 R0 F100\nL X+30 Y+0\nRND R5\nCC X+40 Y+0\nC X+40 Y+10 Z-2 DR-\n") ==
          "rounding_next_to_helix");
}
