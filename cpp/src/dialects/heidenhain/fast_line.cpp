// The Klartext lexer's fast path: most blocks of a CAM program are a function and plain
// words ("L X+100 Y+2.5 R0 FMAX", "CR X+95 Y+7 R+2.5 DR+"), which need none of the general
// lexer's cases. The same tokens, values and columns as lex_line; anything else is left to
// it (test_heidenhain_fast_line.cpp and the fuzz target compare the two on random lines).
#include "line_lexer.hpp"

#include "toolcomp/program/decimal.hpp"

namespace toolcomp::heidenhain {

namespace {

bool upper(char c) { return c >= 'A' && c <= 'Z'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

bool lex_line_fast(std::string_view line, int line_no, Program& prog) {
    const char* const s = line.data();
    const std::size_t n = line.size();
    std::size_t k = 0;
    while (k < n && blank(s[k])) ++k;
    while (k < n && digit(s[k])) ++k;  // the block number
    while (k < n && blank(s[k])) ++k;
    if (k == n || !upper(s[k])) return false;  // block skip, structure block, no function
    // The tokens go into the block as they are read; a line that turns out not to be plain
    // takes its block away again.
    prog.begin_block(line_no, false);
    bool first = true;
    do {
        // The key: upper case letters. Not plain: a word that does not start with one (a
        // comment, a name, a table row), lower case or '.', ':', '_' in a key (CUR.TIME), a
        // '-' before a letter (HSC-MODE), a Q parameter (Q5 = ..., FQ58, X Q5).
        const std::size_t column = k;
        if (k == n || !upper(s[k])) break;
        bool q = false;
        while (k < n && upper(s[k])) q |= s[k++] == 'Q';
        if (q) break;
        const std::string_view key(s + column, k - column);
        // Statements and names (FN 0: ..., BEGIN PGM NAME, CALL PGM FILE) are the general lexer's.
        if (first && (key == "FN" || key == "BEGIN" || key == "END" || key == "CALL")) break;
        if (k < n && !blank(s[k]) && s[k] != '+' && s[k] != '-' && !digit(s[k])) break;
        if (k + 1 < n && s[k] == '-' && (s[k + 1] < '0' || s[k + 1] > '9') && s[k + 1] != '.' && !blank(s[k + 1]))
            break;  // a '-' before a letter joins the key
        bool negative = false, sign = false;
        if (k < n && (s[k] == '+' || s[k] == '-')) negative = s[k++] == '-', sign = true;
        const DecimalRun run = scan_decimal_run(s, k, n);
        // A number: digits with at most one point, not starting with it, up to 15 digits.
        // Digits followed by a sign join the key (R2+3), a comma is a decimal one.
        if (run.end > k && (!run.plain() || s[k] == '.')) break;
        k = run.end;
        if (k < n && !blank(s[k])) break;  // a comment, a sign after digits, a character out of place
        // No digits: a bare key or sign may take a value after blanks ("Z 25", "Z + Q13"),
        // which the next word, not a key, refuses; F MAX and MB MAX are words of two.
        const bool bare = run.digits == 0;
        if (bare && !sign && k < n && (key == "F" || key == "MB")) break;
        Token& t = prog.new_token();
        t.key = key;
        t.column = static_cast<int>(column) + 1;
        if (!bare) {
            const double v = decimal_value(run.m, run.frac);
            t.value = negative ? -v : v;
            t.has_value = true;
        } else if (sign) {
            t.value = negative ? -1 : 1;
            t.sign_only = true;
        }
        first = false;
        while (k < n && blank(s[k])) ++k;
        if (k == n) return true;
    } while (true);
    prog.drop_last_block();
    return false;
}

}  // namespace toolcomp::heidenhain
