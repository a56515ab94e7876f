// Sinumerik 840D tool lengths: $TC_DP totals, L1/L2/L3 mapping, the $TC_DP file form and
// GETTCOR (spec §3.1, §3.2, §3.5).
#include <catch2/catch.hpp>

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/tools/sinumerik_edge.hpp"
#include "toolcomp/tools/sinumerik_gettcor.hpp"

using namespace toolcomp;
using namespace toolcomp::sinumerik;

namespace {

bool near(const Vec3& a, const Vec3& b) { return (a - b).norm() < 1e-9; }

SinumerikEdge milling_example() {  // spec §3.2 worked example, T1 D1
    SinumerikEdge e;
    e.DP(1) = 120;
    e.DP(3) = 120.0;
    e.DP(12) = -0.15;
    e.DP(21) = 10.0;
    e.DP(6) = 6.0;
    e.DP(15) = -0.02;
    return e;
}

}  // namespace

TEST_CASE("sinumerik: spec 3.2 worked example, milling tool", "[sinumerik]") {
    const SinumerikEdge e = milling_example();
    CHECK(e.length(1) == Approx(129.85));
    CHECK(e.radius() == Approx(5.98));
    CHECK(e.radius(1.0, 0.5) == Approx(6.48));  // OFFN allowance
    CHECK(near(tool_length_vector(e, Plane::xy), Vec3(0, 0, 129.85)));  // G17: Z
    CHECK(near(tool_length_vector(e, Plane::zx), Vec3(0, 129.85, 0)));  // G18: Y
    CHECK(near(tool_length_vector(e, Plane::yz), Vec3(129.85, 0, 0)));  // G19: X
    // SD42930 WEAR_SIGN inverts the wear: 120 + 0.15 + 10, 6 + 0.02.
    SinumerikLengthSettings inv;
    inv.wear_sign_inverted = true;
    CHECK(tool_length_vector(e, Plane::xy, inv).z() == Approx(130.15));
    CHECK(e.radius(inv.wear_sign()) == Approx(6.02));
    CHECK_THROWS_AS(e.length(4), ToolTableError);
    CHECK_THROWS_AS(e.DP(26), ToolTableError);
}

TEST_CASE("sinumerik: spec 3.2 worked example, turning tool G18", "[sinumerik]") {
    SinumerikEdge e;
    e.DP(1) = 500;
    e.DP(3) = 50;
    e.DP(4) = 100;
    e.DP(13) = 0.1;
    CHECK(near(tool_length_vector(e, Plane::zx), Vec3(50, 0, 100.1)));  // X 50, Z 100.1
}

TEST_CASE("sinumerik: L1/L2/L3 axis tables and SD42940/SD42950", "[sinumerik]") {
    using A = std::array<int, 3>;
    const int X = 0, Y = 1, Z = 2;
    // Milling (and types < 400, > 599): G17 Z Y X, G18 Y X Z, G19 X Z Y.
    for (int type : {120, 200, 710, 0}) {
        CHECK(length_axes(type, Plane::xy) == A{Z, Y, X});
        CHECK(length_axes(type, Plane::zx) == A{Y, X, Z});
        CHECK(length_axes(type, Plane::yz) == A{X, Z, Y});
    }
    // Turning and grinding (400..599): G17 Y X Z, G18 X Z Y, G19 Z Y X.
    for (int type : {400, 500, 599}) {
        CHECK(length_axes(type, Plane::xy) == A{Y, X, Z});
        CHECK(length_axes(type, Plane::zx) == A{X, Z, Y});
        CHECK(length_axes(type, Plane::yz) == A{Z, Y, X});
    }
    // TOOL_LENGTH_CONST = 18 freezes the G18 assignment in every plane.
    SinumerikLengthSettings c18;
    c18.tool_length_const = 18;
    for (Plane p : {Plane::xy, Plane::zx, Plane::yz}) {
        CHECK(length_axes(120, p, c18) == A{Y, X, Z});
        CHECK(length_axes(500, p, c18) == A{X, Z, Y});
    }
    // Negative values: turning -17 X Y Z, -18 Z X Y, -19 Y Z X;
    //                  milling -17 Z X Y, -18 Y Z X, -19 X Y Z.
    struct Row {
        int c;
        A turning, milling;
    };
    const Row rows[] = {{-17, {X, Y, Z}, {Z, X, Y}}, {-18, {Z, X, Y}, {Y, Z, X}}, {-19, {Y, Z, X}, {X, Y, Z}}};
    for (const Row& r : rows) {
        INFO("TOOL_LENGTH_CONST " << r.c);
        SinumerikLengthSettings s;
        s.tool_length_const = r.c;
        CHECK(length_axes(500, Plane::xy, s) == r.turning);
        CHECK(length_axes(120, Plane::yz, s) == r.milling);
    }
    // TOOL_LENGTH_TYPE: 1 always milling, 2 always turning.
    SinumerikLengthSettings t1, t2;
    t1.tool_length_type = 1;
    t2.tool_length_type = 2;
    CHECK(length_axes(500, Plane::zx, t1) == A{Y, X, Z});
    CHECK(length_axes(120, Plane::zx, t2) == A{X, Z, Y});
    SinumerikLengthSettings bad;
    bad.tool_length_const = 20;
    CHECK_THROWS_AS(length_axes(120, Plane::xy, bad), ToolTableError);
    bad = {};
    bad.tool_length_type = 3;
    CHECK_THROWS_AS(length_axes(120, Plane::xy, bad), ToolTableError);
}

TEST_CASE("sinumerik: $TC_DP file form is read and written back", "[sinumerik]") {
    const char* text =
        "; tool data T1 D1\r\n"
        "N10 $TC_DP1[1,1]=120\r\n"
        "\r\n"
        "$TC_DP3[1,1]=120.0   ; geometry length 1\n"
        "$tc_dp12[1,1] = -0.15\n"
        "N20$TC_DP21[ 1 , 1 ]=10\n"
        "$TC_DP6[1,1]=6\n"
        "$TC_DP15[1,1]=-.02\n"
        "$TC_SCP13[1,1]=0.5\n"
        "$TC_DP1[2,3]=500\n"
        "M17\n";
    const SinumerikEdgeMap m = parse_tc_dp(text);
    REQUIRE(m.size() == 2);
    const SinumerikEdge& e = m.at({1, 1});
    CHECK(e.dp == milling_example().dp);
    CHECK(e.SCP(13) == 0.5);
    CHECK(m.at({2, 3}).type() == 500);
    const std::string out = write_tc_dp(m);
    CHECK(out.find("$TC_DP12[1,1]=-0.15\n") != std::string::npos);
    CHECK(parse_tc_dp(out) == m);
}

TEST_CASE("sinumerik: $TC_DP file errors carry code and line", "[sinumerik]") {
    struct Bad {
        const char* text;
        const char* code;
        int line;
    };
    const Bad cases[] = {
        {"$TC_DP1[1,1]=1\n$TC_DP3[1,1]=abc\n", "sinumerik_bad_line", 2},
        {"$TC_DP3[1,1]\n", "sinumerik_bad_line", 1},
        {"\n\n$TC_XX3[1,1]=1\n", "sinumerik_bad_line", 3},
        {"$TC_DP3[1 1]=1\n", "sinumerik_bad_line", 1},
        {"$TC_DP3[1,1]=1 2\n", "sinumerik_bad_line", 1},
        {"$TC_DP26[1,1]=1\n", "sinumerik_bad_dp", 1},
        {"; x\n$TC_DP0[1,1]=1\n", "sinumerik_bad_dp", 2},
        {"$TC_DP3[0,1]=1\n", "sinumerik_bad_tool", 1},
        {"$TC_DP3[1,32001]=1\n", "sinumerik_bad_edge", 1},
    };
    for (const Bad& b : cases) {
        INFO(b.text);
        try {
            parse_tc_dp(b.text);
            FAIL("no error");
        } catch (const ToolTableError& err) {
            CHECK(err.code() == b.code);
            CHECK(err.line() == b.line);
        }
    }
    try {
        parse_tc_dp("$TC_DP3[1,10]=1", 99, 9);  // custom D limit
        FAIL("no error");
    } catch (const ToolTableError& err) {
        CHECK(err.code() == "sinumerik_bad_edge");
        CHECK(err.column() == 11);  // the "10" of [1,10]
    }
}

TEST_CASE("sinumerik: GETTCOR reproduces the W1 manual example", "[sinumerik]") {
    // Settings that give the manual's numbers: a turning tool (type 500), plane G18,
    // MD20360 TOOL_PARAMETER_DEF_MASK = 3 (geometry and wear of the transverse axis X given
    // as diameters), DP3=3 DP4=4 DP5=5 (geometry), DP12=12 DP13=13 DP14=14 (wear), no adapter.
    // Turning G18 maps L1->X, L2->Z, L3->Y; G18 abscissa Z, ordinate X, applicate Y:
    //   _LEN[2] = Z = 4 + 13 = 17, _LEN[3] = X = 0.5*3 + 0.5*12 = 7.5, _LEN[4] = Y = 5 + 14 = 19.
    SinumerikEdge e;
    e.DP(1) = 500;
    e.DP(2) = 3;
    e.DP(3) = 3, e.DP(4) = 4, e.DP(5) = 5;
    e.DP(12) = 12, e.DP(13) = 13, e.DP(14) = 14;
    GettcorSettings s;
    s.plane = Plane::zx;
    s.set_parameter_def_mask(3);
    std::array<double, 11> len{};
    REQUIRE(gettcor(len, "GW", e, s) == gettcor_ok);
    CHECK(len[0] == 500);
    CHECK(len[1] == 3);
    CHECK(len[2] == Approx(17.0));
    CHECK(len[3] == Approx(7.5));
    CHECK(len[4] == Approx(19.0));
    // Case, blanks and an explicit coordinate system do not change anything here.
    std::array<double, 11> len2{};
    REQUIRE(gettcor(len2, " g w : m ", e, s) == gettcor_ok);
    CHECK(len2 == len);
    // Without the diameter setting X is 3 + 12.
    GettcorSettings radius_x;
    radius_x.plane = Plane::zx;
    REQUIRE(gettcor(len, "GW", e, radius_x) == gettcor_ok);
    CHECK(len[3] == Approx(15.0));
}

TEST_CASE("sinumerik: GETTCOR components and status codes", "[sinumerik]") {
    SinumerikEdge e = milling_example();  // G17: L1 on Z (applicate)
    for (int n = 7; n <= 11; ++n) e.DP(n) = n;
    e.DP(16) = 0.5;
    e.ecp[11] = 1.0;  // $TC_ECP12: setup offset of L1
    e.scp[11] = 2.0;  // $TC_SCP12
    e.scp[14] = 0.1;  // $TC_SCP15: radius
    std::array<double, 11> len{};
    REQUIRE(gettcor(len, "G", e) == gettcor_ok);
    CHECK(len[4] == Approx(120.0));
    CHECK(len[5] == Approx(6.0));
    CHECK((len[6] == 7 && len[10] == 11));
    REQUIRE(gettcor(len, "C", e) == gettcor_ok);
    CHECK((len[4] == Approx(10.0) && len[5] == 0));
    REQUIRE(gettcor(len, "WS", e) == gettcor_ok);
    CHECK(len[4] == Approx(1.85));
    CHECK(len[5] == Approx(0.08));
    CHECK(len[6] == Approx(0.5));
    REQUIRE(gettcor(len, "GWESC", e) == gettcor_ok);
    CHECK(len[4] == Approx(132.85));
    REQUIRE(gettcor(len, "GWESC", e, {}, {}, 0) == gettcor_ok);  // DL0: no E/S
    CHECK(len[4] == Approx(129.85));

    CHECK(gettcor(len, "G", e, {}, "ENV1") == gettcor_no_env_memory);
    GettcorSettings with_mem;
    with_mem.tool_env_memory = 5;
    CHECK(gettcor(len, "G", e, with_mem, "ENV1") == gettcor_env_missing);
    for (const char* c : {"", "GG", "GX", "gWg", ":M"}) CHECK(gettcor(len, c, e) == gettcor_bad_comp);
    for (const char* c : {"G:", "G:X", "G:MCS", "G:M:B"}) CHECK(gettcor(len, c, e) == gettcor_bad_coord);
    for (const char* c : {"G:B", "G:W", "G:K", "G:T", "G:m"}) CHECK(gettcor(len, c, e) == gettcor_ok);
    CHECK(gettcor(len, "G", e, {}, {}, 2) == gettcor_bad_dl);

    SinumerikEdgeMap m{{{1, 1}, e}, {{1, 2}, e}};
    CHECK(gettcor(len, "G", m, 1, 2) == gettcor_ok);
    CHECK(gettcor(len, "G", m, 1, 3) == gettcor_bad_d);
    CHECK(gettcor(len, "G", m, 2, 1) == gettcor_bad_t);
}
