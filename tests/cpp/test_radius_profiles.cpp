// Radius compensation by profile: start-up type A (perpendicular to the next element),
// intersections at outside corners with a corner limit (Sinumerik G451 style), extension
// blocks at acute outside corners (Fanuc). Numbers: spec §1.4, §1.6.1 and hand calculation.
#include <catch2/catch.hpp>
#include <cmath>

#include "run_helpers.hpp"

using namespace toolcomp;
using tctest::end_of;

namespace {
Result run_with(const std::string& text, const ControlProfile& prof, Dialect d = Dialect::linuxcnc) {
    RunOptions o;
    o.profile = prof;
    return run(parse_program(text, d), nullptr, o);
}
void check_xy(const Path& p, std::size_t i, double x, double y) {
    INFO("segment " << i);
    REQUIRE(i < p.size());
    CHECK(end_of(p, i).x() == Approx(x).margin(1e-6));
    CHECK(end_of(p, i).y() == Approx(y).margin(1e-6));
}
}  // namespace

TEST_CASE("Fanuc start-up type A: the activation block ends perpendicular to the next element") {
    // spec 1.6.1: S = (-10,-10), G41 G01 X0 Y0, next X50 Y0, r = 5 -> (0,5) -> (50,5).
    auto r = run_with("G21 G0 X-10 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nG40 G0 X60 Y-10\nM30\n",
                      profile_for(Dialect::fanuc));
    REQUIRE(r.path.size() == 4);
    check_xy(r.path, 1, 0, 5);
    check_xy(r.path, 2, 50, 5);
    check_xy(r.path, 3, 60, -10);
}

TEST_CASE("Fanuc outside corners: intersection when obtuse, extension blocks when acute") {
    const ControlProfile fanuc = profile_for(Dialect::fanuc);
    // A(0,0) -> B(50,0) -> C(80,-20): a right turn of 33.7 degrees, outside for G41.
    // Intersection of y = 5 with BC's equidistant: x = 50 + 5 tan(16.845 deg) = 51.5139.
    auto obtuse = run_with("G21 G0 X-10 Y5\nG41.1 D10\nG1 X0 Y0 F100\nX50\nX80 Y-20\nG40 G0 X90 Y-30\nM30\n", fanuc);
    check_xy(obtuse.path, 2, 51.513878, 5.0);
    // A(0,0) -> B(50,0) -> C(0,-20): a right turn of 158.2 degrees. Extend AB' by r to
    // (55,5), BC' backwards by r from M = (51.857, -4.642) to (56.499, -2.785), join.
    auto acute = run_with("G21 G0 X-10 Y5\nG41.1 D10\nG1 X0 Y0 F100\nX50\nX0 Y-20\nG40 G0 X-10 Y-30\nM30\n", fanuc);
    const Path& p = acute.path;
    REQUIRE(p.size() == 8);
    check_xy(p, 2, 50, 5);
    check_xy(p, 3, 55, 5);
    check_xy(p, 4, 56.499337, -2.785430);
    check_xy(p, 5, 51.856953, -4.642383);
    CHECK(p.generated[3]);
    CHECK(p.generated[4]);
    CHECK(p.generated[5]);
    CHECK(p.kind[4] == 1);
}

TEST_CASE("Intersection style with a corner limit (Sinumerik G451 style) on the L-shape") {
    ControlProfile g451 = profile_for(Dialect::linuxcnc);
    g451.radius.outside_corner = OutsideCorner::intersection;
    g451.radius.corner_limit = 100 * kPi / 180;
    // spec 1.4: joint C of A(0,0) B(50,0) C(50,30) D(80,30) with G41 r = 5 meets at (45,35).
    auto r = run_with("G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nY30\nX80\nG40 G0 X90 Y40\nM2\n", g451);
    const Path& p = r.path;
    bool found = false;
    for (std::size_t i = 0; i < p.size(); ++i)
        if ((end_of(p, i) - Vec3(45, 35, 0)).norm() < 1e-9) found = true;
    CHECK(found);
    for (std::size_t i = 0; i < p.size(); ++i) CHECK_FALSE(p.generated[i]);  // nothing inserted
    // A sharper corner than the limit falls back to the transition arc.
    auto sharp = run_with("G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nX0 Y-20\nG40 G0 X-10 Y-30\nM2\n", g451);
    bool arc = false;
    for (std::size_t i = 0; i < sharp.path.size(); ++i) arc = arc || (sharp.path.generated[i] && sharp.path.kind[i] == 2);
    CHECK(arc);
}

TEST_CASE("Planes: Fanuc compensates in G19, LinuxCNC refuses; Fanuc refuses an arc start-up") {
    auto yz = run_with("G21 G19 G0 Y-10 Z0\nG41.1 D10\nG1 Y0 Z0 F100\nZ50\nG40 G0 Y-10 Z60\nM30\n",
                       profile_for(Dialect::fanuc));
    // G19: (a, b) = (Y, Z); moving +Z along Y = 0 with the tool on the left (seen from +X):
    // left of +b is -a, so the tool centre runs at Y = -5.
    CHECK(end_of(yz.path, 2).y() == Approx(-5));
    CHECK(end_of(yz.path, 2).z() == Approx(50));
    CHECK_THROWS_WITH(run_with("G21 G19 G41.1 D10\nM2\n", profile_for(Dialect::linuxcnc)),
                      "Cutter radius compensation allowed only in XY, XZ planes");
    CHECK_THROWS_WITH(run_with("G21 G0 X-10\nG41.1 D10\nG3 X10 Y0 R10 F100\nM30\n", profile_for(Dialect::fanuc)),
                      "PS0034 NO CIRC ALLOWED IN ST-UP/EXT BLK");
}

TEST_CASE("Blocks without plane motion: limit and reaction by profile") {
    // Inside corner at (20,0) with three Z moves between: LinuxCNC looks past them all.
    const std::string text =
        "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX20\nZ-1\nZ-2\nZ-3\nY20\nG40 G0 X-10 Y30\nM30\n";
    auto lcnc = run_with(text, profile_for(Dialect::linuxcnc));
    // The inside corner is reached: the move along y = 5 ends at x = 15 (pulled back).
    bool pulled = false;
    for (std::size_t i = 0; i < lcnc.path.size(); ++i) pulled = pulled || (end_of(lcnc.path, i) - Vec3(15, 5, 0)).norm() < 1e-9;
    CHECK(pulled);
    // Fanuc looks past two: the third ends the move perpendicular at (20,5) and warns.
    ControlProfile f = profile_for(Dialect::fanuc);
    f.radius.entry = EntryStyle::perpendicular_to_entry;
    auto fanuc = run_with(text, f);
    bool perpendicular = false;
    for (std::size_t i = 0; i < fanuc.path.size(); ++i)
        perpendicular = perpendicular || (end_of(fanuc.path, i) - Vec3(20, 5, 0)).norm() < 1e-9;
    CHECK(perpendicular);
    // The warning of the look-ahead limit, then the overcut watch's: the perpendicular end
    // (20,5) lies on the contour of line 8 (x = 20), 5 mm into the part.
    REQUIRE(fanuc.diagnostics.size() >= 2);
    CHECK(fanuc.diagnostics[0].code == "comp_overcut");
    CHECK(fanuc.diagnostics[0].pos.line == 7);
    CHECK(fanuc.diagnostics[1].code == "comp_overcut");
    CHECK(fanuc.diagnostics[1].message.find("0.000000 mm from the programmed contour of line 8") != std::string::npos);
    f.radius.non_plane_reaction = NonPlaneReaction::error;
    CHECK_THROWS_WITH(run_with(text, f), "Too many blocks without motion in the compensation plane");
}

TEST_CASE("An unreachable step: error, skip with look-ahead, or report") {
    // y = 0 to x = 30, a 2 mm step down, on along y = -2; tool radius 5 on the left (above).
    // The step's equidistant would run upwards: the tool cannot reach it.
    const std::string text =
        "G21 G0 X-10 Y5\nG41.1 D10\nG1 X0 Y0 F100\nX30\nY-2\nX60\nG40 G0 X70 Y10\nM2\n";
    ControlProfile p = profile_for(Dialect::linuxcnc);
    CHECK_THROWS_WITH(run_with(text, p), "Straight feed in concave corner cannot be reached by the tool without gouging");
    // Skip: the tool leaves the step out and meets y = -2 + 5 = 3 on the corner arc about
    // (30,0): x = 30 + sqrt(25 - 9) = 34.
    p.radius.gouge = GougeReaction::skip;
    p.radius.lookahead = 3;
    auto skip = run_with(text, p);
    const Path& s = skip.path;
    bool met = false, step_left = true;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if ((end_of(s, i) - Vec3(34, 3, 0)).norm() < 1e-9) met = true;
        if (s.line[i] == 5 && !s.generated[i]) step_left = false;
    }
    CHECK(met);
    CHECK(step_left);
    REQUIRE(skip.diagnostics.size() == 1);
    CHECK(skip.diagnostics[0].code == "comp_skipped");
    CHECK(skip.diagnostics[0].message.find("line(s) 5") != std::string::npos);
    CHECK(skip.diagnostics[0].pos.line == 6);
    // A look-ahead of one move cannot see past the step: the control stops.
    p.radius.lookahead = 1;
    CHECK_THROWS(run_with(text, p));
    // Report: the path is kept as computed (the step runs backwards) with a warning.
    p.radius.gouge = GougeReaction::report;
    auto rep = run_with(text, p);
    // The reaction's warning, then the overcut watch's: the corner arc about (30,0) and the
    // reversed step both reach (35,0), 2 mm from line 6's contour y = -2 (r = 5).
    REQUIRE(rep.diagnostics.size() >= 2);
    CHECK(rep.diagnostics[0].code == "comp_gouge");
    for (std::size_t i = 1; i < rep.diagnostics.size(); ++i) {
        CHECK(rep.diagnostics[i].code == "comp_overcut");
        CHECK(rep.diagnostics[i].message.find("2.000000 mm from the programmed contour of line 6") != std::string::npos);
    }
    CHECK(rep.diagnostics[0].message.find("line 5") != std::string::npos);
    bool reversed = false;
    for (std::size_t i = 0; i < rep.path.size(); ++i)
        if (rep.path.line[i] == 5 && !rep.path.generated[i]) reversed = end_of(rep.path, i).y() > rep.path.starts()[3 * i + 1];
    CHECK(reversed);
}

TEST_CASE("Side change without G40: refused by LinuxCNC, a perpendicular link where allowed") {
    const std::string text = "G21 G0 X-10 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nG42.1 D10\nX100\nG40 G0 X110 Y-10\nM30\n";
    CHECK_THROWS_WITH(run_with(text, profile_for(Dialect::linuxcnc)), "Cannot turn cutter radius comp on when on");
    ControlProfile f = profile_for(Dialect::fanuc);
    auto r = run_with(text, f);
    const Path& p = r.path;
    // Left of the first line at y = 5 up to (50,5); then a link straight down to the right
    // side's start (50,-5); along y = -5 to (100,-5).
    bool at_left_end = false, linked = false, right_end = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if ((end_of(p, i) - Vec3(50, 5, 0)).norm() < 1e-9) at_left_end = true;
        if ((end_of(p, i) - Vec3(50, -5, 0)).norm() < 1e-9 && p.generated[i]) linked = true;
        if ((end_of(p, i) - Vec3(100, -5, 0)).norm() < 1e-9 && p.side[i] == -1) right_end = true;
    }
    CHECK(at_left_end);
    CHECK(linked);
    CHECK(right_end);
}

TEST_CASE("DISC distorts the transition arc from the arc (0) to the intersection (100)") {
    // L-shape joint C of spec 1.4: equidistants x = 45 and y = 35 meet at V = (45,35); the
    // transition arc runs (45,30) -> (50,35) about (50,30). DISC 50: fillet of radius 2.5
    // from (45,32.5) to (47.5,35) about (47.5,32.5).
    const std::string text = "G21 G0 X0 Y-10\nG41.1 D10\nG1 X0 Y0 F100\nX50\nY30\nX80\nG40 G0 X90 Y40\nM2\n";
    auto find = [](const Path& p, Vec3 pt) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if ((end_of(p, i) - pt).norm() < 1e-9) return static_cast<int>(i);
        return -1;
    };
    ControlProfile p = profile_for(Dialect::linuxcnc);
    p.radius.disc = 50;
    auto r = run_with(text, p);
    int a = find(r.path, Vec3(45, 32.5, 0)), b = find(r.path, Vec3(47.5, 35, 0));
    REQUIRE(a >= 0);
    REQUIRE(b == a + 1);
    CHECK(r.path.kind[b] == 2);
    CHECK(r.path.centers()[3 * b] == Approx(47.5));
    CHECK(r.path.centers()[3 * b + 1] == Approx(32.5));
    p.radius.disc = 100;
    auto sharp = run_with(text, p);
    CHECK(find(sharp.path, Vec3(45, 35, 0)) >= 0);
}

TEST_CASE("Exit: perpendicular to the last move, or joined to the cancel move (type B)") {
    // y = 0 to (50,0) with G41 r = 5, then G40 G1 X60 Y-10 (a 45 degree right turn).
    const std::string text = "G21 G0 X-10 Y5\nG41.1 D10\nG1 X0 Y0 F100\nX50\nG40 X60 Y-10\nM2\n";
    auto find = [](const Path& p, Vec3 pt) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if ((end_of(p, i) - pt).norm() < 1e-6) return static_cast<int>(i);
        return -1;
    };
    auto a = run_with(text, profile_for(Dialect::linuxcnc));
    CHECK(find(a.path, Vec3(50, 5, 0)) == static_cast<int>(a.path.size()) - 2);  // then straight out
    // Type B with intersections: y = 5 meets the cancel move's equidistant (through
    // (53.536, 3.536), direction (1,-1)) at x = 50 + 5 tan(22.5 deg) = 52.071.
    ControlProfile b = profile_for(Dialect::fanuc);
    b.radius.entry = EntryStyle::perpendicular_to_entry;
    b.radius.exit = ExitStyle::corner_with_exit;
    auto r = run_with(text, b);
    const int k = find(r.path, Vec3(50 + 5 * std::tan(kPi / 8), 5, 0));
    REQUIRE(k >= 0);
    CHECK(end_of(r.path, k + 1).isApprox(Vec3(60, -10, 0)));
    CHECK(static_cast<std::size_t>(k + 2) == r.path.size());
    // Type B with the transition arc: the arc about (50,0) to (53.536, 3.536), then out.
    ControlProfile arc = profile_for(Dialect::linuxcnc);
    arc.radius.exit = ExitStyle::corner_with_exit;
    auto s = run_with(text, arc);
    const int j = find(s.path, Vec3(50 + 5 / std::sqrt(2.0), 5 / std::sqrt(2.0), 0));
    REQUIRE(j >= 0);
    CHECK(s.path.kind[j] == 2);
    CHECK(end_of(s.path, j + 1).isApprox(Vec3(60, -10, 0)));
}

TEST_CASE("An inside arc smaller than the tool: error, or left out with the skip reaction") {
    // A 2 mm radius notch (G3, tool inside) in a straight edge, tool radius 5 on the left.
    const std::string text =
        "G21 G0 X-10 Y5\nG41.1 D10\nG1 X0 Y0 F100\nX20\nG3 X24 Y0 R2\nG1 X50\nG40 G0 X60 Y10\nM2\n";
    ControlProfile p = profile_for(Dialect::linuxcnc);
    CHECK_THROWS_WITH(run_with(text, p), "Tool radius not less than arc radius with comp");
    p.radius.gouge = GougeReaction::skip;
    p.radius.lookahead = 2;
    auto r = run_with(text, p);
    // Both lines run at y = 5: the tool passes straight over the notch.
    for (std::size_t i = 1; i + 1 < r.path.size(); ++i) CHECK(end_of(r.path, i).y() == Approx(5));
    for (std::size_t i = 0; i < r.path.size(); ++i) CHECK(r.path.line[i] != 5);
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics[0].message.find("line(s) 5") != std::string::npos);
}
