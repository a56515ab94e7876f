#pragma once
// Text a front end or table reader receives: a UTF-8 byte order mark (editors on Windows
// write one) is not part of the first line. Letters, digits and blanks of programs and
// tables are ASCII whatever the process's locale: std::isalpha & co. take the locale's, and
// Python sets it from the environment (in a Latin-1 locale the bytes of a UTF-8 'é' are
// letters). The readers use these instead (tests/python/test_locale.py).
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

namespace toolcomp {

// Line ends ('\n') in a text, in a loop the compiler vectorises (std::count is not): per
// 4 kB a 32-bit sum the compiler keeps in vector lanes.
inline std::size_t line_ends(std::string_view text) {
    std::size_t n = 0;
    for (std::size_t from = 0; from < text.size(); from += 4096) {
        std::uint32_t ends = 0;
        const std::size_t to = from + 4096 < text.size() ? from + 4096 : text.size();
        for (std::size_t i = from; i < to; ++i) ends += text[i] == '\n';
        n += ends;
    }
    return n;
}

// Writes each line-ending CR of text[0, n) as LF: a run of CRs followed by LF stays (one line
// end, the CRs blanks), a run of CRs followed by anything else becomes that many LFs. A run
// at the end of the text is decided only when `at_end` (more text may bring its LF).
// Returns the length of the part decided: from there on, call again with more text.
inline std::size_t cr_line_ends_to_lf(char* text, std::size_t n, bool at_end) {
    for (std::size_t i = 0; i < n; ++i) {
        const void* cr = std::memchr(text + i, '\r', n - i);
        if (!cr) return n;
        i = static_cast<std::size_t>(static_cast<const char*>(cr) - text);
        std::size_t j = i;
        while (j < n && text[j] == '\r') ++j;
        if (j == n && !at_end) return i;
        if (j == n || text[j] != '\n')
            for (std::size_t k = i; k < j; ++k) text[k] = '\n';
        i = j - 1;
    }
    return n;
}
// Whether text holds a CR that is not part of a CR...LF line end.
inline bool has_lone_cr(std::string_view text) {
    for (std::size_t i = text.find('\r'); i != std::string_view::npos; i = text.find('\r', i)) {
        std::size_t j = i;
        while (j < text.size() && text[j] == '\r') ++j;
        if (j == text.size() || text[j] != '\n') return true;
        i = j;
    }
    return false;
}

inline std::string_view skip_bom(std::string_view text) {
    if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
        static_cast<unsigned char>(text[2]) == 0xBF)
        text.remove_prefix(3);
    return text;
}

// The shortest text that reads back as v (1.5, 12, 1e+20), for messages quoting a value.
inline std::string shortest_number(double v) {
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// v as C's printf writes it with `format`, one conversion of a double ("%f", "%.1f"): how
// controls write numbers into text (LinuxCNC's DEBUG values, its M72 restore).
inline std::string printf_number(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

constexpr bool ascii_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool ascii_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
constexpr bool ascii_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }  // the C locale's isspace
constexpr char ascii_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }
constexpr char ascii_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }
// A name in an expression or a Sinumerik program: a letter, '_' or '$', then those or digits.
constexpr bool ident_start(char c) { return ascii_alpha(c) || c == '_' || c == '$'; }
constexpr bool ident_char(char c) { return ident_start(c) || ascii_digit(c); }
inline std::string to_upper_ascii(std::string_view s) {
    std::string r(s);
    for (char& c : r) c = ascii_upper(c);
    return r;
}

}  // namespace toolcomp
