#pragma once
// Front end for ISO word-address G-code (LinuxCNC RS274NGC and Fanuc-style).
//
// Syntax rules (LinuxCNC's): words in any order and case; spaces and tabs anywhere outside
// comments (also inside numbers: "X 1 0 . 5" is X10.5); "( )" and ";" comments; "/" block
// delete; N line numbers first in a block; a "%" line delimits the program (text after the
// closing "%" is not part of it); blank lines and CRLF line ends are fine.
#include <string>
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::iso {

// strict: throws ParseError (code, message, line, column) on the first syntax error.
// Otherwise the blocks before it are kept and the error is stored in Program::syntax_error.
Program parse(std::string_view text, Dialect dialect, std::string name = "<string>", bool strict = true);

}  // namespace toolcomp::iso
