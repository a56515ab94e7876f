// The ISO lexer's fast path: most blocks of a CAM program are address words with plain
// numbers, which need none of LineLexer's machinery (blanks dropped into a buffer of their
// own, column maps, expressions). The same words, values and columns as LineLexer; anything
// else is left to it (test_fast_line.cpp compares the two on random lines).
#include "toolcomp/program/decimal.hpp"

#include "codes.hpp"
#include "line_lexer.hpp"

namespace toolcomp::iso {

bool lex_line_fast(std::string_view line, int line_no, Program& prog) {
    const char* const s = line.data();
    const std::size_t n = line.size();
    std::size_t k = 0;
    while (k < n && is_blank(s[k])) ++k;
    if (k == n) return false;
    // The words go into the block as they are read; a line that turns out not to be plain
    // takes its block away again.
    prog.begin_block(line_no, false);
    bool first = true;
    do {
        const char c = s[k];
        const char u = c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c;
        // Not a word letter (O-words, '#', '(', ';', '/', ...), N after the first word, or
        // what follows a number that is not a blank or a letter (a digit, point or sign after
        // blanks would continue the number in LinuxCNC's reading).
        if (u < 'A' || u > 'Z' || !is_word_letter(u, prog.dialect) || (u == 'N' && !first)) break;
        const std::size_t letter = k++;
        if (u == 'N' && k < n && (s[k] == '+' || s[k] == '-')) break;  // a signed N: the lexer says why
        bool negative = false;
        while (k < n && (s[k] == '+' || s[k] == '-')) negative ^= s[k++] == '-';
        const DecimalRun run = scan_decimal_run(s, k, n);
        // No digits (an expression, a parameter, a blank inside the word), two points, or
        // more than 15 digits.
        if (!run.plain()) break;
        k = run.end;
        const double v = decimal_value(run.m, run.frac);
        if (u == 'M' && prog.dialect == Dialect::linuxcnc && (v == written(M98) || v == written(M99))) break;  // the lexer refuses them
        prog.add_word({u, negative ? -v : v, static_cast<int>(letter) + 1});
        first = false;
        while (k < n && is_blank(s[k])) ++k;
        if (k == n) return true;
    } while (true);
    prog.drop_last_block();
    return false;
}

}  // namespace toolcomp::iso
