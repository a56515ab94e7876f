// The Sinumerik lexer's fast path (lex_line_fast) against the general lexer (lex_line): on
// every line the fast path takes, the same block and tokens (keys, values bit for bit, texts,
// columns); on every other line, nothing added. Random lines near the plain grammar, and
// hand-picked ones.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "dialects/sinumerik/line_lexer.hpp"
#include "fuzz_targets.hpp"
#include "random_word_lines.hpp"

using namespace toolcomp;
using toolcomp::sinumerik::lex_line_fast;

namespace {

std::string random_line(std::mt19937& rng) {
    static const test::WordLineShape shape{
        .keys = {"G", "X", "Y", "Z", "I", "J", "K", "F", "S", "M", "T", "D", "N", "R", "CR", "x", "g", "n", "CDOF",
                 "CUT", "GOTOF", "AC", "IF", "L", "P", "A", "B", "C"},
        .after_key = "= ",
        .sign_percent = 20,
        .point_percent = 60,
        .in_number = " .E",
        .odd = "=([;:_$\"'/%.\t+-"};
    std::uniform_int_distribution<int> pct(0, 99);
    std::string head;
    if (pct(rng) < 20) head += std::string(static_cast<std::size_t>(pct(rng) % 3), pct(rng) < 80 ? ' ' : '\t');
    if (pct(rng) < 40)
        head += (pct(rng) < 90 ? "N" : "n") + std::to_string(1LL * pct(rng) * (pct(rng) < 5 ? 123456789 : 37)) +
                (pct(rng) < 90 ? " " : "");
    return test::random_word_line(rng, shape, head);
}

}  // namespace

TEST_CASE("sinumerik plain lines: the fast path reads what the general lexer reads, on random lines") {
    std::mt19937 rng(20261208);
    const int lines = 100000;
    const int taken = test::plain_lines_taken(lines, rng, random_line, lex_line_fast, fuzz::same_sinumerik_plain_reading);
    // Both ways are taken often (the generator is near the plain grammar, not on it).
    CHECK(taken > lines / 10);
    CHECK(taken < lines * 9 / 10);
}

TEST_CASE("sinumerik plain lines: hand-picked readings") {
    Program p;
    REQUIRE(lex_line_fast("N0040 g3 X95 Y7.250 I0 J2.5", 8, p));
    REQUIRE(p.size() == 1);
    CHECK(p.blocks()[0].line == 8);
    const auto t = p.tokens(p.blocks()[0]);
    REQUIRE(t.size() == 6);
    CHECK(t[0].key == "N");
    CHECK(t[0].value == 40.0);
    CHECK(t[0].text.empty());
    CHECK(t[1].key == "G");
    CHECK(t[1].text == "G3");
    CHECK(t[1].value == 3.0);
    CHECK(t[1].column == 7);
    CHECK(t[3].key == "Y");
    CHECK(t[3].value == 7.25);
    CHECK(t[3].text == "Y7");  // the word's letter and digits before the point
    CHECK(t[5].value == 2.5);
    Program q;
    REQUIRE(lex_line_fast("G2 X5 Y-0.001 I0 J-3.5 F+.5", 1, q));  // signs, a leading point
    const auto u = q.tokens(q.blocks()[0]);
    REQUIRE(u.size() == 6);
    CHECK(u[2].value == -0.001);
    CHECK(u[2].text == "Y");  // a signed value: the letter alone
    CHECK(u[4].value == -3.5);
    CHECK(u[5].value == 0.5);
    CHECK(u[5].text == "F");
    // Left to the general lexer: comments, assignments, signs, names, labels, calls, block
    // delete, main blocks, '%' headers, compact words.
    for (const char* line : {"G1 X10 ; cut", "X=10", "X - 5", "X-", "X--5", "G1 X=R1", "CDOF2", "LOOP1: G1", "N10G1", "/G1 X1", ":10 G1",
                             "%_N_PART_MPF", "G1X10Y20", "X1.2.3", "MSG(\"x\")", "G1 CR=5", "T1 D1 M6 ; tool",
                             "X12345678901234567", "N1234567890 G1", "G1 X."}) {
        Program r;
        INFO(line);
        CHECK_FALSE(lex_line_fast(line, 1, r));
        CHECK(r.size() == 0);
    }
}
