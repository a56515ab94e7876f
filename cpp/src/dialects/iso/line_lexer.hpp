#pragma once
// The lexer of one ISO line, private to the front end: words (lexer.cpp) and the statements
// of programs that compute (macro_lexer.cpp: parameters, LinuxCNC O-words, Fanuc Macro B).
//
// LinuxCNC reads a line with its blanks removed and its letters folded (outside comments),
// so "X 1 0 . 5" is X10.5 and "#<Tool Dia>" is #<tooldia>: the lexer works on that text,
// `s_`, and maps every character back to its column in the source line for messages.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "toolcomp/program/expr.hpp"
#include "toolcomp/program/program.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::iso {

// A blank within a line: the C locale's white space but the line end.
inline bool is_blank(char c) { return c != '\n' && ascii_space(c); }

// Letters that are address words in ISO G-code (LinuxCNC's set for a machine with axes
// XYZABC; O, # and [ belong to the statements of programs that compute).
inline bool is_word_letter(char u, Dialect d) {
    // Fanuc and 9/Series: U V W are words too (incremental X Y Z on lathes, extra axes on mills).
    if ((u == 'U' || u == 'V' || u == 'W') && (d == Dialect::fanuc || d == Dialect::rockwell)) return true;
    if ((u == '@' || u == '^' || u == '$') && d == Dialect::linuxcnc) return true;  // polar radius and angle, spindle
    if ((u == 'U' || u == 'W') && d == Dialect::linuxcnc) return true;  // read in a G7x profile only (collect_words)
    switch (u) {
        case 'A': case 'B': case 'C': case 'D': case 'E': case 'F': case 'G': case 'H': case 'I':
        case 'J': case 'K': case 'L': case 'M': case 'N': case 'P': case 'Q': case 'R':
        case 'S': case 'T': case 'X': case 'Y': case 'Z':
            return true;
        default:
            return false;
    }
}

// A line of address words with plain numbers ("G1 X10.5 Y-2 F600": letters, signs, digits,
// points, blanks between words), read straight from the source text into a block of `prog`:
// what LineLexer makes of it, without its normalising pass (fast_line.cpp). False, with
// nothing added, for every other line (comments, parameters, expressions, O-words, blanks
// within a word, anything LineLexer refuses): LineLexer reads those.
bool lex_line_fast(std::string_view line, int line_no, Program& prog);

// The normalised text of a line and its maps, reused from line to line (no allocation per
// line on million-block programs).
struct LineBuffers {
    std::string text;
    std::vector<std::pair<std::size_t, int>> shifts;
};

class LineLexer {
public:
    LineLexer(std::string_view line, int line_no, Program& prog, LineBuffers& buffers);
    void run();

private:
    // ---- words (lexer.cpp) ----------------------------------------------------------------
    int col() const { return col_at(i_); }
    int col_at(std::size_t i) const {
        if (i >= s_.size()) return end_col_;
        // The shift in force at i: the last one at or before i (words are read left to
        // right, so the search goes on from where the previous one stopped).
        if (cursor_ > 0 && shifts_[cursor_ - 1].first > i) cursor_ = 0;
        while (cursor_ < shifts_.size() && shifts_[cursor_].first <= i) ++cursor_;
        if (cursor_ == 0) return static_cast<int>(i) + 1;
        const auto& [at, to] = shifts_[cursor_ - 1];
        return to + static_cast<int>(i - at) + 1;
    }
    [[noreturn]] void fail(const char* code, const std::string& msg) const { fail_at(code, msg, i_); }
    [[noreturn]] void fail_at(const char* code, const std::string& msg, std::size_t i) const;
    bool at_end() const { return i_ >= s_.size(); }
    void comment_paren();
    // The value of an address word: a number, or (programs that compute) a parameter,
    // a bracketed expression or a function; an expression is stored in Word::expr.
    void word_value(Word& w);
    double number();
    // The value of an expression without parameters that evaluates cleanly, else nullopt.
    std::optional<double> constant_value(const expr::Expr& e) const;

    // ---- statements (macro_lexer.cpp) ----------------------------------------------------
    bool macros() const { return macros_; }  // this dialect computes (LinuxCNC, Fanuc)
    const expr::Syntax& syntax() const;
    // Compiles the expression at i_ (a LinuxCNC value when `value_only`: number, '#',
    // '[...]' or function; else a whole Fanuc expression).
    std::int32_t expression(bool value_only);
    void o_word();                 // LinuxCNC: o100 sub / o<name> call [..] ...
    bool fanuc_statement();        // IF / WHILE / END / GOTO at the start of a block
    void assignment();             // #n = value, #<name> = value
    bool keyword(std::string_view k);  // consumes k (upper case) when the text continues with it
    bool macro_word(std::string_view k);  // keyword(k) or its first two letters (Fanuc abbreviations)
    void rest_is_comments();       // after an O-word or a GOTO: only comments may follow

    std::string& s_;  // the line as LinuxCNC reads it (comment texts kept as written)
    // (i, p): from s_[i] on, characters come from source position p + (offset past i)
    std::vector<std::pair<std::size_t, int>>& shifts_;
    std::string_view raw_;  // the source line
    mutable std::size_t cursor_ = 0;  // col_at: shifts_ entries at or before the last position asked
    int end_col_ = 1;
    std::size_t i_ = 0;
    int line_;
    Program& prog_;
    bool first_word_ = true;
    bool m98_ = false;  // LinuxCNC: the line begins with M98
    bool macros_ = false;
};

}  // namespace toolcomp::iso
