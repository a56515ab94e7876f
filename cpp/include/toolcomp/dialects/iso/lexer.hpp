#pragma once
// Front end for ISO word-address G-code (LinuxCNC RS274NGC and Fanuc-style).
//
// Syntax rules (LinuxCNC's): words in any order and case; spaces and tabs anywhere outside
// comments (also inside numbers: "X 1 0 . 5" is X10.5); "( )" and ";" comments; "/" block
// delete; N line numbers first in a block; a "%" line delimits the program (text after the
// closing "%" is not part of it); blank lines and CRLF line ends are fine.
#include <string>
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::iso {

// strict: throws ParseError (code, message, line, column) on the first syntax error.
// Otherwise the blocks before it are kept and the error is stored in Program::syntax_error.
Program parse(std::string_view text, Dialect dialect, std::string name = "<string>", bool strict = true);

// Whether `text` may hold control flow that reaches beyond a block: O-words, Fanuc program
// numbers, GOTO, WHILE DO (all written with a letter O outside a comment) or an M99 (which
// runs a main program again from its top). Conservative: "yes" may be wrong, "no" is not.
// A streamed run reads a program without them piece by piece, and one with them whole.
bool has_control_flow(std::string_view text);

// The same for a text read piece by piece (a file too large to hold): each piece is whole
// lines and becomes a Program of its own. Line numbers, the "%" delimiters and the last line
// with content carry over: every piece's Program holds the figures of the text so far.
class PieceParser {
public:
    // `piece_bytes`: the size pieces grow to (FilePieces), 0 for a text parsed whole. A piece's
    // Program is given room for a piece that large (address space: only the rows written
    // become memory), so that a Program parsed over (`into`) keeps its columns in place.
    // The room per byte follows the pieces read so far.
    PieceParser(Dialect dialect, std::string name, bool strict, std::size_t piece_bytes = 0)
        : dialect_(dialect), name_(std::move(name)), strict_(strict), piece_bytes_(piece_bytes) {}
    // `into`: a Program no longer needed, whose memory the piece reuses (Program::clear).
    Program parse(std::string_view piece, Program into = {});
    // The closing "%" or (lenient) a syntax error was met: later text is not part of the program.
    bool done() const { return done_; }
    int lines() const { return line_no_; }  // lines read so far

private:
    Dialect dialect_;
    std::string name_;
    bool strict_;
    std::size_t piece_bytes_;
    double blocks_per_byte_ = 1.0 / 24, words_per_byte_ = 1.0 / 6;  // the most so far
    bool first_ = true, done_ = false;
    int line_no_ = 0, last_line_ = 0;
    bool seen_content_ = false, percent_open_ = false, percent_closed_ = false;
};

}  // namespace toolcomp::iso
