// sinumerik::has_control_flow: which 840D texts a run must read whole (hand-picked cases), and
// the pieces of a text parsed one after the other are the text parsed whole.
#include <catch2/catch.hpp>

#include <string>

#include "toolcomp/dialects/sinumerik/lexer.hpp"

using toolcomp::sinumerik::has_control_flow;

TEST_CASE("sinumerik has_control_flow: jumps, labels, loops, PROC and macros need the whole text") {
    CHECK(has_control_flow("N10 G1 X1\nGOTOF END\nX2\nEND: M30\n"));
    CHECK(has_control_flow("gotob start\n"));
    CHECK(has_control_flow("N10IF R1>0 GOTOF L1\n"));  // a letter run after the block number
    CHECK(has_control_flow("WHILE R1<5\nR1=R1+1\nENDWHILE\n"));
    CHECK(has_control_flow("FOR R2=1 TO 3\nENDFOR\n"));
    CHECK(has_control_flow("LOOP\nENDLOOP\n"));
    CHECK(has_control_flow("REPEAT A B P=2\n"));
    CHECK(has_control_flow("CASE R1 OF 1 GOTOF A DEFAULT GOTOF B\n"));
    CHECK(has_control_flow(":10 G1 X1\n"));  // a main block number
    CHECK(has_control_flow("PROC PART(REAL DEPTH) SAVE\n"));
    CHECK(has_control_flow("DEFINE STEP AS G1 X10\nSTEP\n"));  // a macro may stand for a jump
    CHECK(has_control_flow("MSG(\"a;b\") IF R1==1 GOTOF X\n"));  // ';' in a string is no comment
}

TEST_CASE("sinumerik has_control_flow: CAM text streams") {
    CHECK_FALSE(has_control_flow("%_N_PART_MPF\n;$PATH=/_N_WKS_DIR/_N_PART_WPD\n"));
    CHECK_FALSE(has_control_flow("N10 G90 G17 G71\nT=\"EM10\" D1 M6\nG41 G1 X0 Y0 F1200 RND=2\n"));
    CHECK_FALSE(has_control_flow("; IF GOTOF LABEL: in a comment\nG1 X1\n"));
    CHECK_FALSE(has_control_flow("DEF REAL DEPTH=5\nR1=R1+1\nMCALL CYCLE81(10,0,2,-15)\nX1\nMCALL\nM30\n"));
    CHECK_FALSE(has_control_flow("ENDIFX=1\nMY_IF=2\nCALL \"SUB\"\nL10 P2\nM17\n"));  // names, not keywords
    CHECK_FALSE(has_control_flow(""));
}

// CAM lines of lone letters are passed over 32 bytes at a time: what matters is found at any
// place, across the edges of those runs, and a comment or string opened in one run goes on.
TEST_CASE("sinumerik has_control_flow: found at every offset of long CAM text") {
    const std::string cam = "G1 X100.25 Y-2.5 F1200\nG3 X95 Y7 I0 J2.5\n";  // 40 bytes a pair of lines
    std::string text;
    for (int i = 0; i < 8; ++i) text += cam;
    REQUIRE_FALSE(has_control_flow(text));
    for (std::size_t at = 0; at <= text.size(); ++at) {
        INFO("at byte " << at);
        const std::string before = text.substr(0, at), after = text.substr(at);
        CHECK(has_control_flow(before + "\nGOTOF E\n" + after));
        CHECK(has_control_flow(before + " if " + after));  // lower case
        CHECK(has_control_flow(before + ":" + after));
        CHECK_FALSE(has_control_flow(before + "X" + after));  // a lone letter more
        CHECK_FALSE(has_control_flow(before + "\n; GOTOF E:\n" + after));  // a comment line
        CHECK_FALSE(has_control_flow(before + "\nMSG(\"" + std::string(40, 'A') + "\")\n" + after));
        // A comment to the end of the line hides a jump written 40 bytes later on that line.
        CHECK_FALSE(has_control_flow(before + ";" + std::string(40, ' ') + "GOTOF E\n" + after));
        // A string does not hide a jump (only ';' comments do).
        CHECK(has_control_flow(before + "\"" + std::string(40, ' ') + "\" GOTOB A\n" + after));
    }
}

TEST_CASE("sinumerik PieceParser: pieces go on with the line numbers, macros and syntax error") {
    using toolcomp::sinumerik::PieceParser;
    const std::string a = "DEFINE FEED AS F500\nG1 X1 FEED\n", b = "\nG1 X2 FEED\n", c = "G1 X=(((\nG1 X3\n";
    const auto whole = toolcomp::sinumerik::parse(a + b + c, "p", /*strict=*/false);
    PieceParser p("p", /*strict=*/false, 16);
    const auto first = p.parse(a), second = p.parse(b), third = p.parse(c);
    REQUIRE(first.size() + second.size() + third.size() == whole.size());
    CHECK(first.blocks()[0].line == 2);
    CHECK(second.blocks()[0].line == 4);
    CHECK(second.tokens(second.blocks()[0]).back().key == "F");  // the macro of the first piece
    REQUIRE(third.syntax_error);
    CHECK(third.syntax_error->pos.line == whole.syntax_error->pos.line);
    CHECK(third.syntax_error->pos.line == 5);
    CHECK(p.done());
}

// Program::control_statements: set when a block begins with a statement that steers (after its
// number and label), so that the interpreter indexes the structure; CAM text runs without.
TEST_CASE("sinumerik parse: control_statements marks a block that begins with a steering statement") {
    using toolcomp::sinumerik::parse;
    for (const char* text : {"N10 IF R1==1\nENDIF\n", "L1: WHILE R1<2\nR1=R1+1\nENDWHILE\n", "G1 X1\nN20 gotof END\nEND: M30\n",
                             "PROC SUB(REAL A)\nM17\n", "CASE R1 OF 1 GOTOF A DEFAULT GOTOF B\nA:\nB:\n",
                             "REPEATB L1 P=2\n", "LOOP\nENDLOOP\n", "FOR R1=1 TO 2\nENDFOR\n", "REPEAT\nUNTIL R1==1\n"}) {
        INFO(text);
        CHECK(parse(text, "p", false).control_statements);
    }
    for (const char* text : {"G1 X1 Y2\nG2 X3 Y4 CR=5\n", "N10 G1 X1 ; IF in a comment\n", "R1=R1+1 ENDIFX=1\n",
                             "MSG(\"GOTOF\")\n", "DEF REAL A\nT1 D1\nM30\n"}) {
        INFO(text);
        CHECK_FALSE(parse(text, "p", false).control_statements);
    }
}
