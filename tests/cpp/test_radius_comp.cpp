// Cutter radius compensation: the worked numbers of the spec (§1.4, §1.6.1) and vectors of
// LinuxCNC's interpreter (values from its gcode module at full precision, noted per case).
#include <catch2/catch.hpp>
#include <cmath>

#include "run_helpers.hpp"

using namespace toolcomp;
using tctest::end_of;
using tctest::run_text;

namespace {
struct Seg {
    int kind;
    double a, b;           // end in the plane (X, Y), or (Z, X) in G18
    double ca = NAN, cb = NAN;  // arc centre
};

void check_path(const Path& p, std::size_t first, std::initializer_list<Seg> expect, Plane plane = Plane::xy) {
    auto ax = axes(plane);
    std::size_t i = first;
    for (const Seg& s : expect) {
        INFO("segment " << i);
        REQUIRE(i < p.size());
        CHECK(p.kind[i] == s.kind);
        Vec3 e = end_of(p, i);
        CHECK(e[ax.a] == Approx(s.a).margin(1e-6));
        CHECK(e[ax.b] == Approx(s.b).margin(1e-6));
        if (!std::isnan(s.ca)) {
            CHECK(p.centers()[3 * i + ax.a] == Approx(s.ca).margin(1e-6));
            CHECK(p.centers()[3 * i + ax.b] == Approx(s.cb).margin(1e-6));
        }
        ++i;
    }
    CHECK(i == p.size());
}
}  // namespace

TEST_CASE("spec 1.4 L-shape and 1.6.1 start-up, LinuxCNC style") {
    // A(0,0) B(50,0) C(50,30) D(80,30), G41 r=5, entry from (-10,-10) to A.
    auto r = run_text("G21 G0 X-10 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nY30\nX80\nG40 G0 X90 Y40\nM2\n");
    const Path& p = r.path;
    // Entry: perpendicular to the entry move at (0,0) is (-3.536, 3.536); the outside joint
    // with AB inserts the arc about A from there to (0,5) (spec 1.6.1 "E2-LinuxCNC").
    const double h = 5 / std::sqrt(2.0);
    check_path(p, 1,
               {{1, -h, h},
                {2, 0, 5, 0, 0},        // corner arc about A
                {1, 45, 5},             // AB pulled back to the inside joint B (45,5)
                {1, 45, 30},            // BC
                {2, 50, 35, 50, 30},    // outside joint C: arc (45,30) -> (50,35) about C
                {1, 80, 35},
                {0, 90, 40}});          // exit, uncompensated
    CHECK(p.generated[2]);
    CHECK(p.generated[5]);
    CHECK_FALSE(p.generated[3]);
    CHECK(p.side[3] == 1);
    CHECK(p.side[7] == 0);
    CHECK(end_of(p, 6).isApprox(Vec3(80, 35, 0)));
    CHECK(Vec3(p.starts()[3 * 7], p.starts()[3 * 7 + 1], 0).isApprox(Vec3(80, 35, 0)));  // exit starts at the tool
}

TEST_CASE("LinuxCNC V1: outside corners get arcs, inside corners pull back") {
    auto r = run_text(
        "G21 G17 G90 G94\nG0 X-20 Y-20 Z5\nG1 Z-1 F500\nG41.1 D10\nG1 X0 Y0\nG1 X0 Y30\nG1 X40 Y30\n"
        "G1 X40 Y10\nG1 X20 Y10\nG1 X20 Y0\nG1 X0 Y0\nG40\nG1 X-20 Y-20\nM2\n");
    check_path(r.path, 2,
               {{1, -5, 2.071068}, {1, -5, 30}, {2, 0, 35, 0, 30}, {1, 40, 35}, {2, 45, 30, 40, 30},
                {1, 45, 10}, {2, 40, 5, 40, 10}, {1, 25, 5}, {1, 25, 0}, {2, 20, -5, 20, 0}, {1, 0, -5},
                {1, -20, -20}});
    CHECK(r.path.line[2] == 5);
    CHECK(r.path.line[4] == 7);  // a corner arc carries the line of the block after the corner
}

TEST_CASE("LinuxCNC V2: arc entry, Z-only move, G91 inside comp, tool outside an arc") {
    auto r = run_text(
        "G21 G17 G90 G94\nG0 X0 Y0 Z0\nF300\nG41.1 D8\nG3 X30 Y0 I15 J0\nG1 Z-2\nG91 G1 Y20\n"
        "G90 G2 X50 Y20 R10\nG1 X50 Y-10\nG40\nG1 X60 Y-20\nM2\n");
    check_path(r.path, 1, {{3, 26, 0, 13, 0}, {1, 26, 0}, {1, 26, 20}, {2, 54, 20, 40, 20}, {1, 54, -10}, {1, 60, -20}});
    CHECK(end_of(r.path, 2).z() == -2);
}

TEST_CASE("LinuxCNC V3: negative D cuts on the other side; a rapid corner is a traverse") {
    auto r = run_text(
        "G21 G17 G90\nG0 X-10 Y-10 Z0\nF300\nG41.1 D-6\nG1 X0 Y0\nG1 X0 Y20\nG0 X20 Y20\nG1 X20 Y0\n"
        "G40\nG0 X30 Y-10\nM2\n");
    check_path(r.path, 1,
               {{1, 2.121320, -2.121320}, {3, 3, 0, 0, 0}, {1, 3, 17}, {0, 17, 17}, {1, 17, 0}, {0, 30, -10}});
    CHECK(r.path.side[2] == -1);
}

TEST_CASE("LinuxCNC V4: lathe G42.1 with orientation 3 reports the imaginary tip") {
    auto r = run_text(
        "G21 G18 G90 G94\nG0 X30 Z5 Y0\nF100\nG42.1 D1.6 L3\nG1 X20 Z0\nG1 Z-20\nG2 X30 Z-30 R10\nG1 X40\n"
        "G40\nG0 X50 Z5\nM2\n");
    check_path(r.path, 1,
               {{1, -1.294427, 21.6}, {1, -20.8, 21.6}, {2, -30, 30.8, -20.8, 30.8}, {1, -30, 40.8}, {0, 5, 50}},
               Plane::zx);
}

TEST_CASE("LinuxCNC V5: a step narrower than the tool gouges, reported at the next block") {
    try {
        run_text("G21 G17 G90\nG0 X10 Y10 Z0\nF300\nG41.1 D10\nG1 X10 Y0\nG1 X30\nG1 X30 Y4\nG1 X0\nM2\n");
        FAIL("no error");
    } catch (const CompensationError& e) {
        CHECK(std::string(e.what()) == "Straight feed in concave corner cannot be reached by the tool without gouging");
        CHECK(e.line() == 8);
    }
    CHECK_THROWS_WITH(run_text("G21 G0 X0 Y0\nG41.1 D10\nG1 X3 F100\nM2\n"),
                      "Length of cutter compensation entry move is not greater than the tool radius");
    CHECK_THROWS_WITH(run_text("G21 G0 X0 Y0\nG41.1 D2\nG1 X10 F100\nG40\nG2 X0 Y0 R5\nM2\n"),
                      "The move just after exiting cutter compensation mode must be straight, not an arc");
    CHECK_THROWS_WITH(run_text("G21 G0 X0 Y0\nG41.1 D10\nG1 X20 F100\nG3 X24 Y0 R2\nM2\n"),
                      "Tool radius not less than arc radius with comp");
}

TEST_CASE("Inside corners with arcs: arc to line and arc to arc meet where the equidistants cross") {
    // Left compensation r = 1 around G3 (10,0) -> (0,10) about the origin (tool inside, radius 9).
    // Then a line to (-10,0): a 45 degree left turn. Its equidistant (through (0.7071, 9.2929),
    // direction (-1,-1)/sqrt 2) meets the circle of radius 9 at (0.405092, 8.990879).
    auto al = run_text("G21 G0 X10 Y-5\nG41.1 D2\nG1 X10 Y0 F100\nG3 X0 Y10 R10\nG1 X-10 Y0\nG40 G0 X-20 Y0\nM2\n");
    check_path(al.path, 1,
               {{1, 9, 0},                      // entry, tangent to the arc
                {3, 0.405092, 8.990879, 0, 0},  // the arc, pulled back
                {1, -10 + 0.707107, -0.707107},  // the line's equidistant to its end
                {0, -20, 0}});
    // Arc to arc: then G2 about (-10,10) (a 90 degree left turn; tool outside, radius 11).
    // Circles r 9 about (0,0) and r 11 about (-10,10): x = 80/sqrt 200, h = 7, nearest the
    // corner (0.949747, 8.949747).
    auto aa = run_text("G21 G0 X10 Y-5\nG41.1 D2\nG1 X10 Y0 F100\nG3 X0 Y10 R10\nG2 X-10 Y0 I-10 J0\nG40 G0 X-20 Y0\nM2\n");
    check_path(aa.path, 1, {{1, 9, 0}, {3, 0.949747, 8.949747, 0, 0}, {2, -10, -1, -10, 10}, {0, -20, 0}});
}
