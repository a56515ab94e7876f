// The Sinumerik lexer's fast path: most blocks of a CAM program are address letters with
// plain numbers ("G1 X95 Y7.5", "G3 X95 Y7 I0 J2.5"), which need none of the general
// lexer's statements. The same tokens, values and columns as lex_line; anything else is
// left to it (test_sinumerik_fast_line.cpp and the fuzz target compare the two on random
// lines).
#include "line_lexer.hpp"

#include "toolcomp/program/decimal.hpp"

namespace toolcomp::sinumerik {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }
bool letter(char c) { return upper(c) >= 'A' && upper(c) <= 'Z'; }

}  // namespace

bool lex_line_fast(std::string_view line, int line_no, Program& prog) {
    const char* const s = line.data();
    const std::size_t n = line.size();
    std::size_t k = 0;
    while (k < n && blank(s[k])) ++k;
    if (k == n || !letter(s[k])) return false;  // blank, comment, '%' header, block delete, main block
    // The tokens go into the block as they are read; a line that turns out not to be plain
    // takes its block away again.
    prog.begin_block(line_no, false);
    if (upper(s[k]) == 'N' && k + 1 < n && digit(s[k + 1])) {  // the block number
        std::size_t j = k + 1;
        std::uint64_t number = 0;
        while (j < n && digit(s[j])) number = number * 10 + static_cast<std::uint64_t>(s[j++] - '0');
        if (j - k - 1 > 9 || (j < n && !blank(s[j]))) {  // too long, or N10G1, N10: ...
            prog.drop_last_block();
            return false;
        }
        Token& t = prog.new_token();
        t.key.assign(1, 'N');
        t.value = static_cast<double>(number);
        t.has_value = true;
        t.column = static_cast<int>(k) + 1;
        k = j;
        while (k < n && blank(s[k])) ++k;
        if (k == n) return true;
    }
    do {
        // A word: a letter, an optional sign, a number of up to 15 digits with at most one
        // point, then a blank or the line's end. Not plain: a name (G1A, CDOF2, GOTOF), an
        // assignment (X=...), a call or index, a label, a comment, a blank before the value.
        const std::size_t start = k;
        if (!letter(s[k]) || k + 1 == n) break;
        std::size_t p = k + 1;
        const bool negative = s[p] == '-', sign = negative || s[p] == '+';
        if (sign) ++p;
        if (p == n || (!digit(s[p]) && s[p] != '.')) break;
        // The text of a letter and its digits as written ("X95", "Y7" of Y7.25); of a signed
        // value or one that starts with its point, the letter alone.
        std::size_t text_end = k + 1;
        if (!sign && digit(s[k + 1]))
            while (text_end < n && digit(s[text_end])) ++text_end;
        const DecimalRun run = scan_decimal_run(s, p, n);
        if (!run.plain() || (run.end < n && !blank(s[run.end]))) break;
        Token& t = prog.new_token();
        t.key.assign(1, upper(s[start]));
        const double v = decimal_value(run.m, run.frac);
        t.value = negative ? -v : v;
        t.has_value = true;
        t.text.assign(std::string_view(s + start, text_end - start));
        t.text[0] = t.key[0];
        t.column = static_cast<int>(start) + 1;
        k = run.end;
        while (k < n && blank(s[k])) ++k;
        if (k == n) return true;
    } while (true);
    prog.drop_last_block();
    return false;
}

}  // namespace toolcomp::sinumerik
