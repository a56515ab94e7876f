// The statements of ISO programs that compute: parameter assignments (#1 = ..., #<name> =
// ...), LinuxCNC O-words (o100 sub / call / if / while / do / repeat ...), Fanuc Macro B
// (O1000 program numbers, IF [..] GOTO n, IF [..] THEN, WHILE [..] DO m, END m, GOTO n).
// Their meaning is the interpreter's (flow.cpp); here they are only read.
#include <string>

#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

#include "line_lexer.hpp"

namespace toolcomp::iso {

namespace {
bool digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

const expr::Syntax& LineLexer::syntax() const {
    return prog_.dialect == Dialect::fanuc ? expr::fanuc_syntax() : expr::linuxcnc_syntax();
}

std::int32_t LineLexer::expression(bool value_only) {
    if (at_end() || s_[i_] == '(' || s_[i_] == ';') fail(code::bad_expression, "Expression expected");
    std::size_t pos = i_;
    try {
        expr::Expr e = value_only ? expr::parse_value(s_, pos, syntax()) : expr::parse(s_, pos, syntax());
        i_ = pos;
        return prog_.add_expression(std::move(e));
    } catch (const expr::SyntaxError& e) {
        fail_at(code::bad_expression, e.what(), e.offset);
    }
}

// A Fanuc macro word, or its abbreviation: its first two letters (WH for WHILE, GO for GOTO,
// TH for THEN, EN for END), as the control takes them.
bool LineLexer::macro_word(std::string_view k) {
    return keyword(k) || keyword(k.substr(0, 2));
}

bool LineLexer::keyword(std::string_view k) {
    if (s_.size() - i_ < k.size()) return false;
    for (std::size_t j = 0; j < k.size(); ++j)
        if (ascii_upper(s_[i_ + j]) != k[j]) return false;
    i_ += k.size();
    return true;
}

void LineLexer::rest_is_comments() {
    while (!at_end()) {
        if (s_[i_] == '(') {
            comment_paren();
        } else if (s_[i_] == ';') {
            prog_.add_comment({s_.substr(i_ + 1), col(), true});
            return;
        } else {
            fail(code::o_word_extra_words, prog_.dialect == Dialect::linuxcnc ? "Unexpected character after O-word"
                                                                           : "Unexpected text after the macro statement");
        }
    }
}

void LineLexer::assignment() {
    Statement st;
    st.kind = Stmt::assign;
    st.column = col();
    ++i_;  // '#'
    if (!at_end() && s_[i_] == '<' && prog_.dialect == Dialect::linuxcnc) {
        const std::size_t open = i_;
        while (i_ < s_.size() && s_[i_] != '>') ++i_;
        if (at_end()) fail_at(code::bad_parameter, "Named parameter not terminated", open);
        for (std::size_t k = open + 1; k < i_; ++k)
            st.label.push_back(ascii_lower(s_[k]));
        ++i_;
        if (st.label.empty()) fail_at(code::bad_parameter, "Named parameter with no name", open);
    } else {
        st.target = expression(true);  // the number: 5, #2, [#1+1]
    }
    if (at_end() || s_[i_] != '=') fail(code::equal_sign_missing, "Equal sign missing in parameter setting");
    ++i_;
    st.value = expression(prog_.dialect == Dialect::linuxcnc);
    prog_.add_statement(std::move(st));
}

void LineLexer::o_word() {
    Statement st;
    st.column = col();
    ++i_;  // 'O'
    if (prog_.dialect == Dialect::fanuc) {
        // A Fanuc program number: O and up to 4 (8 on later controls) digits.
        std::string n;
        while (!at_end() && digit(s_[i_])) n.push_back(s_[i_++]);
        if (n.empty() || n.size() > 8) fail_at(code::bad_program_number, "Program number expected after O", i_ - 1);
        st.kind = Stmt::program_number;
        st.label = std::to_string(std::stol(n));
        prog_.add_statement(std::move(st));
        rest_is_comments();
        return;
    }
    if (!at_end() && s_[i_] == '<') {
        const std::size_t open = i_;
        while (i_ < s_.size() && s_[i_] != '>') ++i_;
        if (at_end()) fail_at(code::bad_o_word, "O-word name not terminated", open);
        st.label = "<";
        for (std::size_t k = open + 1; k < i_; ++k)
            st.label.push_back(ascii_lower(s_[k]));
        st.label += ">";
        ++i_;
        if (st.label.size() == 2) fail_at(code::bad_o_word, "O-word name is empty", open);
    } else if (!at_end() && (s_[i_] == '#' || s_[i_] == '[') && prog_.dialect == Dialect::linuxcnc) {
        st.target = expression(true);  // a computed number ("o#1 call"): worked out when the block runs
    } else {
        std::string n;
        while (!at_end() && digit(s_[i_])) n.push_back(s_[i_++]);
        if (n.empty()) fail(code::bad_o_word, "O-word number or <name> expected");
        std::size_t z = n.find_first_not_of('0');
        st.label = z == std::string::npos ? "0" : n.substr(z);
    }
    struct Kw {
        std::string_view text;
        Stmt kind;
    };
    // Longest first where one spelling starts another.
    static constexpr Kw kWords[] = {
        {"ENDSUB", Stmt::o_endsub},       {"ENDWHILE", Stmt::o_endwhile}, {"ENDREPEAT", Stmt::o_endrepeat},
        {"ENDIF", Stmt::o_endif},         {"ELSEIF", Stmt::o_elseif},     {"ELSE", Stmt::o_else},
        {"SUB", Stmt::o_sub},             {"CALL", Stmt::o_call},         {"RETURN", Stmt::o_return},
        {"IF", Stmt::o_if},               {"WHILE", Stmt::o_while},       {"DO", Stmt::o_do},
        {"REPEAT", Stmt::o_repeat},       {"BREAK", Stmt::o_break},       {"CONTINUE", Stmt::o_continue},
    };
    const Kw* found = nullptr;
    for (const Kw& k : kWords)
        if (keyword(k.text)) {
            found = &k;
            break;
        }
    if (!found) {
        // A bare O<n> (with a comment at most) opens a Fanuc-style numbered subprogram on
        // LinuxCNC 2.9 (O<n> ... M99, called with M98).
        std::size_t k = i_;
        while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t')) ++k;
        if (prog_.dialect != Dialect::linuxcnc || !(k >= s_.size() || s_[k] == '(' || s_[k] == ';') || st.target >= 0)
            fail(code::unknown_control_command, "Unknown control command in o word");
        st.kind = Stmt::program_number;
        prog_.add_statement(std::move(st));
        rest_is_comments();
        return;
    }
    st.kind = found->kind;
    // Structures are matched by their labels before the program runs: a computed number only
    // names the subroutine a call runs.
    if (st.target >= 0 && st.kind != Stmt::o_call)
        fail(code::unsupported_o_word, "A computed O-word number is supported by toolcomp with call only");
    st.text = std::string(raw_.substr(0, raw_.find_last_not_of("\r") + 1));
    auto bracket = [&](bool required) {
        if (!at_end() && s_[i_] == '[') return expression(true);
        if (required) {
            std::string k(found->text);
            for (char& c : k) c = ascii_lower(c);
            fail(code::o_word_missing_expression, "Left bracket missing after '" + k + "'");
        }
        return -1;
    };
    switch (st.kind) {
        case Stmt::o_if: case Stmt::o_elseif: case Stmt::o_while: case Stmt::o_repeat:
            st.value = bracket(true);
            break;
        case Stmt::o_return: case Stmt::o_endsub:
            st.value = bracket(false);
            break;
        case Stmt::o_call:
            // LinuxCNC reads comments between the arguments: o<s> call [1] (first) [2].
            for (;;) {
                while (!at_end() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
                if (!at_end() && s_[i_] == '(') {
                    comment_paren();
                    continue;
                }
                if (at_end() || s_[i_] != '[') break;
                if (st.args.size() == 30) fail(code::too_many_arguments, "Too many subroutine parameters");
                st.args.push_back(expression(true));
            }
            break;
        default:
            break;
    }
    prog_.add_statement(std::move(st));
    rest_is_comments();
}

bool LineLexer::fanuc_statement() {
    Statement st;
    st.column = col();
    const std::size_t start = i_;
    auto condition = [&] {
        if (at_end() || s_[i_] != '[') fail(code::bad_macro_statement, "'[' expected before the condition");
        return expression(true);
    };
    auto loop_number = [&] {
        std::string n;
        while (!at_end() && digit(s_[i_])) n.push_back(s_[i_++]);
        if (n.empty() || n.size() > 3) fail(code::bad_macro_statement, "Loop identification number expected");
        return static_cast<std::int32_t>(std::stol(n));
    };
    if (keyword("IF") && !at_end() && s_[i_] == '[') {
        st.value = condition();
        if (macro_word("GOTO")) {
            st.kind = Stmt::if_goto;
            st.target = expression(true);
            prog_.add_statement(std::move(st));
            rest_is_comments();
            return true;
        }
        if (macro_word("THEN")) {
            st.kind = Stmt::if_then;
            prog_.add_statement(std::move(st));
            first_word_ = false;
            return true;
        }
        fail(code::bad_macro_statement, "GOTO or THEN expected after the IF condition");
    }
    i_ = start;
    if (macro_word("WHILE") && !at_end() && s_[i_] == '[') {
        st.value = condition();
        if (!keyword("DO")) fail(code::bad_macro_statement, "DO expected after the WHILE condition");
        st.kind = Stmt::while_do;
        st.loop = loop_number();
        prog_.add_statement(std::move(st));
        rest_is_comments();
        return true;
    }
    i_ = start;
    if (macro_word("END") && !at_end() && digit(s_[i_])) {
        st.kind = Stmt::end_loop;
        st.loop = loop_number();
        prog_.add_statement(std::move(st));
        rest_is_comments();
        return true;
    }
    i_ = start;
    if (macro_word("GOTO")) {
        st.kind = Stmt::goto_n;
        st.target = expression(true);
        prog_.add_statement(std::move(st));
        rest_is_comments();
        return true;
    }
    i_ = start;
    return false;
}

}  // namespace toolcomp::iso
