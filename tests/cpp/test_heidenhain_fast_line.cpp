// The Klartext lexer's fast path (lex_line_fast) against the general lexer (lex_line): on
// every line the fast path takes, the same block, tokens, values (bit for bit) and columns;
// on every other line, nothing added. Random lines near the plain grammar, and hand-picked
// ones.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "dialects/heidenhain/line_lexer.hpp"
#include "fuzz_targets.hpp"
#include "random_word_lines.hpp"

using namespace toolcomp;
using toolcomp::heidenhain::lex_line_fast;

namespace {

std::string random_line(std::mt19937& rng) {
    static const test::WordLineShape shape{
        .keys = {"L", "CR", "C", "CC", "CT", "RND", "CHF", "LP", "X", "IX", "Y", "Z", "R", "DR", "RL", "RR", "R0",
                 "F", "FMAX", "M", "MB", "PA", "IPA", "CCA", "LEN", "FN", "Q", "FQ", "BEGIN", "END", "CALL", "PGM",
                 "TOOL", "REP", "x", "Cur", "HSC", "MAX", "LBL", "APPR", "DEP"},
        .after_key = " ",
        .sign_percent = 60,
        .blank_after_sign = true,
        .point_percent = 70,
        .decimal_comma = true,
        .in_number = " .+-",
        .odd = "#()\";~/*=:._,Qq\t\r-+"};
    std::uniform_int_distribution<int> pct(0, 99);
    std::string head;
    if (pct(rng) < 20) head += std::string(static_cast<std::size_t>(pct(rng) % 3), ' ');
    if (pct(rng) < 60) head += std::to_string(pct(rng) * 37) + (pct(rng) < 90 ? " " : "");
    std::string line = test::random_word_line(rng, shape, head);
    if (pct(rng) < 10) line += '\r';
    return line;
}

}  // namespace

TEST_CASE("klartext plain lines: the fast path reads what the general lexer reads, on random lines") {
    std::mt19937 rng(20261208);
    const int lines = 100000;
    const int taken = test::plain_lines_taken(lines, rng, random_line, lex_line_fast, fuzz::same_klartext_plain_reading);
    // Both ways are taken often (the generator is near the plain grammar, not on it).
    CHECK(taken > lines / 10);
    CHECK(taken < lines * 9 / 10);
}

TEST_CASE("klartext plain lines: hand-picked readings") {
    Program p;
    REQUIRE(lex_line_fast("12 L X+100 Y-2.5 R0 FMAX M3\r", 13, p));
    REQUIRE(p.size() == 1);
    CHECK(p.blocks()[0].line == 13);
    const auto t = p.tokens(p.blocks()[0]);
    REQUIRE(t.size() == 6);
    CHECK(t[0].key == "L");
    CHECK_FALSE(t[0].has_value);
    CHECK(t[0].column == 4);
    CHECK(t[1].key == "X");
    CHECK(t[1].value == 100.0);
    CHECK(t[1].column == 6);
    CHECK(t[2].value == -2.5);
    CHECK(t[3].key == "R");
    CHECK(t[3].value == 0.0);
    CHECK(t[4].key == "FMAX");
    CHECK(t[5].key == "M");
    CHECK(t[5].value == 3.0);
    Program q;
    REQUIRE(lex_line_fast("CR X+5 Y+0 R+3.5 DR- F600", 1, q));
    const auto u = q.tokens(q.blocks()[0]);
    REQUIRE(u.size() == 6);
    CHECK(u[4].key == "DR");
    CHECK(u[4].sign_only);
    CHECK_FALSE(u[4].has_value);
    CHECK(u[4].value == -1.0);
    CHECK(u[5].value == 600.0);
    // Left to the general lexer: a comment, a Q parameter, spaced values, F MAX, a decimal
    // comma, a leading point, a sign after digits, a name, a statement, a structure block.
    for (const char* line : {"L X+0 ; approach", "L X+Q5", "L Z 25", "L Z + 2", "L F MAX", "L X+1,5", "L X+.5",
                             "CR R2+3 DR+", "CALL PGM SUB1", "BEGIN PGM A MM", "FN 0: Q1 = 5", "Q1 = 5", "* - part",
                             "/ L X+1", "L IX-Q2", "CYCL DEF 7.0", "M140 MB MAX", "L X+1 FQ5", "l x+1",
                             "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB MAX FMAX", "L X+1234567890123456"}) {
        Program r;
        INFO(line);
        CHECK_FALSE(lex_line_fast(line, 1, r));
        CHECK(r.size() == 0);
    }
}
