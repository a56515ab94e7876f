// heidenhain::has_control_flow: which Klartext texts a run must read whole (hand-picked
// cases), and heidenhain::PieceParser: the pieces of a text parsed one after the other are
// the text parsed whole (line numbers, unit, blank, '~' blocks, the frame's errors).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/program/diagnostic.hpp"

using toolcomp::heidenhain::has_control_flow;

TEST_CASE("heidenhain has_control_flow: labels, jumps and contours by label need the whole text") {
    CHECK(has_control_flow("5 LBL 1\n6 L X+10 R0 F500\n7 LBL 0\n"));
    CHECK(has_control_flow("8 CALL LBL 1 REP 3\n"));
    CHECK(has_control_flow("8 CALL LBL \"CONTOUR\"\n"));
    CHECK(has_control_flow("9 lbl 0\n"));                        // lower case
    CHECK(has_control_flow("9 Call Lbl1\n"));                    // mixed case, the number against it
    CHECK(has_control_flow("10 FN 9: IF +Q1 EQU +Q2 GOTO LBL 5\n"));
    CHECK(has_control_flow("10 FN 12: IF +Q1 LT +5 GOTO LBL \"A\"\n"));
    CHECK(has_control_flow("10 fn11: if +q1 gt +5 goto lbl 2\n"));  // no blank after FN
    CHECK(has_control_flow("11 FN10\n"));                        // FN 10 whatever follows
    CHECK(has_control_flow("11 FN\n"));                          // FN without a number: unknown
    CHECK(has_control_flow("12 CYCL DEF 14.0 CONTOUR GEOMETRY\n13 CYCL DEF 14.1 CONTOUR LABEL 1\n"));
    CHECK(has_control_flow("12 cycl def 14.0 contour\n"));
    CHECK(has_control_flow("13 CYCL DEF 20 CONTOUR DATA ~\n  Q1=-20 ;MILLING DEPTH ~\n  Q2=1 ~\n  LBL 3\n"));  // in a tilde block
    CHECK(has_control_flow("14 L X+1 \"a;b\" LBL 1\n"));  // ';' in quotes is no comment
}

TEST_CASE("heidenhain has_control_flow: the unit and the blank outside the first piece") {
    const std::string head = "0 BEGIN PGM PART MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n";
    CHECK_FALSE(has_control_flow(head, /*start=*/true));
    CHECK(has_control_flow(head, /*start=*/false));
    CHECK(has_control_flow("7 begin pgm X inch\n", false));
    CHECK(has_control_flow("7 blk form 0.2 X+1\n", false));
    // A block continued with '~' at the first piece's end may go on in the next piece.
    CHECK(has_control_flow("0 BEGIN PGM PART ~\nMM\n", true));
    CHECK(has_control_flow("3 L X+0\n4 BLK FORM 0.2 ~\n\n  X+100 Y+100 Z+0\n", true));
    CHECK(has_control_flow("3 CYCL DEF 200 ~\n  Q200=2 ~\n4 BLK FORM 0.2 X+1\n", true));  // the block of line 3 goes on
    CHECK_FALSE(has_control_flow("3 L X+0 ; BEGIN BLK LBL in a comment\n", false));
    CHECK_FALSE(has_control_flow("3 * - BLK FORM\n", true));
}

TEST_CASE("heidenhain has_control_flow: CAM text streams") {
    CHECK_FALSE(has_control_flow(""));
    CHECK_FALSE(has_control_flow("0 BEGIN PGM 11SETUP MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n"
                                 "3 TOOL CALL 14 Z S5000 F800 DL+0.1\n4 TOOL DEF 14\n5 L Z+50 R0 FMAX M3\n"
                                 "6 APPR LCT X+10 Y+0 R5 RL F300\n7 L X+90 Y+0\n8 RND R3\n9 CC X+50 Y+50\n"
                                 "10 C X+90 Y+100 DR+\n11 DEP LCT X+0 Y+0 R5\n12 END PGM 11SETUP MM\n"));
    CHECK_FALSE(has_control_flow("15 CYCL DEF 200 DRILLING ~\n  Q200=2 ;SET-UP CLEARANCE ~\n  Q201=-15 ;DEPTH ~\n"
                                 "  Q206=+150 ;FEED RATE FOR PLNGNG\n16 CYCL CALL POS X+10 Y+10 Z+0 FMAX\n"));
    CHECK_FALSE(has_control_flow("17 CALL PGM TNC:\\PARTS\\SIDE.H\n18 FN 0: Q1 = +5\n19 FN 18: SYSREAD Q3 = ID210 NR1\n"
                                 "20 Q5 = Q1 * 2\n21 FN 14: ERROR = 1000\n"));
    CHECK_FALSE(has_control_flow("22 CYCL DEF 7.0 DATUM SHIFT\n23 CYCL DEF 7.1 X+10\n24 CYCL DEF 140\n"));
    CHECK_FALSE(has_control_flow("25 L X+1 ; LBL 1 / CALL LBL / FN 9: GOTO LBL / CYCL DEF 14\n"));  // a comment
    CHECK_FALSE(has_control_flow("26 LBLX+1\n27 LABELS\n28 L X+1 M91 ; label\n"));  // no such word
}

TEST_CASE("heidenhain has_control_flow: a steering word at every offset, lines passed over 32 bytes at a time") {
    const std::string cam = "7 L X+100 Y+2.000 R0 FMAX M3\n8 CR X+95 Y+7.000 R+2.5 DR+ F600\n";
    for (std::size_t off = 0; off < 80; ++off) {
        for (const char* word : {"LBL 1", "GOTO", "fn 9", "Label"}) {
            const std::string line = "5 L X+1" + std::string(off, ' ') + word + "\n";
            INFO("offset " << off << ", " << word);
            CHECK(has_control_flow(cam + line));         // at the text's end
            CHECK(has_control_flow(cam + line + cam));   // with CAM lines after it
            CHECK(has_control_flow(line + cam + cam));   // first
        }
        const std::string plain = "5 L X+1" + std::string(off, ' ') + "Y+2 DR- FMAX\n";
        CHECK_FALSE(has_control_flow(cam + plain + cam + plain));
    }
}

namespace {
// `text` read in pieces cut after the lines listed (line numbers, 1-based), then end().
std::vector<toolcomp::Program> in_pieces(const std::string& text, std::vector<int> cuts, bool strict = false) {
    toolcomp::heidenhain::PieceParser p("p", strict, 16);
    std::vector<toolcomp::Program> out;
    std::size_t pos = 0;
    int line = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n') continue;
        ++line;
        if (!cuts.empty() && cuts.front() == line) {
            out.push_back(p.parse(std::string_view(text).substr(pos, i + 1 - pos)));
            pos = i + 1;
            cuts.erase(cuts.begin());
        }
    }
    if (pos < text.size()) out.push_back(p.parse(std::string_view(text).substr(pos)));
    if (!p.done()) out.push_back(p.end());
    return out;
}
std::size_t blocks(const std::vector<toolcomp::Program>& ps) {
    std::size_t n = 0;
    for (const auto& p : ps) n += p.size();
    return n;
}
}  // namespace

TEST_CASE("heidenhain PieceParser: a '~' block over a piece's end is read with the next piece") {
    const std::string text =
        "0 BEGIN PGM P INCH\n1 BLK FORM 0.1 Z X+0 Y+0 Z-1\n2 BLK FORM 0.2 X+4 Y+4 Z+0\n3 L X+1 R0 FMAX\n"
        "4 CYCL DEF 200 DRILLING ~\n  Q200=2 ;SET-UP CLEARANCE ~\n\n  Q201=-15 ;DEPTH ~\n  Q206=+150\n"
        "5 L X+2\n6 END PGM P INCH\n7 text after the end\n";
    const auto whole = toolcomp::heidenhain::parse(text, "p", false);
    REQUIRE_FALSE(whole.syntax_error);
    // Cut inside the cycle's block (after lines 5, 6 and 7): the block is held back to line 10.
    const auto ps = in_pieces(text, {5, 6, 7, 8});
    REQUIRE(blocks(ps) == whole.size());
    CHECK(ps[0].size() == 4);  // lines 1 to 4; the cycle's first line held back
    REQUIRE(ps[1].size() == 0);
    REQUIRE(ps[3].size() == 0);
    REQUIRE(ps[4].size() == 3);  // the cycle (lines 5 to 9), lines 10 and 11
    CHECK(ps[4].blocks()[0].line == 5);
    CHECK(ps[4].tokens(ps[4].blocks()[0]).size() == whole.tokens(whole.blocks()[4]).size());
    CHECK(ps[4].blocks()[1].line == 10);
    for (const auto& p : ps) {
        CHECK(p.inch);  // the unit of BEGIN PGM goes on
        REQUIRE(p.blank);
        CHECK(p.blank->max.x() == 4);
        CHECK_FALSE(p.syntax_error);
    }
    CHECK(ps.back().last_line == 11);
}

TEST_CASE("heidenhain PieceParser: the frame's errors are those of the text parsed whole") {
    const std::string body = "0 BEGIN PGM P MM\n1 L X+1 R0 FMAX\n2 L X+2\n\n3 L X+3\n";
    SECTION("END PGM missing: found at the end") {
        const auto whole = toolcomp::heidenhain::parse(body, "p", false);
        REQUIRE(whole.syntax_error);
        const auto ps = in_pieces(body, {2, 3});
        REQUIRE(ps.back().syntax_error);
        CHECK(ps.back().syntax_error->code == whole.syntax_error->code);
        CHECK(ps.back().syntax_error->pos.line == 5);
        CHECK(ps.back().syntax_error->pos.line == whole.syntax_error->pos.line);
        for (std::size_t i = 0; i + 1 < ps.size(); ++i) CHECK_FALSE(ps[i].syntax_error);
        CHECK_THROWS_AS(in_pieces(body, {2, 3}, /*strict=*/true), toolcomp::ParseError);
    }
    SECTION("BEGIN PGM missing: raised at END PGM, after the blocks") {
        const std::string text = "; a comment\n1 L X+1 R0 FMAX\n2 L X+2\n3 END PGM P MM\n";
        const auto whole = toolcomp::heidenhain::parse(text, "p", false);
        const auto ps = in_pieces(text, {1, 2});
        REQUIRE(blocks(ps) == whole.size());
        REQUIRE(ps.back().syntax_error);
        CHECK(ps.back().syntax_error->code == whole.syntax_error->code);
        CHECK(ps.back().syntax_error->pos.line == 2);
        CHECK(ps.back().syntax_error->pos.column == whole.syntax_error->pos.column);
    }
    SECTION("a syntax error in a later piece: the blocks before it, no frame error") {
        const std::string text = body + "4 L X+1&\n5 L X+5\n";
        const auto whole = toolcomp::heidenhain::parse(text, "p", false);
        const auto ps = in_pieces(text, {1, 4});
        REQUIRE(blocks(ps) == whole.size());
        REQUIRE(ps.back().syntax_error);
        CHECK(ps.back().syntax_error->code == whole.syntax_error->code);
        CHECK(ps.back().syntax_error->pos.line == 6);
    }
    SECTION("an empty text") {
        const auto ps = in_pieces("", {});
        REQUIRE(ps.size() == 1);
        REQUIRE(ps[0].syntax_error);
        CHECK(ps[0].syntax_error->pos.line == 1);
    }
}
