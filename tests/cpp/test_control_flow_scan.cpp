// iso::has_control_flow: which texts a streamed run must read whole (hand-picked cases, and random
// texts against a byte-by-byte scan).
#include <catch2/catch.hpp>

#include <iterator>
#include <random>
#include <string>

#include "toolcomp/dialects/iso/lexer.hpp"

using toolcomp::iso::has_control_flow;

TEST_CASE("has_control_flow: O-words, GOTO, loops, program numbers and M99 need the whole text") {
    CHECK(has_control_flow("o100 sub\n"));
    CHECK(has_control_flow("G1 X1\nO1000\nG1 X2\n"));
    CHECK(has_control_flow("IF [#1 GT 2] GOTO 10\n"));
    CHECK(has_control_flow("WHILE [#1 LT 5] DO 1\n"));
    CHECK(has_control_flow("M99\n"));
    CHECK(has_control_flow("m 0 9 9\n"));
    CHECK(has_control_flow("#<_tool_o> = 1\n"));  // conservative: a letter o anywhere outside a comment
}

TEST_CASE("has_control_flow: straight CAM text streams") {
    CHECK_FALSE(has_control_flow("G21 G90 (TOOL ONE, O-RING GROOVE)\nG1 X1 Y2 F100\n"));
    CHECK_FALSE(has_control_flow("G1 X1 (a comment (O) ends at its first parenthesis\nG1 X2\n"));
    CHECK_FALSE(has_control_flow("M98 P1000\nM9\nM990\nM30\n"));  // a call of a file and other M codes
    CHECK_FALSE(has_control_flow("#1 = [#1 + 2]\nIF [#1 GT 2] THEN #2 = 1\nG1 X#1\n"));
    CHECK_FALSE(has_control_flow(""));
}

namespace {
// The scan byte by byte, as it was written first: the reference for the one that passes over
// runs of bytes.
bool may_steer_bytewise(std::string_view text) {
    bool comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            comment = false;
        } else if (comment) {
            comment = c != ')';
        } else if (c == '(') {
            comment = true;
        } else if (c == 'O' || c == 'o') {
            return true;
        } else if (c == 'M' || c == 'm') {
            long value = 0;
            for (std::size_t j = i + 1; j < text.size(); ++j) {
                const char d = text[j];
                if (d == ' ' || d == '\t') continue;
                if (d < '0' || d > '9' || value > 1000) break;
                value = value * 10 + (d - '0');
            }
            if (value == 99) return true;
        }
    }
    return false;
}
}  // namespace

TEST_CASE("has_control_flow: passing over runs of bytes finds what the byte-by-byte scan finds") {
    // Texts of CAM lines with, now and then, a comment, an M code or a letter O, at every
    // offset against the 32-byte runs, the special bytes also at the runs' edges.
    std::mt19937 rng(7);
    const char* pieces[] = {"G1 X1.5 Y-2\n", "(O in a comment)\n", "(open comment O\n", "M9\n", "M 9 9\n",
                            "M099\n", "o", "(", ")", "\n", "M", "9", " ", "X12.345 Y6.789 Z-1\n", "m99", "M98 P1\n"};
    int steer = 0;
    for (int n = 0; n < 20000; ++n) {
        std::string text(rng() % 40, 'X');
        for (int k = rng() % 12; k-- > 0;) text += pieces[rng() % std::size(pieces)];
        for (int k = rng() % 3; k-- > 0;) text += std::string(rng() % 70, 'Y');
        text += pieces[rng() % std::size(pieces)];
        INFO(text);
        const bool want = may_steer_bytewise(text);
        steer += want;
        REQUIRE(has_control_flow(text) == want);
    }
    CHECK(steer > 2000);  // both answers are met often
    CHECK(steer < 18000);
}
