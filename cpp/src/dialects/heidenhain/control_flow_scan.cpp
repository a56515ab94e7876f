// has_control_flow (lexer.hpp): which Klartext texts a run must read whole before it starts.
#include <string_view>

#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

bool word_is(std::string_view line, std::size_t from, std::size_t to, std::string_view upper) {
    if (to - from != upper.size()) return false;
    for (std::size_t i = 0; i < upper.size(); ++i)
        if (ascii_upper(line[from + i]) != upper[i]) return false;
    return true;
}

// The number written at `i` after blanks (and signs), -1 if none.
long number_at(std::string_view line, std::size_t i) {
    while (i < line.size() && (blank(line[i]) || line[i] == '+' || line[i] == '-')) ++i;
    if (i >= line.size() || !ascii_digit(line[i])) return -1;
    long n = 0;
    for (; i < line.size() && ascii_digit(line[i]) && n < 100000; ++i) n = n * 10 + (line[i] - '0');
    return n;
}

// Whether one line (no line end in it) holds a word that steers across blocks. `framing`:
// BEGIN and BLK count as such (outside the file's first piece, or in a continued block).
bool steers(std::string_view line, bool framing) {
    bool quoted = false, cycl = false;  // cycl: the word before was CYCL
    std::size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (c == '"') quoted = !quoted;
        if (c == ';' && !quoted) return false;  // a comment to the line's end
        if (!ascii_alpha(c)) {
            ++i;
            continue;
        }
        const std::size_t from = i;
        while (i < line.size() && ascii_alpha(line[i])) ++i;
        if (word_is(line, from, i, "LBL") || word_is(line, from, i, "LABEL") || word_is(line, from, i, "GOTO"))
            return true;
        if (framing && (word_is(line, from, i, "BEGIN") || word_is(line, from, i, "BLK"))) return true;
        if (word_is(line, from, i, "FN")) {  // FN 9 to FN 12: the conditional jumps; no number: unknown
            const long n = number_at(line, i);
            if (n < 0 || (n >= 9 && n <= 12)) return true;
        }
        if (cycl && word_is(line, from, i, "DEF") && number_at(line, i) == 14) return true;  // the contour's labels
        cycl = word_is(line, from, i, "CYCL");
    }
    return false;
}

}  // namespace

bool has_control_flow(std::string_view text, bool start) {
    bool continued = false;  // the last line not blank ended with '~'
    for (std::size_t pos = 0; pos < text.size();) {
        std::size_t end = pos;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        const std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        std::size_t e = line.size();
        while (e > 0 && blank(line[e - 1])) --e;
        if (e == 0) continue;  // a blank line goes on with the block before
        const bool goes_on = line[e - 1] == '~';
        if (steers(line, !start || continued || goes_on)) return true;
        continued = goes_on;
    }
    return false;
}

}  // namespace toolcomp::heidenhain
