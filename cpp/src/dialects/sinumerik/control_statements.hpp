#pragma once
// The statements that steer a Sinumerik program when they begin a block (after its number and
// label), named once: the lexer marks a program that has one (Program::control_statements),
// and the interpreter indexes the structure of such a program before it runs it (interp.cpp).
#include <cstdint>
#include <span>
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::sinumerik {

enum Ctl : std::uint8_t { ctl_none, ctl_if, ctl_else, ctl_endif, ctl_while, ctl_endwhile, ctl_for, ctl_endfor,
                          ctl_repeat, ctl_until, ctl_loop, ctl_endloop, ctl_jump,
                          ctl_section };  // REPEAT label [label] P=n, REPEATB label P=n

// The structure statement a block's first statement names (jumps and sections are told from
// the whole block: interp.cpp).
inline Ctl ctl_of(std::string_view k) {
    if (k == "IF") return ctl_if;
    if (k == "ELSE") return ctl_else;
    if (k == "ENDIF") return ctl_endif;
    if (k == "WHILE") return ctl_while;
    if (k == "ENDWHILE") return ctl_endwhile;
    if (k == "FOR") return ctl_for;
    if (k == "ENDFOR") return ctl_endfor;
    if (k == "REPEAT") return ctl_repeat;
    if (k == "UNTIL") return ctl_until;
    if (k == "LOOP") return ctl_loop;
    if (k == "ENDLOOP") return ctl_endloop;
    return ctl_none;
}

// Whether a block whose first statement is `k` steers: a structure statement, REPEATB, CASE,
// PROC, or any name that starts with GOTO (as the interpreter takes them: GOTOS too).
inline bool is_control_statement(std::string_view k) {
    return ctl_of(k) != ctl_none || k == "REPEATB" || k == "CASE" || k == "PROC" || k.starts_with("GOTO");
}

// The statements of a block from its first, after its number and label.
inline std::span<const Token> statements(std::span<const Token> t) {
    std::size_t i = 0;
    while (i < t.size() && (t[i].is("N") || t[i].is(":"))) ++i;
    return t.subspan(i);
}

}  // namespace toolcomp::sinumerik
