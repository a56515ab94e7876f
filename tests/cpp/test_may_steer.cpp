// iso::may_steer: which texts a streamed run must read whole (hand-picked cases).
#include <catch2/catch.hpp>

#include "toolcomp/dialects/iso/lexer.hpp"

using toolcomp::iso::may_steer;

TEST_CASE("may_steer: O-words, GOTO, loops, program numbers and M99 need the whole text") {
    CHECK(may_steer("o100 sub\n"));
    CHECK(may_steer("G1 X1\nO1000\nG1 X2\n"));
    CHECK(may_steer("IF [#1 GT 2] GOTO 10\n"));
    CHECK(may_steer("WHILE [#1 LT 5] DO 1\n"));
    CHECK(may_steer("M99\n"));
    CHECK(may_steer("m 0 9 9\n"));
    CHECK(may_steer("#<_tool_o> = 1\n"));  // conservative: a letter o anywhere outside a comment
}

TEST_CASE("may_steer: straight CAM text streams") {
    CHECK_FALSE(may_steer("G21 G90 (TOOL ONE, O-RING GROOVE)\nG1 X1 Y2 F100\n"));
    CHECK_FALSE(may_steer("G1 X1 (a comment (O) ends at its first parenthesis\nG1 X2\n"));
    CHECK_FALSE(may_steer("M98 P1000\nM9\nM990\nM30\n"));  // a call of a file and other M codes
    CHECK_FALSE(may_steer("#1 = [#1 + 2]\nIF [#1 GT 2] THEN #2 = 1\nG1 X#1\n"));
    CHECK_FALSE(may_steer(""));
}
