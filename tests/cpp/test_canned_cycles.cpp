// Canned cycles expanded into moves. Expected moves are LinuxCNC rs274's output for the
// same program (Debian 12 linuxcnc-uspace 2.9.0~pre1), transcribed.
#include <catch2/catch.hpp>

#include "run_helpers.hpp"

using namespace toolcomp;
using tctest::end_of;
using tctest::run_text;

namespace {
struct Move {
    int kind;  // 0 rapid, 1 feed
    double x, y, z;
};

void check_moves(const Path& p, std::size_t first, std::initializer_list<Move> expect) {
    std::size_t i = first;
    for (const Move& m : expect) {
        INFO("segment " << i);
        REQUIRE(i < p.size());
        CHECK(p.kind[i] == m.kind);
        CHECK(end_of(p, i).isApprox(Vec3(m.x, m.y, m.z), 1e-9));
        ++i;
    }
}
}  // namespace

TEST_CASE("G81 modal, G98 above the initial level, G91 with L repeats") {
    auto r = run_text(
        "G21 G17 G90 F100\nG0 X0 Y0 Z10\nG81 X1 Y1 Z-2 R2\nX5\nG98 G81 X6 Z-2 R12\n"
        "G91 G99 G81 X1 Z-3 R-2 L3\nG90 G80 G0 Z1\nM2\n");
    check_moves(r.nominal, 0,
                {{0, 0, 0, 10},  {0, 1, 1, 10},  {0, 1, 1, 2},   {1, 1, 1, -2},  {0, 1, 1, 2},
                 {0, 5, 1, 2},   {1, 5, 1, -2},  {0, 5, 1, 2},   {0, 5, 1, 12},  {0, 6, 1, 12},
                 {1, 6, 1, -2},  {0, 6, 1, 12},  {0, 7, 1, 12},  {0, 7, 1, 8},   {1, 7, 1, 5},
                 {0, 7, 1, 8},   {0, 8, 1, 8},   {1, 8, 1, 5},   {0, 8, 1, 8},   {0, 9, 1, 8},
                 {1, 9, 1, 5},   {0, 9, 1, 8},   {0, 9, 1, 1}});
    CHECK(r.nominal.size() == 23);
}

TEST_CASE("G83 peck and G73 chip break with 0.254 mm rapid clearance") {
    auto r = run_text("G21 G17 G90 F100\nG0 X0 Y0 Z1\nG83 X0 Y0 Z-5 R2 Q3\nG73 X1 Y0 Z-5 R2 Q3\nM2\n");
    check_moves(r.nominal, 1,
                {{0, 0, 0, 2},      {0, 0, 0, 2},  {1, 0, 0, -1},      {0, 0, 0, 2},  {0, 0, 0, -0.746},
                 {1, 0, 0, -4},     {0, 0, 0, 2},  {0, 0, 0, -3.746},  {1, 0, 0, -5}, {0, 0, 0, 2},
                 // G73 continues the cycle's initial level (Z1, below R): rs274 lifts to R again.
                 {0, 0, 0, 2},      {0, 1, 0, 2},      {1, 1, 0, -1}, {0, 1, 0, -0.746},  {1, 1, 0, -4}, {0, 1, 0, -3.746},
                 {1, 1, 0, -5},     {0, 1, 0, 2}});
}

TEST_CASE("G85 feeds out, G89 dwells and feeds out, G86 needs the spindle") {
    auto r = run_text("G21 G17 G90 F100\nG0 X2 Y0 Z2\nG85 X2 R2 Z-1\nG89 X3 R2 Z-1 P0.5\nM2\n");
    check_moves(r.nominal, 1,
                {{0, 2, 0, 2}, {1, 2, 0, -1}, {1, 2, 0, 2}, {0, 2, 0, 2}, {0, 3, 0, 2}, {1, 3, 0, -1}, {1, 3, 0, 2}});
    CHECK_THROWS_WITH(run_text("G21 F100\nG0 Z5\nG86 X4 R2 Z-1 P1\nM2\n"), "Spindle not turning in g86");
    CHECK_THROWS_WITH(run_text("G21 F100\nG0 Z5\nG81 X4 Z-1\nM2\n"), "R clearance plane unspecified in cycle");
    CHECK_THROWS_WITH(run_text("G21 F100\nG0 Z5\nG83 X4 R2 Z-1\nM2\n"), "Q word missing with g83");
    CHECK_THROWS_WITH(run_text("G21 F100\nG0 Z5\nG81 X4 R-2 Z-1\nM2\n"), "R less than z in cycle in xy plane");
}

TEST_CASE("G87 back boring, absolute and incremental with repeats") {
    auto r = run_text("G21 G17 G90 F200\nM3 S100\nG0 X0 Y0 Z10\nG98 G87 X5 Y5 R2 Z-10 I1 J0.5 K-5\nM2\n");
    check_moves(r.nominal, 1,
                {{0, 5, 5, 10}, {0, 5, 5, 2}, {0, 6, 5.5, 2}, {0, 6, 5.5, -10}, {0, 5, 5, -10}, {1, 5, 5, -5},
                 {1, 5, 5, -10}, {0, 6, 5.5, -10}, {0, 6, 5.5, 10}, {0, 5, 5, 10}});
    auto inc = run_text("G21 G17 G90 F200\nM3 S100\nG0 X0 Y0 Z10\nG91 G99 G87 X5 Y5 R-2 Z-10 I1 J0.5 K3 L2\nM2\n");
    check_moves(inc.nominal, 11,
                {{0, 10, 10, 8}, {0, 11, 10.5, 8}, {0, 11, 10.5, -2}, {0, 10, 10, -2}, {1, 10, 10, 1},
                 {1, 10, 10, -2}, {0, 11, 10.5, -2}, {0, 11, 10.5, 8}, {0, 10, 10, 8}});
    CHECK_THROWS_WITH(run_text("G21 F100\nG0 Z10\nG87 X5 Y5 R2 Z-10 I1 J0.5 K-5\nM2\n"), "Spindle not turning in g87");
    CHECK_THROWS_WITH(run_text("G21 F100\nM3\nG0 Z10\nG87 X5 Y5 R2 Z-10 I1 K-5\nM2\n"), "J word missing with g87");
}
