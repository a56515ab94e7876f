// Heidenhain APPR / DEP that do not change radius compensation (spec §2.5.1): connecting
// elements computed on the contour and compensated with the active RL/RR, which stays on.
// Expected numbers are worked by hand in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "heidenhain_helpers.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;
using namespace tctest::hh;

namespace {

constexpr auto kArcCcw = static_cast<std::uint8_t>(MotionKind::arc_ccw);

}  // namespace

TEST_CASE("heidenhain APPR CT with compensation on: a tangential arc, compensated", "[heidenhain][approach]") {
    // r = 2, RL. The contour runs along y = 5 to PS = (20,5). APPR CT X+40 Y+10 CCA90 R+5
    // without RL/RR: first element L X+40 Y+30 (t_A = +Y), n_s = left normal = (-1,0), centre
    // C = PA + 5 n_s = (35,10), arc direction RL & R > 0 = CCW, PH = PA rotated 90° CW about
    // C = (35,5). On the contour: PS -> PH straight (on y = 5), PH -> PA a CCW arc about
    // (35,10). Compensated (tool 2 left): (20,7) -> (35,7), arc about (35,10) of radius 3 to
    // (38,10), then x = 38 up to (38,30); every joint is tangent.
    const Result r = run_h(
        "TOOL DEF 1 L+0 R+2\nTOOL CALL 1 Z\nL X+0 Y-10 Z+0 R0 F100\nL X+0 Y+5 RL\nL X+20 Y+5\n"
        "APPR CT X+40 Y+10 CCA90 R+5\nL X+40 Y+30\nL X+60 Y+30\nL X+60 Y+50 R0\n");
    // The programmed contour of the APPR block.
    const auto nom = of_line(r.nominal, 7);
    REQUIRE(nom.size() == 2);
    CHECK_XY(col(r.nominal.starts(), nom[0]), 20, 5);
    CHECK_XY(col(r.nominal.end, nom[0]), 35, 5);
    CHECK(r.nominal.kind[nom[1]] == kArcCcw);
    CHECK_XY(col(r.nominal.centers(), nom[1]), 35, 10);
    CHECK_XY(col(r.nominal.end, nom[1]), 40, 10);
    // The tool path.
    const Path& p = r.path;
    const auto appr = of_line(p, 7), next = of_line(p, 8);
    REQUIRE(appr.size() == 2);
    REQUIRE(next.size() == 1);
    CHECK_XY(col(p.starts(), appr[0]), 20, 7);
    CHECK_XY(col(p.end, appr[0]), 35, 7);
    CHECK(p.kind[appr[1]] == kArcCcw);
    CHECK_XY(col(p.centers(), appr[1]), 35, 10);
    CHECK_XY(col(p.end, appr[1]), 38, 10);
    CHECK_XY(col(p.end, next[0]), 38, 30);
    for (std::size_t i : {appr[0], appr[1], next[0]}) CHECK(p.side[i] == 1);  // compensation stays on
    // Tangent joints up to the first element: no transition arc inserted (the first one is
    // at the outside corner (40,30) of the next block).
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.line[i] <= 8) CHECK_FALSE(p.generated[i]);
}

TEST_CASE("heidenhain APPR LT with compensation on: corners of the connecting lines", "[heidenhain][approach]") {
    // r = 5, RL, contour along y = 0 to PS = (20,0). APPR LT X+40 Y+10 LEN5, first element
    // heading +Y: PH = PA - 5·(0,1) = (40,5). Contour PS -> PH -> PA, all left turns (inside
    // corners for RL): at PS the tool meets y = 5 and the left equidistant of PS -> PH,
    // -5(x - 20) + 20y = 5√425, at x = 40 - √425; at PH that equidistant meets x = 35 at
    // y = 3.75 + √425/4. Then x = 35 up to (35,30).
    const Result r = run_h(
        "TOOL DEF 1 L+0 R+5\nTOOL CALL 1 Z\nL X+0 Y-20 Z+0 R0 F100\nL X+0 Y+0 RL\nL X+20 Y+0\n"
        "APPR LT X+40 Y+10 LEN5\nL X+40 Y+30\nL X+60 Y+50 R0\n");
    const double s = std::sqrt(425.0);
    const auto nom = of_line(r.nominal, 7);
    REQUIRE(nom.size() == 2);
    CHECK_XY(col(r.nominal.end, nom[0]), 40, 5);  // PH on the contour
    CHECK_XY(col(r.nominal.end, nom[1]), 40, 10);
    const Path& p = r.path;
    const auto before = of_line(p, 6), appr = of_line(p, 7), next = of_line(p, 8);
    REQUIRE(before.size() == 1);
    REQUIRE(appr.size() == 2);
    REQUIRE(next.size() == 1);
    CHECK_XY(col(p.end, before[0]), 40 - s, 5);
    CHECK_XY(col(p.end, appr[0]), 35, 3.75 + s / 4);
    CHECK_XY(col(p.end, appr[1]), 35, 10);
    CHECK_XY(col(p.end, next[0]), 35, 30);
    for (std::size_t i : {appr[0], appr[1], next[0]}) CHECK(p.side[i] == 1);
}

TEST_CASE("heidenhain APPR LN with compensation on: PH on the contour normal", "[heidenhain][approach]") {
    // RR, r = 0 (the contour itself): APPR LN X+10 Y+20 LEN+15 with the first element
    // L X+20 Y+35 (t_A = (10,15)/√325): n_s = right normal = (15,-10)/√325 and, on the
    // contour, PH = PA + 15 n_s = (10 + 225/√325, 20 - 150/√325).
    const Result r = run_h(
        "TOOL DEF 1 L+0 R+0\nTOOL CALL 1 Z\nL X+40 Y+0 Z+0 R0 F100\nL X+40 Y+10 RR\n"
        "APPR LN X+10 Y+20 LEN+15\nL X+20 Y+35\nL X+40 Y+40 R0\n");
    const double q = std::sqrt(325.0);
    const auto appr = of_line(r.path, 6);
    REQUIRE(appr.size() == 2);
    CHECK_XY(col(r.path.starts(), appr[0]), 40, 10);
    CHECK_XY(col(r.path.end, appr[0]), 10 + 225 / q, 20 - 150 / q);
    CHECK_XY(col(r.path.end, appr[1]), 10, 20);
    CHECK(r.path.side[appr[0]] == -1);
}

TEST_CASE("heidenhain DEP with RL/RR programmed again keeps compensation on", "[heidenhain][departure]") {
    // r = 2, RL, last element L X+40 Y+30 heading +Y (tool on x = 38).
    SECTION("DEP LT") {
        // On the contour PE = (40,30) -> PN = PE + 10·(0,1) = (40,40), compensated: x = 38.
        // The next element L X+20 Y+40 heads -X: a left turn, an inside corner for RL, the
        // tool meets y = 38 at (38,38).
        const Result r = run_h(
            "TOOL DEF 1 L+0 R+2\nTOOL CALL 1 Z\nL X+40 Y-10 Z+0 R0 F100\nL X+40 Y+0 RL\nL X+40 Y+30\n"
            "DEP LT LEN10 RL\nL X+20 Y+40\nL X+20 Y+60 R0\n");
        const auto nom = of_line(r.nominal, 7);
        REQUIRE(nom.size() == 1);
        CHECK_XY(col(r.nominal.end, nom[0]), 40, 40);
        const auto dep = of_line(r.path, 7), next = of_line(r.path, 8);
        REQUIRE(dep.size() == 1);
        REQUIRE(next.size() == 1);
        CHECK_XY(col(r.path.starts(), dep[0]), 38, 30);
        CHECK_XY(col(r.path.end, dep[0]), 38, 38);
        CHECK_XY(col(r.path.end, next[0]), 20, 38);
        CHECK(r.path.side[dep[0]] == 1);
        CHECK(r.path.side[next[0]] == 1);
    }
    SECTION("DEP CT") {
        // DEP CT CCA90 R+5 RL: centre C = PE + 5·(-1,0) = (35,30), CCW (RL, R > 0), PN = PE
        // turned 90° CCW about C = (35,35). The tool arc has radius 5 - 2 = 3: (38,30) ->
        // (35,33). The next element L X+20 Y+35 continues tangentially (-X) on y = 33.
        const Result r = run_h(
            "TOOL DEF 1 L+0 R+2\nTOOL CALL 1 Z\nL X+40 Y-10 Z+0 R0 F100\nL X+40 Y+0 RL\nL X+40 Y+30\n"
            "DEP CT CCA90 R+5 RL\nL X+20 Y+35\nL X+20 Y+60 R0\n");
        const auto dep = of_line(r.path, 7), next = of_line(r.path, 8);
        REQUIRE(dep.size() == 1);
        REQUIRE(next.size() == 1);
        CHECK(r.path.kind[dep[0]] == kArcCcw);
        CHECK_XY(col(r.path.starts(), dep[0]), 38, 30);
        CHECK_XY(col(r.path.centers(), dep[0]), 35, 30);
        CHECK_XY(col(r.path.end, dep[0]), 35, 33);
        CHECK_XY(col(r.path.end, next[0]), 20, 33);
        CHECK(r.path.side[dep[0]] == 1);
        for (std::size_t i = 0; i < r.path.size(); ++i) CHECK_FALSE(r.path.generated[i]);
    }
    SECTION("DEP without RL/RR still cancels compensation") {
        const Result r = run_h(
            "TOOL DEF 1 L+0 R+2\nTOOL CALL 1 Z\nL X+40 Y-10 Z+0 R0 F100\nL X+40 Y+0 RL\nL X+40 Y+30\n"
            "DEP LT LEN10\n");
        const auto dep = of_line(r.path, 7);
        REQUIRE(dep.size() == 1);
        CHECK_XY(col(r.path.end, dep[0]), 38, 40);  // PE_tool + LEN·t_E
        CHECK(r.path.side[dep[0]] == 0);
    }
}

TEST_CASE("heidenhain APPR/DEP with compensation on: errors", "[heidenhain][approach]") {
    std::string msg;
    int line = 0;
    const std::string head = "TOOL DEF 1 L+0 R+2\nTOOL CALL 1 Z\nL X+0 Y-10 Z+0 R0 F100\nL X+0 Y+5 RL\nL X+20 Y+5\n";
    // RL active, RR in the APPR block: a side change without R0.
    CHECK(error_of(head + "APPR LT X+40 Y+10 LEN5 RR\nL X+40 Y+30\n", &msg, &line) == "comp_side_change");
    CHECK(line == 7);
    CHECK(error_of(head + "APPR LT X+40 Y+10 LEN5 R0\nL X+40 Y+30\n", &msg, &line) == "appr_cancels_comp");
    CHECK(line == 7);
    CHECK(error_of(head + "DEP LT LEN5 RR\n", &msg, &line) == "comp_side_change");
    CHECK(line == 7);
    // DEP cannot switch compensation on.
    CHECK(error_of("TOOL DEF 1 L+0 R+2\nTOOL CALL 1 Z\nL X+0 Y-10 Z+0 R0 F100\nL X+0 Y+5\nDEP LT LEN5 RL\n", &msg,
                   &line) == "dep_starts_comp");
    CHECK(line == 6);
    // The connecting CT arc with the tool inside: R 5 with r = 6 does not fit.
    CHECK(error_of("TOOL DEF 1 L+0 R+6\nTOOL CALL 1 Z\nL X+0 Y-10 Z+0 R0 F100\nL X+0 Y+5 RL\nL X+20 Y+5\n"
                   "APPR CT X+40 Y+10 CCA90 R+5\nL X+40 Y+30\nL X+60 Y+30 R0\n",
                   &msg) != "");
    CHECK(msg == "TOOL RADIUS TOO LARGE");
}
