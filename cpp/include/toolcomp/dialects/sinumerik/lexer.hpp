#pragma once
// Front end for Siemens Sinumerik 840D part programs (.mpf main programs, .spf subprograms).
//
// One block per line: an optional '/' (block delete), an optional block number "N10" or main
// block number ":10", an optional jump label "NAME:", then statements up to an optional ';'
// comment. A '%' line (the file header "%_N_NAME_MPF") is skipped. Names are case-insensitive.
//
// Each statement becomes one Token of the block:
// * Address with a number, "X10", "G1", "X=-5", "M6": key = address ("X", "G", "M"), value;
//   text = the word as written when it was one identifier ("CDOF2" stays a keyword; "L10"
//   gives key "L", value 10, text "L10", so a subprogram named MYSUB2 keeps its name).
// * Address with a computed value, "X=R1+5", "CR=2*R3", "X=AC(10)", "I=IC(R2)": key = address,
//   expr = the compiled expression (Program::expression), param = 1 for AC(), 2 for IC().
// * Address with a string, T="DRILL": key = address, text = "\"DRILL\"" (quotes kept).
// * Keyword, "NORM", "CDON", "G41" style names without value: key, no value.
// * Assignment "R1=...", "$TC_DP1[1,2]=...", "LOCAL[R2]=...": key "=", expr = the value,
//   param = the index of an expression whose last instruction is the target variable (its
//   indices computed by the instructions before).
// * Calls with an argument list, "GETTCOR(_LEN,\"GW\")", "MSG(\"x\")", "R1=GETTCOR(...)":
//   key = the name, text = the argument text between the parentheses, param = 1 + the index
//   of the target expression when the result is assigned (0 otherwise).
// * Control statements: "IF"/"WHILE"/"UNTIL" (expr = condition), "FOR" (text = variable,
//   expr = start) followed by "TO" (expr = end), "GOTOF"/"GOTOB"/"GOTO"/"GOTOC" (text =
//   label), "ELSE", "ENDIF", "ENDWHILE", "ENDFOR", "REPEAT", "LOOP", "ENDLOOP", "RET",
//   "DEF" (text = type) followed by one "DEFVAR" per name (text = name, expr = initial
//   value, value = array size when declared with [n]), "PROC" (text = name).
// * Block number: key "N", value. Label: key ":", text = the label.
// Syntax errors are ParseError "syntax_error" with line and column.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::sinumerik {

Program parse(std::string_view text, std::string name = "<string>", bool strict = true);

namespace detail {
class Macros;
}

// A program file read a piece at a time (whole lines each: program/file_pieces.hpp): each
// piece's Program goes on with the line numbers and the DEFINE macros of the pieces before.
// parse() above is a text read as one piece.
class PieceParser {
public:
    // `piece_bytes`: the size pieces grow to (room is reserved for that much), 0 for a text
    // parsed whole.
    PieceParser(std::string name, bool strict, std::size_t piece_bytes = 0);
    ~PieceParser();
    PieceParser(PieceParser&&) noexcept;
    PieceParser& operator=(PieceParser&&) noexcept;
    // `into`: a Program no longer needed, whose memory the piece reuses.
    Program parse(std::string_view piece, Program into = {});
    // A syntax error was met (lenient): later text is not part of the program.
    bool done() const { return done_; }

private:
    std::string name_;
    bool strict_;
    std::size_t piece_bytes_;
    bool first_ = true, done_ = false;
    int line_ = 0;
    std::unique_ptr<detail::Macros> macros_;
};

// Whether the blocks of `text` may depend on each other beyond the modal state, so that a
// run must read the whole program before it starts: a control structure or jump (IF, ELSE,
// WHILE, FOR, LOOP, REPEAT, UNTIL, CASE, GOTO...), a label or main block number (':'), a
// PROC header, or a DEFINE (a macro may stand for any of them). A scan of the bytes outside
// ';' comments for runs of letters (so "N10IF" has IF): "yes" may be wrong, "no" is not.
bool has_control_flow(std::string_view text);

// The address names whose "NAME=value" is a word of the block rather than a variable
// assignment (single letters, and CR, AR, TURN, DISC, OFFN, RPL, I1, J1, K1 ...).
bool is_address(std::string_view upper_name);

// Calls whose result may be assigned ("R1=GETTCOR(...)"): GETTCOR, SETTCOR, LENTOAX. Such a
// token's param is 1 + the target expression's index (0 when the result is not assigned).
bool is_value_call(std::string_view upper_name);

// Names with digits that are one keyword, not an address and a number ("CDOF2", not CDOF = 2;
// "DIAM90"). Every keyword of the interpreter that holds a digit must be here (checked where
// the interpreter lists its keywords).
inline constexpr std::array<std::string_view, 13> kDigitKeywords = {
    "CDOF2", "CUT2D", "DIAM90", "CUT2DF", "CUT3DC", "CUT3DF", "CUT3DFS", "CUT3DFF", "CUT3DCC", "CUT3DCCD",
    "TCOFRZ", "TCOFRY", "TCOFRX"};
inline constexpr std::size_t kShortestDigitKeyword = 5;  // the lexer looks up no shorter name
static_assert([] {
    for (std::string_view k : kDigitKeywords)
        if (k.size() < kShortestDigitKeyword) return false;
    return true;
}());

}  // namespace toolcomp::sinumerik
