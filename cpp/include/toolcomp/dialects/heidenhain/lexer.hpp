#pragma once
// Front end for Heidenhain conversational (Klartext) programs, TNC 426 era.
//
// A block per line: an optional block number, then a function (L, C, CC, CR, CT, RND, CHF,
// LP, CP, TOOL DEF, TOOL CALL, APPR .., DEP .., BLK FORM, BEGIN/END PGM ...) and its words.
// Words are letters with an optional signed number (X+10, IX-5, DR-, RL, FMAX, F100, M3,
// LEN15, CCA180); a decimal comma is read as a point; ';' starts a comment; a '*' block is a
// structure block (kept as a comment). Lines after END PGM are not part of the program.
#include <string>
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::heidenhain {

Program parse(std::string_view text, std::string name = "<string>", bool strict = true);

}  // namespace toolcomp::heidenhain
