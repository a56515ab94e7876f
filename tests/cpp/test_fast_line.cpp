// The ISO lexer's fast path (lex_line_fast) against the general lexer (LineLexer): on every
// line the fast path takes, the same block, words, values (bit for bit) and columns; on every
// other line, nothing added. Random lines near the plain grammar, and hand-picked ones.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "dialects/iso/line_lexer.hpp"
#include "fuzz_targets.hpp"
#include "toolcomp/program/diagnostic.hpp"

using namespace toolcomp;
using toolcomp::iso::lex_line_fast;

namespace {

Program empty(Dialect d) {
    Program p;
    p.dialect = d;
    return p;
}

// The general lexer's reading of `line`, or false when it refuses the line.
bool general(const std::string& line, Program& p) {
    iso::LineBuffers buffers;
    try {
        iso::LineLexer(line, 7, p, buffers).run();
        return true;
    } catch (const ParseError&) {
        return false;
    }
}

void same_reading(const std::string& line, Dialect d, int& plain) {
    INFO("line '" << line << "', dialect " << static_cast<int>(d));
    Program fast = empty(d), slow = empty(d);
    if (!lex_line_fast(line, 7, fast)) {
        CHECK(fast.size() == 0);
        CHECK(fast.word_count() == 0);
        return;
    }
    ++plain;
    REQUIRE(general(line, slow));
    REQUIRE(fast.size() == 1);
    REQUIRE(slow.size() == 1);
    const Block& a = fast.blocks()[0];
    const Block& b = slow.blocks()[0];
    CHECK(b.comment_count == 0);
    CHECK(b.statement_count == 0);
    // line, block delete, words: letters, values bit for bit, columns (the fuzz target's test)
    CHECK(fuzz::same_block(fast, a, slow, b));
}

std::string random_line(std::mt19937& rng) {
    static const std::string letters = "GXYZIJKFNMSTDHPQRABCEULVWOgxyzfn";
    static const std::string odd = "#[]()/;$=*<>e\x80\xe9\f\v";
    std::uniform_int_distribution<int> pct(0, 99);
    auto pick = [&](const std::string& s) { return s[std::uniform_int_distribution<std::size_t>(0, s.size() - 1)(rng)]; };
    std::string line;
    if (pct(rng) < 20) line += std::string(static_cast<std::size_t>(pct(rng) % 3), ' ');
    const int words = pct(rng) % 7;
    for (int w = 0; w < words; ++w) {
        line += pick(letters);
        if (pct(rng) < 5) line += ' ';
        while (pct(rng) < 12) line += pct(rng) < 50 ? '-' : '+';
        const int digits = pct(rng) < 3 ? 16 + pct(rng) % 4 : pct(rng) % 8;
        const int point = pct(rng) < 70 ? pct(rng) % (digits + 1) : -1;
        for (int k = 0; k < digits; ++k) {
            if (k == point) line += '.';
            line += static_cast<char>('0' + pct(rng) % 10);
            if (pct(rng) < 2) line += pick(" .");
        }
        if (point == digits) line += '.';
        if (pct(rng) < 6) line += pick(odd);
        const int blanks = pct(rng) < 30 ? 0 : 1 + pct(rng) % 2;
        for (int k = 0; k < blanks; ++k) line += pct(rng) < 85 ? ' ' : '\t';
    }
    if (pct(rng) < 10) line += '\r';
    return line;
}

}  // namespace

TEST_CASE("plain lines: the fast path reads what the general lexer reads, on random lines") {
    std::mt19937 rng(20261203);
    int plain = 0, lines = 0;
    for (int i = 0; i < 60000; ++i) {
        const std::string line = random_line(rng);
        for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc, Dialect::rockwell}) {
            same_reading(line, d, plain);
            ++lines;
        }
    }
    // Both ways are taken often (the generator is near the plain grammar, not on it).
    CHECK(plain > lines / 5);
    CHECK(plain < lines * 4 / 5);
}

TEST_CASE("plain lines: hand-picked readings") {
    Program p = empty(Dialect::linuxcnc);
    REQUIRE(lex_line_fast("G1 X10.5 y-2 F600\r", 3, p));
    REQUIRE(p.size() == 1);
    const auto w = p.words(p.blocks()[0]);
    REQUIRE(w.size() == 4);
    CHECK(p.blocks()[0].line == 3);
    CHECK((w[0].letter == 'G' && w[0].value == 1 && w[0].column == 1));
    CHECK((w[1].letter == 'X' && w[1].value == 10.5 && w[1].column == 4));
    CHECK((w[2].letter == 'Y' && w[2].value == -2 && w[2].column == 10));
    CHECK((w[3].letter == 'F' && w[3].value == 600 && w[3].column == 14));

    Program q = empty(Dialect::linuxcnc);
    REQUIRE(lex_line_fast("N10G1X1Y.5", 1, q));
    CHECK(q.word_count() == 4);

    // Left to the general lexer, with nothing added.
    for (const char* line : {"", "   ", "X 1 0", "X1 0", "N10 N20", "O100 sub", "G1 X1 (c)", "G1 X1;c",
                             "G1 X1.2.3", "G1 X", "G1 X#1", "G1 X[1+2]", "/G1 X1", "G1 Xsin[0]",
                             "G1 X12345678901234567", "IF[#1GT2]GOTO5", "G1 X1 $", "G1 X1e"}) {
        Program r = empty(Dialect::fanuc);
        INFO(line);
        CHECK_FALSE(lex_line_fast(line, 1, r));
        CHECK(r.size() == 0);
        CHECK(r.word_count() == 0);
    }
    // U, V and W are words on Fanuc and the 9/Series; on LinuxCNC U and W only (read in a lathe
    // cycle's profile, refused elsewhere when the block runs), not V.
    Program f = empty(Dialect::fanuc), l = empty(Dialect::linuxcnc);
    CHECK(lex_line_fast("G1 U1 V2 W-2", 1, f));
    CHECK(lex_line_fast("G1 U1 W-2", 2, l));
    CHECK_FALSE(lex_line_fast("G1 V1", 3, l));
}
