#pragma once
// The lexer of one Sinumerik line, private to the front end (lexer.cpp reads the lines,
// DEFINE macros and pieces): the general lexer, and the fast path of the lines CAM posts
// write most (fast_line.cpp).
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::sinumerik {

// One line (macros expanded) into a new block of `prog` (none for a blank line, a comment
// line or the '%' header). Throws ParseError; the block it began stays for the caller to drop.
void lex_line(std::string_view line, int line_no, Program& prog);

// A line of address words with plain numbers ("N10 G1 X95 Y-7.5 F600": an optional block
// number, letters each followed by an optional sign and digits with at most one point,
// blanks between) into a new block of `prog`, as lex_line reads it: the same tokens (key, value bit for bit, the
// word's text, column). False, with nothing added, for any other line (comments,
// assignments, expressions, keywords, labels ...), which lex_line reads.
bool lex_line_fast(std::string_view line, int line_no, Program& prog);

}  // namespace toolcomp::sinumerik
