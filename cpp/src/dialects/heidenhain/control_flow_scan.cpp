// has_control_flow (lexer.hpp): which Klartext texts a run must read whole before it starts.
#include <cstdint>
#include <cstring>
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
// The words of CAM blocks (L, X, CR, DR, FMAX ...) are passed by on their length and first
// letter.
bool steers(std::string_view line, bool framing) {
    bool quoted = false, cycl = false;  // cycl: the word before was CYCL
    std::size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (!ascii_alpha(c)) {
            if (c == '"') quoted = !quoted;
            if (c == ';' && !quoted) return false;  // a comment to the line's end
            ++i;
            continue;
        }
        const std::size_t from = i;
        while (i < line.size() && ascii_alpha(line[i])) ++i;
        const std::size_t n = i - from;
        const char first = ascii_upper(c);
        const bool was_cycl = cycl;
        cycl = false;
        if (n < 2 || n > 5 || (first != 'L' && first != 'G' && first != 'B' && first != 'F' && first != 'D' && first != 'C'))
            continue;  // none of the words below
        if (word_is(line, from, i, "LBL") || word_is(line, from, i, "LABEL") || word_is(line, from, i, "GOTO"))
            return true;
        if (framing && (word_is(line, from, i, "BEGIN") || word_is(line, from, i, "BLK"))) return true;
        if (word_is(line, from, i, "FN")) {  // FN 9 to FN 12: the conditional jumps; no number: unknown
            const long k = number_at(line, i);
            if (k < 0 || (k >= 9 && k <= 12)) return true;
        }
        if (was_cycl && word_is(line, from, i, "DEF") && number_at(line, i) == 14) return true;  // the contour's labels
        cycl = word_is(line, from, i, "CYCL");
    }
    return false;
}

// Whether the 32 bytes from p may hold a word steers() looks for: each has a B, E, G or N
// (LBL, LABEL, GOTO, BEGIN, BLK, FN, DEF), which a CAM block ("L X+100 Y+2.5 R0 FMAX", "CR
// X+5 Y+0 R+3.5 DR-") has none of. With GCC and Clang 16 bytes are compared at a time.
constexpr std::size_t kRun = 32;
#if defined(__GNUC__)
bool may_steer(const char* p) {
    using Bytes = unsigned char __attribute__((vector_size(16)));
    Bytes a, b;
    std::memcpy(&a, p, sizeof a);
    std::memcpy(&b, p + sizeof a, sizeof b);
    a |= 0x20;  // lower case (and some other bytes, never these)
    b |= 0x20;
    const auto hit = (a == 'b') | (a == 'e') | (a == 'g') | (a == 'n') | (b == 'b') | (b == 'e') | (b == 'g') | (b == 'n');
    std::uint64_t w[2];
    std::memcpy(w, &hit, sizeof w);
    return (w[0] | w[1]) != 0;
}
#else
bool may_steer(const char* p) {
    unsigned any = 0;
    for (std::size_t k = 0; k < kRun; ++k) {
        const unsigned u = static_cast<unsigned char>(p[k]) | 0x20u;
        any |= static_cast<unsigned>(u == 'b') | (u == 'e') | (u == 'g') | (u == 'n');
    }
    return any != 0;
}
#endif

// Whether `line` (in `text`) may hold such a word: 32 bytes at a time while the text lasts
// (bytes of the lines after it only make a "maybe"), then byte by byte.
bool may_steer(std::string_view text, std::string_view line) {
    const std::size_t from = static_cast<std::size_t>(line.data() - text.data());
    std::size_t k = 0;
    for (; k < line.size() && from + k + kRun <= text.size(); k += kRun)
        if (may_steer(line.data() + k)) return true;
    for (; k < line.size(); ++k) {
        const unsigned u = static_cast<unsigned char>(line[k]) | 0x20u;
        if (u == 'b' || u == 'e' || u == 'g' || u == 'n') return true;
    }
    return false;
}

}  // namespace

bool has_control_flow(std::string_view text, bool start) {
    const auto find = [&](char c, std::size_t from, std::size_t to) {  // `to` when not found
        const void* p = from < to ? std::memchr(text.data() + from, c, to - from) : nullptr;
        return p ? static_cast<std::size_t>(static_cast<const char*>(p) - text.data()) : to;
    };
    bool continued = false;  // the last line not blank ended with '~'
    for (std::size_t pos = 0; pos < text.size();) {
        std::size_t end = find('\r', pos, find('\n', pos, text.size()));  // the first CR or LF
        const std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        std::size_t e = line.size();
        while (e > 0 && blank(line[e - 1])) --e;
        if (e == 0) continue;  // a blank line goes on with the block before
        const bool goes_on = line[e - 1] == '~';
        if (may_steer(text, line) && steers(line, !start || continued || goes_on)) return true;
        continued = goes_on;
    }
    return false;
}

}  // namespace toolcomp::heidenhain
