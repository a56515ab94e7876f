#pragma once
// Splitting a file into lines with their own line endings, so they can be written back
// exactly (private to cpp/src/tools).
#include <string>
#include <string_view>
#include <vector>

namespace toolcomp::tables {

struct TextLine {
    std::string text;  // without the line ending
    std::string eol;   // "\n", "\r\n" or "" (last line without one)
};

inline std::vector<TextLine> split_lines(std::string_view s) {
    std::vector<TextLine> out;
    std::size_t pos = 0;
    while (pos < s.size()) {
        const std::size_t nl = s.find('\n', pos);
        if (nl == std::string_view::npos) {
            out.push_back({std::string(s.substr(pos)), ""});
            break;
        }
        std::size_t end = nl;
        if (end > pos && s[end - 1] == '\r') --end;
        out.push_back({std::string(s.substr(pos, end - pos)), std::string(s.substr(end, nl + 1 - end))});
        pos = nl + 1;
    }
    return out;
}

}  // namespace toolcomp::tables
