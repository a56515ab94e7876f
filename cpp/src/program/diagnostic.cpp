#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

void throw_at(const Error& e, const SourcePos& pos) {
    switch (e.kind()) {
        case ErrorKind::parse: throw ParseError(e.code(), e.what(), pos);
        case ErrorKind::compensation: throw CompensationError(e.code(), e.what(), pos);
        case ErrorKind::tool_table: throw ToolTableError(e.code(), e.what(), pos);
        default: throw ProgramError(e.code(), e.what(), pos);
    }
}

}  // namespace toolcomp
