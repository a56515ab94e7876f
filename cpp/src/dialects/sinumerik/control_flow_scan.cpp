// has_control_flow (lexer.hpp): which Sinumerik texts a run must read whole before it starts.
#include <array>
#include <string_view>

#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {

// The words that steer across blocks, and the ones that may hide such a word (a macro) or
// read the program's own header (PROC's parameters).
constexpr std::array<std::string_view, 15> kSteering = {
    "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "ENDFOR", "LOOP", "ENDLOOP",
    "REPEAT", "REPEATB", "UNTIL", "CASE", "PROC", "DEFINE"};

bool steering(std::string_view upper_word) {
    if (upper_word.starts_with("GOTO")) return true;  // GOTO, GOTOF, GOTOB, GOTOC, GOTOS
    for (std::string_view k : kSteering)
        if (k == upper_word) return true;
    return false;
}

// Whether 32 bytes from p (and the one after them) may hold what the scan looks for: a ':',
// ';' or '"', or two letters in a row (every steering word has two or more). A CAM line ("G1
// X100 Y2.5") has only lone letters. The loop is one the compiler vectorises.
constexpr std::size_t kRun = 32;
bool may_matter(const char* p) {
    unsigned any = 0;
    for (std::size_t k = 0; k < kRun; ++k) {
        const auto c = static_cast<unsigned char>(p[k]), d = static_cast<unsigned char>(p[k + 1]);
        const bool lc = static_cast<unsigned char>((c | 0x20) - 'a') < 26 || c == '_';
        const bool ld = static_cast<unsigned char>((d | 0x20) - 'a') < 26 || d == '_';
        any |= static_cast<unsigned>(lc & ld) | (c == ':') | (c == ';') | (c == '"');
    }
    return any != 0;
}

}  // namespace

bool has_control_flow(std::string_view text) {
    char word[16];
    std::size_t n = 0;  // letters of the run so far (a run longer than the longest keyword: none)
    bool comment = false, quoted = false;  // after ';' (not in a string); inside "..."
    for (std::size_t i = 0; i <= text.size(); ++i) {
        // Outside comments and strings, with no letter run going on, runs of lone letters
        // are passed over whole.
        while (n == 0 && !comment && !quoted && i % kRun == 0 && text.size() - i > kRun && !may_matter(text.data() + i))
            i += kRun;
        const char c = i < text.size() ? text[i] : '\n';
        const bool letter = !comment && (ascii_alpha(c) || c == '_');
        if (letter) {
            if (n < sizeof word) word[n] = ascii_upper(c);
            ++n;
            continue;
        }
        if (n > 0 && n <= sizeof word && steering(std::string_view(word, n))) return true;
        n = 0;
        if (c == '\n' || c == '\r') comment = quoted = false;
        else if (!comment && c == '"') quoted = !quoted;
        else if (!comment && !quoted && c == ';') comment = true;
        else if (!comment && c == ':') return true;  // a label, a main block number, CASE ... OF
    }
    return false;
}

}  // namespace toolcomp::sinumerik
