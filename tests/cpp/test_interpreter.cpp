// The modal interpreter: positions, units, distance modes, planes, arcs, offsets and tool
// length compensation. Numbers are hand calculations or LinuxCNC rs274 output (noted).
#include <catch2/catch.hpp>
#include <cmath>

#include "run_helpers.hpp"

using namespace toolcomp;
using tctest::end_of;
using tctest::run_text;

TEST_CASE("G0/G1 with G90 and G91, feed in mm/min") {
    auto r = run_text("G21 G90 G0 X1 Y2 Z3\nG1 X4 F300\nG91 G1 X1 Y1\nM2\n");
    const Path& p = r.nominal;
    REQUIRE(p.size() == 3);
    CHECK(p.kind[0] == 0);
    CHECK(std::isnan(p.feed[0]));
    CHECK(end_of(p, 1).x() == 4);
    CHECK(p.feed[1] == 300);
    CHECK(end_of(p, 2).isApprox(Vec3(5, 3, 3)));
    CHECK(p.line[2] == 3);
}

TEST_CASE("G20: inch program gives millimetres; F before G20 on the line is in the old units") {
    auto r = run_text("G21 G0 X0 Y0\nG20 G1 X1 F10\nF10\nG1 Y1\nM2\n");
    const Path& p = r.nominal;
    REQUIRE(p.size() == 3);
    CHECK(end_of(p, 1).x() == Approx(25.4));
    CHECK(p.feed[1] == Approx(10.0));  // F10 read while G21 was still active
    CHECK(p.feed[2] == Approx(254.0));
    CHECK(end_of(p, 2).y() == Approx(25.4));
}

TEST_CASE("axis words need a motion mode, and G80 refuses them") {
    CHECK_THROWS_WITH(run_text("G21\nX10\nM2\n"), "Cannot use axis values without a g code that uses them");
    CHECK_THROWS_WITH(run_text("X1 G80\nM2\n"), "Cannot use axis values with g80");
    CHECK_THROWS_WITH(run_text("G0 G1 X1\nM2\n"), "Two g codes used from same modal group");
    CHECK_THROWS_WITH(run_text("M3 M4\nM2\n"), "Two m codes used from same modal group");
    CHECK_THROWS_WITH(run_text("G0 X1 X2\nM2\n"), "Multiple x words on one line");
    CHECK_THROWS_WITH(run_text("G12 X1\nM2\n"), "Unknown g code used");
    CHECK_THROWS_WITH(run_text("M123\nM2\n"), "Unknown m code used: M123");
    CHECK_THROWS_WITH(run_text("G0 X1\n"), "File ended with no percent sign or program end");
}

TEST_CASE("errors carry their line and column") {
    try {
        run_text("G21 G0 X0 Y0\nG1 F100\nG2 X10 Y0 R4\nM2\n");
        FAIL("no error");
    } catch (const ProgramError& e) {
        CHECK(std::string(e.what()) == "Arc radius too small to reach end point");
        CHECK(e.code() == "arc_radius_too_small");
        CHECK(e.line() == 3);
        CHECK(e.column() == 11);
    }
}

TEST_CASE("arcs: IJK and R in G17, G18, G19; helix; full circle with turns") {
    auto r = run_text(
        "G21 G17 G0 X10 Y0 Z0\nF100\n"
        "G3 X0 Y10 I-10 J0\n"          // quarter, centre (0,0)
        "G2 X10 Y0 R10\n"              // back, R>0 short arc clockwise: centre (0,0)
        "G3 X10 Y0 I-10 Z-2 P3\n"      // helix of three full turns
        "G18 G0 X0 Y0 Z10\n"
        "G3 X10 Z0 I0 K-10\n"          // ZX quarter about the origin
        "G19 G0 X0 Y10 Z0\n"
        "G2 Y0 Z-10 R-10\n"            // YZ: R<0 = more than 180 degrees
        "M2\n");
    const Path& p = r.nominal;
    REQUIRE(p.size() == 8);  // three rapids, five arcs
    CHECK(p.kind[1] == 3);
    CHECK(Vec3(p.centers()[3], p.centers()[4], p.centers()[5]).isApprox(Vec3(0, 0, 0)));
    CHECK(p.kind[2] == 2);
    CHECK(std::fabs(p.centers()[6]) < 1e-9);
    CHECK(std::fabs(p.centers()[7]) < 1e-9);
    CHECK(p.turns(3) == 2);
    CHECK(end_of(p, 3).z() == Approx(-2));
    CHECK(p.plane(5) == 1);
    CHECK(p.centers()[3 * 5 + 0] == Approx(0).margin(1e-12));
    CHECK(p.centers()[3 * 5 + 2] == Approx(0).margin(1e-12));
    // G19 R-10 from (Y10,Z0) to (Y0,Z-10), clockwise seen from +X, more than 180 degrees: the
    // centre is the one of the two candidates ((0,0) and (10,-10)) that gives the long arc.
    CHECK(p.plane(7) == 2);
    CHECK(p.centers()[3 * 7 + 1] == Approx(10));
    CHECK(p.centers()[3 * 7 + 2] == Approx(-10));
}

TEST_CASE("arc end off the circle: LinuxCNC's tolerance and message") {
    // r1 = 5, r2 = 5.1: abs_err 0.1 > 0.028284 and rel_err 1.96% > 0.1%.
    CHECK_THROWS_WITH(run_text("G21 G0 X0 Y0\nG1 F100\nG2 X10.1 Y0 I5 J0\nM2\n"),
                      "Radius to end of arc differs from radius to start: start=(X0.0000,Y0.0000) "
                      "center=(X5.0000,Y0.0000) end=(X10.1000,Y0.0000) r1=5.0000 r2=5.1000 abs_err=0.1 "
                      "rel_err=1.9608%");
    // r = 10, r2 = 10.0282: within 0.028284 mm, accepted as a slight spiral.
    CHECK_NOTHROW(run_text("G21 G0 X0 Y0\nG1 F100\nG2 X20.0282 Y0 I10 J0\nM2\n"));
}

TEST_CASE("work offsets: G54-G59.3, G10 L2/L20, G92 family, G53, G28 (checked against rs274)") {
    // The same program as LinuxCNC rs274 ran (outputs noted in the research notes).
    auto r = run_text(
        "G21 G0 X1 Y2 Z3\nG28.1\nG0 X5 Y5 Z5\nG28 Z10\nG28\nG0 X7 Y7 Z7\nG91 G28 X1\nG90 G55\n"
        "G10 L20 P2 X0 Y0\nG0 X1\nG92 X0 Y0\nG0 X1\nG92.2\nG0 X1\nG92.3\nG0 X1\nG92.1\nG0 X1\n"
        "G53 G0 X0 Y0\nM2\n");
    const Path& p = r.nominal;
    const double expect[][3] = {{1, 2, 3}, {5, 5, 5}, {5, 5, 10}, {5, 5, 3}, {5, 5, 3}, {1, 2, 3},
                                {7, 7, 7}, {8, 7, 7}, {1, 7, 7}, {1, 0, 7}, {1, 0, 7}, {1, 0, 7},
                                {1, 0, 7}, {1, 0, 7}, {-1, -7, 7}};
    REQUIRE(p.size() == std::size(expect));
    for (std::size_t i = 0; i < p.size(); ++i) {
        INFO("segment " << i);
        CHECK(end_of(p, i).isApprox(Vec3(expect[i][0], expect[i][1], expect[i][2]), 1e-12));
    }
}

TEST_CASE("G7 diameter mode halves X words but not I, K or R") {
    // LinuxCNC rs274: from X5 (radius) Z-5, "G7 G2 X20 Z-10 I5 K0" ends at x 10, centre x 10.
    auto r = run_text("G21 G18 G8 G0 X5 Z-5\nG7 G2 X20 Z-10 I5 K0 F100\nG1 X30\nM2\n");
    const Path& p = r.nominal;
    REQUIRE(p.size() == 3);
    CHECK(end_of(p, 1).x() == Approx(10));
    CHECK(p.centers()[3 * 1 + 0] == Approx(10));
    CHECK(end_of(p, 2).x() == Approx(15));
}
