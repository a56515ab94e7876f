#pragma once
// Splitting a file into lines with their own line endings, so they can be written back
// exactly (private to cpp/src/tools). A line ends with "\n" (Unix), "\r\n" (Windows) or a
// lone "\r" (classic Mac OS, and some older DNC transfer programs).
#include <string>
#include <string_view>
#include <vector>

namespace toolcomp::tables {

struct TextLine {
    std::string text;  // without the line ending
    std::string eol;   // "\n", "\r\n", "\r" (see line_end_length) or "" (last line without one)
};

// Length of the line ending that starts at s[i], 0 when s[i] does not end a line (or i is
// past the end). "\r\n" is one line ending, and so is "\r\r\n" (a file converted to CRLF
// twice): CRs right before a "\n" belong to it. Any other "\r" ends a line by itself.
inline std::size_t line_end_length(std::string_view s, std::size_t i) {
    if (i >= s.size()) return 0;
    if (s[i] == '\n') return 1;
    if (s[i] != '\r') return 0;
    std::size_t j = i;
    while (j < s.size() && s[j] == '\r') ++j;
    return j < s.size() && s[j] == '\n' ? j + 1 - i : 1;
}

// Whether text written so far ends with a complete line (or is empty).
inline bool ends_with_line_end(std::string_view s) { return s.empty() || s.back() == '\n' || s.back() == '\r'; }

inline std::vector<TextLine> split_lines(std::string_view s) {
    std::vector<TextLine> out;
    std::size_t pos = 0;
    while (pos < s.size()) {
        const std::size_t end = s.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) {
            out.push_back({std::string(s.substr(pos)), ""});
            break;
        }
        const std::size_t n = line_end_length(s, end);
        out.push_back({std::string(s.substr(pos, end - pos)), std::string(s.substr(end, n))});
        pos = end + n;
    }
    return out;
}

}  // namespace toolcomp::tables
