#pragma once
// Diagnostic codes by name (code::arc_too_many_turns), from the one catalogue codes.inc.
#include <span>

#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

namespace code {
#define TOOLCOMP_CODE(name, code_text, kind, severity, alarm, text) inline constexpr char name[] = code_text;
#include "toolcomp/program/codes.inc"
#undef TOOLCOMP_CODE
}  // namespace code

struct CodeInfo {
    const char* code;
    ErrorKind kind;
    Severity severity;
    const char* alarm;  // the control's alarm number, "" when the code is toolcomp's
    const char* text;   // its message, <what the block gives> in angle brackets
};

// Every row of the catalogue, in its order.
std::span<const CodeInfo> code_catalogue();

}  // namespace toolcomp
