#pragma once
// Text a front end or table reader receives: a UTF-8 byte order mark (editors on Windows
// write one) is not part of the first line.
#include <string_view>

namespace toolcomp {

inline std::string_view skip_bom(std::string_view text) {
    if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
        static_cast<unsigned char>(text[2]) == 0xBF)
        text.remove_prefix(3);
    return text;
}

}  // namespace toolcomp
