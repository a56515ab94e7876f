// The Sinumerik lexer's tokens for address words: the short way for an address letter glued
// to its digits ("X95", "y2.000") and the general way for everything next to it (a name that
// goes on, a call, an index, an assignment, a sign or a point after the letter). Expected
// tokens written out by hand from the 840D syntax.
#include <catch2/catch.hpp>

#include <string>

#include "toolcomp/dialects/sinumerik/lexer.hpp"

using namespace toolcomp;

namespace {
// "KEY=value/TEXT" for each token of the first block ("-" for no value, "e" for an expression).
std::string tokens(const std::string& line) {
    const Program p = sinumerik::parse(line, "t", true);
    REQUIRE(p.blocks().size() == 1);
    std::string out;
    for (const Token& t : p.tokens(p.blocks()[0])) {
        out += t.key + "=";
        out += t.has_value ? std::to_string(t.value) : (t.expr >= 0 ? "e" : "-");
        out += "/" + t.text + "@" + std::to_string(t.column) + " ";
    }
    return out;
}
}  // namespace

TEST_CASE("Sinumerik address words: letter and digits, any case, numbers running on past the name") {
    CHECK(tokens("G1 X95 Y2.000") == "G=1.000000/G1@1 X=95.000000/X95@4 Y=2.000000/Y2@8 ");
    CHECK(tokens("g3 x95 y7.5 i0 j2.5") ==
          "G=3.000000/G3@1 X=95.000000/X95@4 Y=7.500000/Y7@8 I=0.000000/I0@13 J=2.500000/J2@16 ");
    CHECK(tokens("X1.5E3") == "X=1.500000/X1@1 E=3.000000/E3@5 ");  // no exponent: E is an address
    CHECK(tokens("N20 X10") == "N=20.000000/@1 X=10.000000/X10@5 ");
}

TEST_CASE("Sinumerik address words next to names, calls, indices and assignments") {
    CHECK(tokens("X-5.5 Y.5") == "X=-5.500000/X@1 Y=0.500000/Y@7 ");  // sign or point: the general way
    CHECK(tokens("X=10 Y = 2") == "X=10.000000/@1 Y=2.000000/@6 ");
    CHECK(tokens("G1X10Y20") == "G=1.000000/G1@1 X=10.000000/X10@3 Y=20.000000/Y20@6 ");  // glued
    CHECK(tokens("R1=5") == "==e/@1 ");  // an assignment to R1, not the address R
    CHECK(tokens("X1A=2") == "==e/@1 ");  // a variable named X1A
    CHECK(tokens("X1 = 2") == "==e/@1 ");  // an assignment to X1
    CHECK_THROWS_WITH(tokens("X1==2"), "Unexpected '='");  // a comparison is no assignment: X1, then '='
    CHECK_THROWS_WITH(tokens("X1 [2]=3"), "'=' expected");  // an index
    CHECK(tokens("L10") == "L=10.000000/L10@1 ");  // a subprogram call by number
}
