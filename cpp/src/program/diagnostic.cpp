#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

std::string without_nul(const std::string& message) {
    std::string out;
    out.reserve(message.size() + 8);
    for (char c : message) {
        if (c == '\0')
            out += "\\x00";
        else
            out += c;
    }
    return out;
}

void throw_at(const Error& e, const SourcePos& pos) {
    switch (e.kind()) {
        case ErrorKind::parse: throw ParseError(e.code(), e.what(), pos);
        case ErrorKind::compensation: throw CompensationError(e.code(), e.what(), pos);
        case ErrorKind::tool_table: throw ToolTableError(e.code(), e.what(), pos);
        default: throw ProgramError(e.code(), e.what(), pos);
    }
}

}  // namespace toolcomp
