// may_steer: a byte scan (no parsing) for what makes a program's blocks depend on each
// other beyond the modal state: any letter O outside a parenthesised comment, or M99.
#include <cctype>

#include "toolcomp/dialects/iso/lexer.hpp"

namespace toolcomp::iso {

bool may_steer(std::string_view text) {
    bool comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
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
            if (value == 99) return true;
        }
    }
    return false;
}

}  // namespace toolcomp::iso
