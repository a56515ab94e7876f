// The ISO lexer: every syntax rule of the foundation scope, with LinuxCNC's messages.
#include <catch2/catch.hpp>

#include <charconv>
#include <cstring>
#include <random>
#include <string>

#include "random_decimal.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"

using namespace toolcomp;

namespace {
Program P(const std::string& s) { return iso::parse(s, Dialect::linuxcnc); }

std::string word_string(const Program& p, std::size_t b) {
    std::string out;
    for (const Word& w : p.words(p.blocks()[b])) out += w.letter + std::to_string(w.value) + " ";
    return out;
}

void require_error(const std::string& text, const std::string& message, int line, int column) {
    try {
        P(text);
        FAIL("no error for: " << text);
    } catch (const ParseError& e) {
        CHECK(std::string(e.what()) == message);
        CHECK(e.line() == line);
        CHECK(e.column() == column);
    }
}
}  // namespace

TEST_CASE("words in any order and case, with values") {
    Program p = P("g1 x10.5 Y-2 z+.5 f300\n");
    REQUIRE(p.size() == 1);
    auto w = p.words(p.blocks()[0]);
    REQUIRE(w.size() == 5);
    CHECK(w[0].letter == 'G');
    CHECK(w[1].letter == 'X');
    CHECK(w[1].value == 10.5);
    CHECK(w[2].value == -2);
    CHECK(w[3].value == 0.5);
    CHECK(w[4].value == 300);
    CHECK(w[1].column == 4);
}

TEST_CASE("spaces inside words and numbers are ignored") {
    Program p = P("G 1 X 1 0 . 5 Y- 2\n");
    auto w = p.words(p.blocks()[0]);
    REQUIRE(w.size() == 3);
    CHECK(w[0].value == 1);
    CHECK(w[1].value == 10.5);
    CHECK(w[2].value == -2);
}

TEST_CASE("comments: parentheses and semicolon, kept with the block") {
    Program p = P("G0 (rapid) X1 ; to the start\n(only a comment)\n");
    REQUIRE(p.size() == 2);
    auto c = p.comments(p.blocks()[0]);
    REQUIRE(c.size() == 2);
    CHECK(c[0].text == "rapid");
    CHECK(c[0].column == 4);
    CHECK(c[1].text == " to the start");
    CHECK(p.words(p.blocks()[0]).size() == 2);
    CHECK(p.words(p.blocks()[1]).size() == 0);
}

TEST_CASE("block delete, N numbers, blank lines, CRLF and percent delimiters") {
    Program p = P("%\r\n\r\n/G1 X1\r\nN10 G0 Y2\r\n   \r\n%\r\nG0 X99\r\n");
    REQUIRE(p.size() == 2);
    CHECK(p.blocks()[0].block_delete);
    CHECK(p.blocks()[0].line == 3);
    CHECK(p.blocks()[1].line == 4);
    CHECK(word_string(p, 1).rfind("N10", 0) == 0);
    CHECK(p.percent_open);
    CHECK(p.percent_closed);
}

TEST_CASE("syntax errors carry LinuxCNC's message, the line and the column") {
    require_error("G0 X1\nG1 X1.2.3\n", "bad number format (trailing characters) parsing '1.2.3'", 2, 5);
    require_error("G0 Y.\n", "bad number format (conversion failed) parsing '.'", 1, 5);
    require_error("G0 X\n", "No characters found in reading real value", 1, 5);
    require_error("G0 X1 & Y2\n", "Bad character '&' used", 1, 7);
    require_error("G0 X1 N10\n", "Bad character 'n' used", 1, 7);
    require_error("G0 V1\n", "Bad character 'v' used", 1, 4);  // U and W: when the block runs
    require_error("G0 (open\n", "Unclosed comment found", 1, 4);
    require_error("G0 (a (b) c)\n", "Nested comment found", 1, 7);
}

TEST_CASE("the 9/Series dialect refuses parameters, expressions and O-words explicitly") {
    auto R = [](const std::string& t) { return iso::parse(t, Dialect::rockwell); };
    CHECK_THROWS_AS(R("G0 X#1\n"), ParseError);
    CHECK_THROWS_AS(R("G0 X[1+2]\n"), ParseError);
    CHECK_THROWS_AS(R("o100 sub\n"), ParseError);
}

TEST_CASE("LinuxCNC lines: computed words, statements, the 252-character limit") {
    Program p = P("G0 X[1+2] Y#1 Z - 5\n#<a b>=[2]\no100 if [#1 EQ 0] (c)\n");
    REQUIRE(p.size() == 3);
    const auto w = p.words(p.blocks()[0]);
    CHECK(w[1].value == 3);  // a constant expression is folded when read
    CHECK(w[1].expr < 0);
    CHECK(w[2].expr >= 0);
    CHECK(w[3].value == -5);
    CHECK(p.statements(p.blocks()[1])[0].label == "ab");  // blanks dropped, case folded
    CHECK(p.statements(p.blocks()[2])[0].kind == Stmt::o_if);
    CHECK(p.comments(p.blocks()[2]).size() == 1);
    require_error("o1 if [1] G1 X1\n", "Unexpected character after O-word", 1, 11);
    require_error("o1 foo\n", "Unknown control command in o word", 1, 4);
    require_error("o1 if\n", "Left bracket missing after 'if'", 1, 6);
    require_error("G1 X[1+2\n", "Unclosed expression", 1, 9);
    require_error("G1 X-INF\n", "Unknown word where unary operation could be", 1, 6);
    require_error("#1 5\n", "Equal sign missing in parameter setting", 1, 5);
    require_error("G0 X1 (" + std::string(245, 'a') + ")\n", "Command too long", 1, 253);
    CHECK_NOTHROW(P("G0 X1 (" + std::string(244, 'a') + ")\n"));  // 252 characters
}

TEST_CASE("numbers read as from_chars reads them, bit for bit, with signs and up to 20 digits") {
    std::mt19937_64 rng(7);
    for (int k = 0; k < 20000; ++k) {
        const std::string digits = random_decimal(rng);
        const char* sign = rng() % 3 == 0 ? "-" : rng() % 2 ? "+" : "";
        const Program p = P("G1 X" + std::string(sign) + digits + " Y1\n");
        double want = 0;
        REQUIRE(std::from_chars(digits.data(), digits.data() + digits.size(), want).ec == std::errc());
        if (*sign == '-') want = -want;
        const Word& x = p.words(p.blocks()[0])[1];
        INFO(sign << digits);
        REQUIRE(x.letter == 'X');
        REQUIRE(std::memcmp(&x.value, &want, sizeof want) == 0);
    }
}

TEST_CASE("lenient ISO parse: a line refused half-way leaves none of its expressions behind") {
    // "X#1" is read (an expression) before '!' refuses the line.
    const Program p = iso::parse("G0 X[1+2] Y#5\nG1 X#1 !\n", Dialect::linuxcnc, "t", /*strict=*/false);
    REQUIRE(p.syntax_error.has_value());
    CHECK(p.syntax_error->code == "bad_character");
    CHECK(p.size() == 1);
    CHECK(p.expression_count() == 1);  // Y#5 of the first line ([1+2] is the constant 3)
}

TEST_CASE("a piece parsed over the piece before last: its own blocks, in the same memory") {
    iso::PieceParser parser(Dialect::linuxcnc, "<pieces>", /*strict=*/false, 4096);
    Program first = parser.parse("%\nG0 X1 (a comment) Y2\n#1 = 5\nG1 X#1 F100\n");
    REQUIRE(first.size() == 3);
    REQUIRE(first.word_count() == 6);
    const Block* rows = first.blocks().data();
    // Blocks without comments, statements or expressions, line numbers running on.
    Program second = parser.parse("G1 X3\nG2 X4 Y0 I1\n", std::move(first));
    CHECK(second.blocks().data() == rows);  // parsed over: the column did not move
    REQUIRE(second.size() == 2);
    CHECK(second.blocks()[0].line == 5);
    CHECK(second.blocks()[0].first_word == 0);
    CHECK(second.blocks()[1].first_word == 2);
    CHECK(second.word_count() == 6);
    CHECK(word_string(second, 1) == "G2.000000 X4.000000 Y0.000000 I1.000000 ");
    CHECK(second.comments(second.blocks()[0]).empty());
    CHECK(second.statements(second.blocks()[0]).empty());
    CHECK(second.expression_count() == 0);
    CHECK(!second.blocks()[0].computed);
    CHECK(second.percent_open);  // the text so far
    CHECK(second.last_line == 6);
    CHECK(second.name == "<pieces>");
}
