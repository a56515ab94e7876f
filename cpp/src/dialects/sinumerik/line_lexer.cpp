// The general lexer of one Sinumerik line: block delete and number, jump labels, and each
// statement a token (addresses with numbers or expressions, assignments, calls, control
// statements, declarations), as lexer.hpp lists them.
#include "line_lexer.hpp"

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "control_statements.hpp"
#include "frame_value.hpp"
#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/expr.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {

bool is_digit(char c) { return ascii_digit(c); }

// Statements that read an expression after them.
bool condition_keyword(std::string_view k) { return k == "IF" || k == "WHILE" || k == "UNTIL"; }
bool jump_keyword(std::string_view k) { return k == "GOTOF" || k == "GOTOB" || k == "GOTO" || k == "GOTOC"; }
// Synchronized actions run beside the program in the interpolation cycle.
bool synchronized_action(std::string_view k) { return k == "WHENEVER" || k == "WHEN" || k == "EVERY" || k == "FROM"; }

// A channel's axis or spindle name as a machine datum's index: X, Y, Z, A, B, C, U, V, W (with
// digits: X1, the machine axes), AX1, SP1, S1.
bool axis_name(std::string_view n) {
    std::size_t letters = n.size() >= 2 && (n.substr(0, 2) == "AX" || n.substr(0, 2) == "SP") ? 2
                          : !n.empty() && std::string_view("XYZABCUVWS").find(n[0]) != std::string_view::npos ? 1 : 0;
    if (letters == 0 || (n[0] == 'S' && letters == 1 && n.size() == 1)) return false;
    for (std::size_t i = letters; i < n.size(); ++i)
        if (!is_digit(n[i])) return false;
    return letters == 1 || n.size() > 2;
}

// $MA_AX_VELO_LIMIT[X], $MN_USER_DATA_INT[3]: indices that are axis names or whole numbers
// merge into the datum's name ("$MA_AX_VELO_LIMIT[X]"), the key a machine file gives it by.
void merge_machine_data_indices(expr::Expr& e) {
    for (std::size_t i = 0; i < e.code.size(); ++i) {
        const expr::Instr v = e.code[i];
        if (v.op != expr::Op::variable) continue;
        const std::string name = e.names[v.name];
        if (v.argc == 0 || i < v.argc || name.size() < 5 || name[0] != '$' ||
            (name[1] != 'M' && name[1] != 'S') || std::string_view("NCA").find(name[2]) == std::string_view::npos ||
            name[3] != '_')
            continue;
        std::string key = name + "[";
        bool merged = true;
        for (std::size_t k = i - v.argc; k < i && merged; ++k) {
            const expr::Instr& x = e.code[k];
            if (x.op == expr::Op::variable && x.argc == 0 && axis_name(e.names[x.name])) key += e.names[x.name];
            else if (x.op == expr::Op::number && x.value == std::floor(x.value) && std::fabs(x.value) < 1e9)
                key += std::to_string(static_cast<long>(x.value));
            else merged = false;
            key += k + 1 < i ? "," : "]";
        }
        if (!merged) continue;
        e.names.push_back(key);
        e.code.erase(e.code.begin() + static_cast<std::ptrdiff_t>(i - v.argc), e.code.begin() + static_cast<std::ptrdiff_t>(i));
        i -= v.argc;
        e.code[i] = expr::Instr{expr::Op::variable, 0, expr::Fn::sin, static_cast<std::uint32_t>(e.names.size() - 1), 0};
    }
}

class LineLexer {
public:
    LineLexer(std::string_view line, int line_no, Program& prog) : s_(line), line_(line_no), prog_(prog) {}

    void run() {
        skip();
        if (i_ >= s_.size()) return;
        if (s_[i_] == '%') return;  // file header "%_N_NAME_MPF"
        bool block_delete = false;
        if (s_[i_] == '/') {
            block_delete = true;
            ++i_;
            while (i_ < s_.size() && is_digit(s_[i_])) ++i_;  // /0 .. /9: skip level
        }
        skip();
        if (i_ >= s_.size() || s_[i_] == ';') {
            return;
        }
        prog_.begin_block(line_, block_delete);
        // Block number "N10" or main block ":10".
        if (i_ < s_.size() && (s_[i_] == ':' || ((s_[i_] == 'N' || s_[i_] == 'n') && i_ + 1 < s_.size() && is_digit(s_[i_ + 1])))) {
            std::size_t j = i_ + 1;
            while (j < s_.size() && is_digit(s_[j])) ++j;
            if (j == i_ + 1) error("Block number expected");
            if (j - i_ - 1 > 9) error("Block number longer than 9 digits");
            if (j >= s_.size() || !ident_char(s_[j])) {
                Token t;
                t.key = "N";
                t.value = std::stod(std::string(s_.substr(i_ + 1, j - i_ - 1)));
                t.has_value = true;
                t.column = col();
                prog_.add_token(std::move(t));
                i_ = j;
            }
        }
        skip();
        // Jump label "NAME:".
        if (i_ < s_.size() && ident_start(s_[i_])) {
            std::size_t j = i_;
            while (j < s_.size() && ident_char(s_[j])) ++j;
            if (j < s_.size() && s_[j] == ':') {
                Token t;
                t.key = ":";
                t.text = to_upper_ascii(s_.substr(i_, j - i_));
                t.column = col();
                prog_.add_token(std::move(t));
                i_ = j + 1;
            }
        }
        while (true) {
            skip();
            if (i_ >= s_.size()) break;
            if (s_[i_] == ';') {
                prog_.add_comment({std::string(s_.substr(i_ + 1)), col()});
                break;
            }
            statement();
        }
    }

private:
    [[noreturn]] void error(const std::string& msg) const { throw ParseError(code::syntax_error, msg, {line_, col()}); }
    int col() const { return static_cast<int>(i_) + 1; }
    void skip() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
    }
    std::string ident() {
        std::size_t b = i_;
        while (i_ < s_.size() && ident_char(s_[i_])) ++i_;
        return to_upper_ascii(s_.substr(b, i_ - b));
    }
    std::int32_t expression() {
        try {
            expr::Expr e = expr::parse(s_, i_, expr::sinumerik_syntax());
            rewrite_frame_components(e);
            merge_machine_data_indices(e);
            return prog_.add_expression(std::move(e));
        } catch (const expr::SyntaxError& e) {
            i_ = e.offset;
            error(e.what());
        }
    }
    // Stores a constant expression as a literal value.
    void set_value(Token& t, std::int32_t e) {
        const expr::Expr& x = prog_.expression(e);
        if (x.constant()) {
            t.value = x.code[0].value;
            t.has_value = true;
        } else {
            t.expr = e;
        }
    }
    // Text between balanced parentheses, i_ at '('; leaves i_ after ')'.
    std::string parenthesised() {
        int depth = 0;
        bool quote = false;
        std::size_t b = i_ + 1;
        for (; i_ < s_.size(); ++i_) {
            char c = s_[i_];
            if (c == '"') quote = !quote;
            if (quote) continue;
            if (c == '(') ++depth;
            if (c == ')' && --depth == 0) {
                ++i_;
                return std::string(s_.substr(b, i_ - 1 - b));
            }
        }
        error("')' expected");
    }
    bool at_assign() {
        skip();
        return i_ < s_.size() && s_[i_] == '=' && (i_ + 1 >= s_.size() || s_[i_ + 1] != '=');
    }

    // The common CAM word, an address letter and its digits ("X95", "Y2.000", "G1"), taken as
    // the general path in statement() takes it, without building the name first. Not when
    // the name goes on (X1A), or a call, an index or an assignment follows it.
    bool plain_word() {
        const std::size_t start = i_;
        if (!ascii_alpha(s_[start]) || start + 1 >= s_.size() || !is_digit(s_[start + 1])) return false;
        std::size_t j = start + 2;
        while (j < s_.size() && is_digit(s_[j])) ++j;
        if (j < s_.size() && ident_char(s_[j])) return false;
        std::size_t k = j;
        while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t')) ++k;
        if (k < s_.size() && (s_[k] == '(' || s_[k] == '[' || (s_[k] == '=' && (k + 1 >= s_.size() || s_[k + 1] != '='))))
            return false;
        std::size_t p = start + 1;
        double v = 0;
        if (!expr::read_number(s_, p, v, false)) return false;  // the general path reports it
        Token& w = prog_.new_token();
        w.column = col();
        w.key.assign(1, ascii_upper(s_[start]));
        w.value = v;
        w.has_value = true;
        w.text.assign(s_.substr(start, j - start));
        w.text[0] = w.key[0];
        i_ = p;
        return true;
    }

    void statement() {
        if (plain_word()) return;
        const int column = col();
        if (!ident_start(s_[i_])) error(std::string("Unexpected '") + s_[i_] + "'");
        const std::size_t start = i_;
        std::string name = ident();
        Token t;
        t.column = column;
        if (condition_keyword(name)) {
            t.key = name;
            t.expr = expression();
            prog_.add_token(std::move(t));
            return;
        }
        if (name == "CALL" || name == "PCALL" || name == "EXTCALL") {  // CALL "/_N_WKS_DIR/_N_PART_WPD/_N_SUB_SPF"
            skip();
            std::string target;
            if (i_ < s_.size() && s_[i_] == '"') {
                target = quoted();
                target = target.substr(1, target.size() - 2);
            } else if (i_ < s_.size() && ident_start(s_[i_])) {
                target = ident();
            }
            if (target.empty()) error("A program name or path expected after " + name);
            // The program's name: the path's last part, without the NC file system's _N_ and
            // _SPF / _MPF (_N_SUB_SPF is SUB.SPF).
            if (const auto slash = target.find_last_of("/\\"); slash != std::string::npos) target.erase(0, slash + 1);
            target = to_upper_ascii(target);
            if (target.rfind("_N_", 0) == 0) target.erase(0, 3);
            for (std::string_view ext : {"_SPF", "_MPF"})
                if (target.size() > ext.size() && target.compare(target.size() - ext.size(), ext.size(), ext) == 0)
                    target.erase(target.size() - ext.size());
            if (target.empty()) error("A program name or path expected after " + name);
            t.key = "CALL";
            t.text = std::move(target);
            prog_.add_token(std::move(t));
            return;
        }
        if (std::string_view(name) == "CASE") {  // CASE expr OF c GOTOF L ... DEFAULT GOTOF L
            t.key = "CASE";
            t.expr = expression();
            prog_.add_token(std::move(t));
            skip();
            if (i_ >= s_.size() || !ident_start(s_[i_]) || ident() != "OF") error("OF expected in CASE");
            for (;;) {
                skip();
                if (i_ >= s_.size()) return;
                Token branch;
                branch.column = col();
                if (ident_start(s_[i_])) {
                    const std::size_t save = i_;
                    if (ident() != "DEFAULT") {
                        i_ = save;
                        error("A constant or DEFAULT expected in CASE");
                    }
                    branch.param = 2;
                } else {
                    double v = 0;
                    bool negative = false;
                    if (s_[i_] == '-' || s_[i_] == '+') negative = s_[i_++] == '-';
                    if (!expr::read_number(s_, i_, v, false)) error("A constant or DEFAULT expected in CASE");
                    branch.value = negative ? -v : v;
                    branch.param = 1;
                }
                skip();
                const std::size_t b = i_;
                while (i_ < s_.size() && ident_char(s_[i_])) ++i_;
                branch.key = to_upper_ascii(s_.substr(b, i_ - b));
                if (!jump_keyword(branch.key)) error("GOTOF, GOTOB or GOTO expected in CASE");
                skip();
                const std::size_t l = i_;
                while (i_ < s_.size() && ident_char(s_[i_])) ++i_;
                if (i_ == l) error("Jump label expected after " + branch.key);
                branch.text = to_upper_ascii(s_.substr(l, i_ - l));
                prog_.add_token(std::move(branch));
            }
        }
        if (std::string_view(name) == "EXTERN") {  // EXTERN NAME(REAL, VAR INT): a declaration
            t.key = "EXTERN";
            t.text = std::string(s_.substr(i_));
            i_ = s_.size();
            prog_.add_token(std::move(t));
            return;
        }
        if (synchronized_action(name)) {  // WHENEVER ... DO ...: the rest of the line
            t.key = "SYNACT";
            t.text = name + std::string(s_.substr(i_));
            i_ = s_.size();
            prog_.add_token(std::move(t));
            return;
        }
        if (jump_keyword(name)) {
            t.key = name;
            skip();
            std::size_t b = i_;
            while (i_ < s_.size() && ident_char(s_[i_])) ++i_;
            if (i_ == b) error("Jump label expected after " + name);
            t.text = to_upper_ascii(s_.substr(b, i_ - b));
            prog_.add_token(std::move(t));
            return;
        }
        if (std::string_view(name) == "FOR") {
            skip();
            if (i_ >= s_.size() || !ident_start(s_[i_])) error("Loop variable expected after FOR");
            t.key = "FOR";
            t.text = ident();
            if (!at_assign()) error("'=' expected after the FOR variable");
            ++i_;
            t.expr = expression();
            prog_.add_token(std::move(t));
            skip();
            const int c2 = col();
            if (i_ >= s_.size() || !ident_start(s_[i_]) || ident() != "TO") error("TO expected in FOR");
            Token to;
            to.key = "TO";
            to.column = c2;
            to.expr = expression();
            prog_.add_token(std::move(to));
            return;
        }
        if (std::string_view(name) == "DEF") {
            skip();
            t.key = "DEF";
            t.text = ident();
            if (t.text.empty()) error("Type expected after DEF");
            if (t.text == "STRING") {  // STRING[n]: texts of at most n characters
                skip();
                double n = 0;
                if (i_ >= s_.size() || s_[i_] != '[') error("STRING[length] expected");
                ++i_;
                skip();
                if (!expr::read_number(s_, i_, n, false) || n < 1 || n > 200 || n != std::floor(n))
                    error("STRING length 1..200 expected");
                skip();
                if (i_ >= s_.size() || s_[i_] != ']') error("']' expected");
                ++i_;
                t.value = n;
                t.has_value = true;
            }
            prog_.add_token(std::move(t));
            for (;;) {
                skip();
                Token v;
                v.key = "DEFVAR";
                v.column = col();
                if (i_ >= s_.size() || !ident_start(s_[i_])) error("Variable name expected");
                v.text = ident();
                skip();
                if (i_ < s_.size() && s_[i_] == '[') {
                    ++i_;
                    double n = 0;
                    skip();
                    if (!expr::read_number(s_, i_, n, false) || n < 1 || n > 100000 || n != std::floor(n))
                        error("Array size 1..100000 expected");
                    v.value = n;
                    v.has_value = true;
                    skip();
                    if (i_ < s_.size() && s_[i_] == ',') {  // two dimensions [n, m]
                        ++i_;
                        skip();
                        double m2 = 0;
                        if (!expr::read_number(s_, i_, m2, false) || m2 < 1 || m2 > 100000 || m2 != std::floor(m2))
                            error("Array size 1..100000 expected");
                        v.param = static_cast<int>(m2);
                        skip();
                    }
                    if (i_ >= s_.size() || s_[i_] != ']') error("']' expected");
                    ++i_;
                }
                if (at_assign()) {
                    ++i_;
                    v.expr = expression();
                }
                prog_.add_token(std::move(v));
                skip();
                if (i_ < s_.size() && s_[i_] == ',') {
                    ++i_;
                    continue;
                }
                return;
            }
        }
        if (std::string_view(name) == "PROC") {
            skip();
            t.key = "PROC";
            t.text = ident();
            if (t.text.empty()) error("Subprogram name expected after PROC");
            skip();
            std::string args;  // the formal parameters, read when the program is called
            if (i_ < s_.size() && s_[i_] == '(') args = parenthesised();
            // Attributes after PROC: SAVE (the caller's modal G functions and frame come back at
            // the return: param 1); DISPLOF and the like do nothing to the path.
            while (i_ < s_.size() && s_[i_] != ';') {
                if (ident_char(s_[i_])) {
                    if (ident() == "SAVE") t.param = 1;
                } else {
                    ++i_;
                }
            }
            prog_.add_token(std::move(t));
            if (args.find_first_not_of(" \t") != std::string::npos) {
                Token a;
                a.key = "PROCARGS";
                a.text = std::move(args);
                a.column = column;
                prog_.add_token(std::move(a));
            }
            return;
        }
        skip();
        // Call with an argument list.
        if (i_ < s_.size() && s_[i_] == '(') {
            t.key = name;
            t.text = parenthesised();
            prog_.add_token(std::move(t));
            return;
        }
        // AX[axis]=value: the address of the axis named (an axis or an AXIS variable).
        if (name == "AX" && i_ < s_.size() && s_[i_] == '[') {
            ++i_;
            skip();
            if (i_ >= s_.size() || !ident_start(s_[i_])) error("An axis name expected in AX[...]");
            t.key = "AX";
            t.text = ident();
            skip();
            if (i_ >= s_.size() || s_[i_] != ']') error("']' expected");
            ++i_;
            if (!at_assign()) error("'=' expected after AX[...]");
            ++i_;
            address_value(t);
            prog_.add_token(std::move(t));
            return;
        }
        // Assignment to an indexed variable: NAME[i, j] = value.
        if (i_ < s_.size() && s_[i_] == '[') {
            i_ = start;
            std::int32_t target = expression();
            if (!at_assign()) error("'=' expected");
            ++i_;
            assignment_value(t, target);
            return;
        }
        if (at_assign()) {
            ++i_;
            if (is_address(name)) {
                t.key = name;
                skip();
                if (i_ < s_.size() && s_[i_] == '"') {
                    t.text = quoted();
                } else {
                    address_value(t);
                }
                prog_.add_token(std::move(t));
                return;
            }
            expr::Expr target;
            target.names.push_back(name);
            target.code.push_back(expr::Instr{expr::Op::variable, 0, expr::Fn::sin, 0, 0});
            assignment_value(t, prog_.add_expression(std::move(target)));
            return;
        }
        // NAME<number>: address and value ("X10", "G1", "X-5.5", "L10"), unless a keyword.
        std::size_t letters = 0;
        while (letters < name.size() && !is_digit(name[letters])) ++letters;
        bool keyword = false;
        if (name.size() >= kShortestDigitKeyword)
            for (std::string_view k : kDigitKeywords) keyword |= (k == name);
        bool digits_only = letters < name.size();
        for (std::size_t k = letters; k < name.size(); ++k) digits_only &= is_digit(name[k]);
        // One letter glued to its number and the next word ("G1X10Y20") splits too.
        const bool glued = letters == 1 && name.size() > 1;
        // Only an address takes a value so: a longer name ending in digits (PART12, L_39) is a
        // name, a subprogram's (the 840D's program names begin with two letters or a '_').
        const bool address = letters == 1 || is_address(std::string_view(name).substr(0, letters));
        if (!keyword && letters > 0 && address &&
            (digits_only || glued || (letters == name.size() && i_ < s_.size() && number_follows()))) {
            std::size_t p = start + letters;
            if (letters == name.size()) p = i_;
            double v = 0;
            if (!expr::read_number(s_, p, v, false)) {
                i_ = p;
                error("Bad number");
            }
            i_ = p;
            Token& w = prog_.new_token();  // filled in place (a failure later drops the block)
            w.column = column;
            w.key.assign(std::string_view(name).substr(0, letters));
            w.value = v;
            w.has_value = true;
            if (glued && !digits_only) {
                w.text = w.key;
                w.text.append(s_.substr(start + 1, p - start - 1));
            } else {
                w.text = std::move(name);
            }
            return;
        }
        // A single address letter without a value ("G1 Y" cut short): not a subprogram call,
        // whose names start with two letters.
        if (name.size() == 1 && is_address(name)) {
            i_ = start;
            error("Value expected after the address " + name);
        }
        t.key = name;
        t.text = name;
        prog_.add_token(std::move(t));
    }

    bool number_follows() const {
        std::size_t j = i_;
        if (j < s_.size() && (s_[j] == '-' || s_[j] == '+')) ++j;
        if (j < s_.size() && s_[j] == '.') ++j;
        return j < s_.size() && is_digit(s_[j]);
    }

    std::string quoted() {
        std::size_t b = ++i_;
        while (i_ < s_.size() && s_[i_] != '"') ++i_;
        if (i_ >= s_.size()) error("Closing '\"' missing");
        ++i_;
        return "\"" + std::string(s_.substr(b, i_ - 1 - b)) + "\"";
    }

    // The value of an address: an expression, AC(...) or IC(...); of a rotary axis A, B, C
    // also DC(...), ACP(...), ACN(...) (param 1 AC, 2 IC, 3 DC, 4 ACP, 5 ACN).
    void address_value(Token& t) {
        skip();
        std::size_t save = i_;
        if (i_ < s_.size() && ident_start(s_[i_])) {
            std::string mod = ident();
            skip();
            const bool rotary = t.key == "A" || t.key == "B" || t.key == "C";
            const bool modulo = mod == "DC" || mod == "ACP" || mod == "ACN";
            if (i_ < s_.size() && s_[i_] == '(' && (mod == "AC" || mod == "IC" || (modulo && rotary))) {
                ++i_;
                std::int32_t e = expression();
                skip();
                if (i_ >= s_.size() || s_[i_] != ')') error("')' expected");
                ++i_;
                t.param = mod == "AC" ? 1 : mod == "IC" ? 2 : mod == "DC" ? 3 : mod == "ACP" ? 4 : 5;
                set_value(t, e);
                return;
            }
            if (i_ < s_.size() && s_[i_] == '(' && (modulo || mod == "CAC" || mod == "CIC" ||
                                                    mod == "CACP" || mod == "CACN" || mod == "CDC")) {
                i_ = save;
                throw ParseError(code::unsupported_word,
                                 mod + (modulo ? "() positions rotary axes (A, B, C), not " + t.key
                                               : "() positioning of rotary axes is not supported by toolcomp"),
                                 {line_, col()});
            }
            i_ = save;
        }
        set_value(t, expression());
    }

    void assignment_value(Token& t, std::int32_t target) {
        skip();
        std::size_t save = i_;
        if (i_ < s_.size() && ident_start(s_[i_])) {
            std::string fn = ident();
            skip();
            if (is_value_call(fn) && i_ < s_.size() && s_[i_] == '(') {
                t.key = fn;
                t.text = parenthesised();
                t.param = target + 1;
                prog_.add_token(std::move(t));
                return;
            }
            i_ = save;
        }
        t.key = "=";
        t.param = target;
        if (whole_frame(prog_.expression(target))) {  // $P_UIFR[1] = CTRANS(X, 10) : CROT(Z, 30)
            t.key = "FRAME=";
            t.text = frame_text();
            prog_.add_token(std::move(t));
            return;
        }
        if (i_ < s_.size() && s_[i_] == '"') {  // text data ($TC_CARR23[1]="P", NAME="ABC")
            const std::size_t save = i_;
            t.text = quoted();
            skip();
            if (i_ + 1 >= s_.size() || s_[i_] != '<' || s_[i_ + 1] != '<') {
                prog_.add_token(std::move(t));
                return;
            }
            i_ = save;  // "T" << R1: a string expression
            t.text.clear();
        }
        t.expr = expression();
        t.param = target;
        prog_.add_token(std::move(t));
    }

    static bool whole_frame(const expr::Expr& target) {
        const expr::Instr& v = target.code.back();
        return v.op == expr::Op::variable && frame_indices(target.names[v.name]) == v.argc;
    }
    // A frame expression's text: terms (a frame function's call, a frame variable with its
    // indices) joined by ':'; the interpreter reads it when the block runs.
    std::string frame_text() {
        std::string out;
        for (;;) {
            skip();
            const std::size_t b = i_;
            if (i_ >= s_.size() || !ident_start(s_[i_])) error("A frame (CTRANS(...), $P_UIFR[n], ...) expected");
            ident();
            skip();
            if (i_ < s_.size() && s_[i_] == '[') {
                while (i_ < s_.size() && s_[i_] != ']') ++i_;
                if (i_ >= s_.size()) error("']' expected");
                ++i_;
            } else if (i_ < s_.size() && s_[i_] == '(') {
                parenthesised();
            }
            out += std::string(s_.substr(b, i_ - b));
            skip();
            if (i_ >= s_.size() || s_[i_] != ':') return out;
            out += ':';
            ++i_;
        }
    }

    std::string_view s_;
    std::size_t i_ = 0;
    int line_;
    Program& prog_;
};

}  // namespace

void lex_line(std::string_view line, int line_no, Program& prog) { LineLexer(line, line_no, prog).run(); }

}  // namespace toolcomp::sinumerik
