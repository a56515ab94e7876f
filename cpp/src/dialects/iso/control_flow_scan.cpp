// has_control_flow: a byte scan (no parsing) for what makes a program's blocks depend on each
// other beyond the modal state: any letter O outside a parenthesised comment, M99, or a P
// on a line with G70-G73 (a lathe cycle reading the blocks N<P> .. N<Q>).
#include <algorithm>
#include <cstddef>

#include "toolcomp/dialects/iso/lexer.hpp"

#include "codes.hpp"

namespace toolcomp::iso {

namespace {
// Whether a run of 32 bytes holds a byte that can matter outside a comment: one that opens a
// comment or an O or M word. The loop is one the compiler vectorises; most lines of a CAM
// program have none of them.
constexpr std::size_t kRun = 32;
bool has_special(const char* p) {
    unsigned any = 0;
    for (std::size_t k = 0; k < kRun; ++k) {
        const unsigned char c = static_cast<unsigned char>(p[k]);
        any |= static_cast<unsigned>(c == '(') | (c == 'O') | (c == 'o') | (c == 'M') | (c == 'm') | (c == 'P') |
               (c == 'p');
    }
    return any != 0;
}
// Whether the line around text[i] has G70, G71, G72 or G73 (blanks and leading zeros
// allowed: G 71, G071).
bool line_has_contour_cycle(std::string_view text, std::size_t i) {
    std::size_t b = text.rfind('\n', i);
    b = b == std::string_view::npos ? 0 : b + 1;
    const std::size_t e = std::min(text.find('\n', i), text.size());
    for (std::size_t k = b; k < e; ++k) {
        if (text[k] != 'G' && text[k] != 'g') continue;
        std::size_t j = k + 1;
        while (j < e && (text[j] == ' ' || text[j] == '\t' || text[j] == '0')) ++j;
        if (j < e && text[j] == '7' && j + 1 < e && text[j + 1] >= '0' && text[j + 1] <= '3' &&
            (j + 2 >= e || text[j + 2] < '0' || text[j + 2] > '9'))
            return true;
    }
    return false;
}
}  // namespace

bool has_control_flow(std::string_view text) {
    bool comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        // Outside a comment, runs without such a byte are passed over whole.
        while (!comment && i % kRun == 0 && text.size() - i >= kRun && !has_special(text.data() + i)) i += kRun;
        if (i >= text.size()) break;
        const char c = text[i];
        if (c == '\n') {
            comment = false;  // a comment ends at the end of its line
        } else if (comment) {
            comment = c != ')';
        } else if (c == '(') {
            comment = true;
        } else if (c == 'O' || c == 'o') {
            return true;
        } else if (c == 'M' || c == 'm') {
            // M, blanks and leading zeros allowed between the digits: M99, M 9 9, M099.
            long value = 0;
            std::size_t j = i + 1;
            for (; j < text.size(); ++j) {
                const char d = text[j];
                if (d == ' ' || d == '\t') continue;
                if (d < '0' || d > '9' || value > 1000) break;
                value = value * 10 + (d - '0');
            }
            if (value * 10 == M99) return true;
        } else if ((c == 'P' || c == 'p') && line_has_contour_cycle(text, i)) {
            return true;
        }
    }
    return false;
}

}  // namespace toolcomp::iso
