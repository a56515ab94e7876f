#pragma once
// The lexer of one Klartext line, private to the front end (lexer.cpp reads the lines and
// their continuations): the general lexer, and the fast path of the lines CAM posts write
// most (fast_line.cpp).
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::heidenhain {

// A blank within a line (a CR before the line's LF is one).
inline bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// One line (without its '~') into a new block of `prog`, or into the open block when
// `continued` (the line before ended with '~'; `in_comment`: inside a comment it wrapped).
// Throws ParseError; the block it began stays for the caller to drop.
void lex_line(std::string_view line, int line_no, Program& prog, bool continued = false, bool in_comment = false);

// A line of a function and plain words ("12 L X+100 Y-2.5 R0 FMAX M3", "CR X+5 Y+0 R+3.5
// DR-": an optional block number, upper case keys with an optional sign and a plain
// number, blanks between) into a new block of `prog`, as lex_line reads it: the same
// tokens, values bit for bit and columns. False, with nothing added, for any other line
// (comments, Q parameters, spaced values, program names, decimal commas ...), which
// lex_line reads.
bool lex_line_fast(std::string_view line, int line_no, Program& prog);

}  // namespace toolcomp::heidenhain
