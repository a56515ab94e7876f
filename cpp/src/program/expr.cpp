#include "toolcomp/program/expr.hpp"
#include "toolcomp/program/decimal.hpp"
#include "toolcomp/program/text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "toolcomp/geometry/vec.hpp"

namespace toolcomp::expr {

namespace {

constexpr int kMaxDepth = 200;

struct FnName {
    std::string_view name;
    Fn fn;
    int min_args, max_args;
    std::uint8_t families;
};
constexpr std::uint8_t S = family_sinumerik, L = family_linuxcnc, F = family_fanuc;
constexpr FnName kFunctions[] = {
    {"SIN", Fn::sin, 1, 1, S | L | F},      {"COS", Fn::cos, 1, 1, S | L | F},
    {"TAN", Fn::tan, 1, 1, S | L | F},      {"ASIN", Fn::asin, 1, 1, S | L | F},
    {"ACOS", Fn::acos, 1, 1, S | L | F},    {"ATAN2", Fn::atan2, 2, 2, S},
    {"SQRT", Fn::sqrt, 1, 1, S | L | F},    {"ABS", Fn::abs, 1, 1, S | L | F},
    {"EXP", Fn::exp, 1, 1, S | L | F},      {"LN", Fn::ln, 1, 1, S | L | F},
    {"ROUND", Fn::round, 1, 1, S | L | F},  {"TRUNC", Fn::trunc, 1, 1, S},
    {"ROUNDUP", Fn::roundup, 1, 1, S},      {"POT", Fn::square, 1, 1, S},
    {"MINVAL", Fn::minval, 2, 2, S},        {"MAXVAL", Fn::maxval, 2, 2, S},
    {"BOUND", Fn::bound, 3, 3, S},          {"FIX", Fn::floor, 1, 1, L},
    {"FUP", Fn::ceil, 1, 1, L},             {"FIX", Fn::trunc, 1, 1, F},
    {"FUP", Fn::away, 1, 1, F},
    {"STRLEN", Fn::strlen, 1, 1, S},        {"INDEX", Fn::index, 2, 2, S},
    {"RINDEX", Fn::rindex, 2, 2, S},        {"SUBSTR", Fn::substr, 2, 3, S},
    {"TOUPPER", Fn::toupper, 1, 1, S},      {"TOLOWER", Fn::tolower, 1, 1, S},
    {"NUMBER", Fn::number, 1, 1, S},        {"ISNUMBER", Fn::isnumber, 1, 1, S},
    {"AXNAME", Fn::axname, 1, 1, S},        {"AXSTRING", Fn::axstring, 1, 1, S},
};
const FnName* find_function(const std::string& name, std::uint8_t family) {
    for (const FnName& k : kFunctions)
        if (k.name == name && (k.families & family)) return &k;
    return nullptr;
}

class Parser {
public:
    Parser(std::string_view t, std::size_t pos, const Syntax& s) : t_(t), p_(pos), s_(s) {}
    Expr run() {
        expression(0, 0);
        return std::move(e_);
    }
    Expr run_value() {
        unary(0);
        return std::move(e_);
    }
    std::size_t pos() const { return p_; }

private:
    [[noreturn]] void error(const std::string& m) const { throw SyntaxError(m, p_); }
    void blanks() {
        while (p_ < t_.size() && (t_[p_] == ' ' || t_[p_] == '\t')) ++p_;
    }
    // A word operator matches a whole identifier only; a symbol operator matches its text.
    bool matches(std::string_view spelling) const {
        if (t_.size() - p_ < spelling.size()) return false;
        for (std::size_t i = 0; i < spelling.size(); ++i)
            if (ascii_upper(t_[p_ + i]) != spelling[i]) return false;
        // (ISO controls read lines without blanks: "[#3LT3]" has the operator LT.)
        if (ident_start(spelling[0]) && !s_.hash_parameters) {
            std::size_t end = p_ + spelling.size();
            if (end < t_.size() && ident_char(t_[end])) return false;
        }
        return true;
    }
    void emit(Op op, std::uint8_t argc = 0) { e_.code.push_back(Instr{op, argc, Fn::sin, 0, 0}); }

    void expression(int min_prec, int depth) {
        if (depth > kMaxDepth) error("Expression nested too deeply");
        unary(depth + 1);
        for (;;) {
            std::size_t save = p_;
            blanks();
            const BinaryOp* best = nullptr;
            for (const BinaryOp& b : s_.binary)
                if (matches(b.spelling) && (!best || b.spelling.size() > best->spelling.size())) best = &b;
            if (!best || best->precedence < min_prec) {
                p_ = save;
                return;
            }
            p_ += best->spelling.size();
            expression(best->precedence + 1, depth + 1);
            emit(best->op);
            if (best->op == Op::concat) e_.uses_text = true;
        }
    }

    void unary(int depth) {
        if (depth > kMaxDepth) error("Expression nested too deeply");
        blanks();
        if (p_ >= t_.size()) error("Expression expected");
        char c = t_[p_];
        if (c == '-' || c == '+') {
            ++p_;
            unary(depth + 1);
            if (c == '-') emit(Op::neg);
            return;
        }
        if (c == '#' && s_.hash_parameters) {
            parameter(depth + 1);
            return;
        }
        if (s_.unary_not && matches("NOT")) {
            p_ += 3;
            unary(depth + 1);
            emit(Op::logical_not);
            return;
        }
        if (s_.unary_not && matches("B_NOT")) {
            p_ += 5;
            unary(depth + 1);
            emit(Op::bit_not);
            return;
        }
        primary(depth);
    }

    void primary(int depth) {
        char c = t_[p_];
        double v;
        if (c == '\'' && s_.family == family_sinumerik) {  // 'B0101' binary, 'H1F' hexadecimal (840D)
            const std::size_t end = t_.find('\'', p_ + 1);
            if (end == std::string_view::npos || end < p_ + 3) error("Constant 'B...' or 'H...' expected");
            const char base = ascii_upper(t_[p_ + 1]);
            const std::string_view digits = t_.substr(p_ + 2, end - p_ - 2);
            if (base != 'B' && base != 'H') error("Constant 'B...' or 'H...' expected");
            if (digits.size() > (base == 'B' ? 32u : 8u))
                error(base == 'B' ? "Binary constant longer than 32 bits" : "Hexadecimal constant longer than 8 digits");
            std::uint64_t n = 0;
            for (char d : digits) {
                const int x = base == 'B' ? (d == '0' || d == '1' ? d - '0' : -1)
                              : ascii_digit(d)         ? d - '0'
                              : ascii_upper(d) >= 'A' && ascii_upper(d) <= 'F' ? ascii_upper(d) - 'A' + 10
                                                                             : -1;
                if (x < 0) error(std::string("Bad digit '") + d + "' in a constant");
                n = n * (base == 'B' ? 2 : 16) + static_cast<std::uint64_t>(x);
            }
            p_ = end + 1;
            e_.code.push_back(Instr{Op::number, 0, Fn::sin, 0, static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(n)))});
            return;
        }
        if (ascii_digit(c) || c == '.') {
            if (!read_number(t_, p_, v, s_.ex_exponent)) error("Bad number");
            e_.code.push_back(Instr{Op::number, 0, Fn::sin, 0, v});
            return;
        }
        if (c == s_.open) {
            ++p_;
            expression(0, depth + 1);
            blanks();
            if (p_ >= t_.size() || t_[p_] != s_.close)
                error(s_.hash_parameters ? std::string("Unclosed expression") : std::string("'") + s_.close + "' expected");
            ++p_;
            return;
        }
        if (c == '"') {
            if (!s_.strings) error("A string is not allowed in an arithmetic expression");
            const std::size_t end = t_.find('"', p_ + 1);
            if (end == std::string_view::npos) error("Unclosed string");
            e_.texts.emplace_back(t_.substr(p_ + 1, end - p_ - 1));
            e_.code.push_back(Instr{Op::text, 0, Fn::sin, static_cast<std::uint32_t>(e_.texts.size() - 1), 0});
            e_.uses_text = true;
            p_ = end + 1;
            return;
        }
        if (!ident_start(c)) error(std::string("Unexpected '") + c + "' in expression");
        std::size_t b = p_;
        while (p_ < t_.size() && ident_char(t_[p_])) ++p_;
        std::string name = to_upper_ascii(t_.substr(b, p_ - b));
        if (!s_.hash_parameters && (name == "TRUE" || name == "FALSE")) {
            e_.code.push_back(Instr{Op::number, 0, Fn::sin, 0, name == "TRUE" ? 1.0 : 0.0});
            return;
        }
        std::size_t after = p_;
        blanks();
        if (s_.hash_parameters) {
            iso_function(name, b, depth);
            return;
        }
        if (p_ < t_.size() && t_[p_] == s_.open) {
            const FnName* f = find_function(name, s_.family);
            if (!f) {
                p_ = b;
                error("Unknown function " + name);
            }
            ++p_;
            int n = 0;
            blanks();
            if (p_ < t_.size() && t_[p_] == s_.close) {
                ++p_;
            } else {
                for (;;) {
                    expression(0, depth + 1);
                    ++n;
                    blanks();
                    if (p_ < t_.size() && t_[p_] == ',') {
                        ++p_;
                        continue;
                    }
                    if (p_ < t_.size() && t_[p_] == s_.close) {
                        ++p_;
                        break;
                    }
                    error(std::string("',' or '") + s_.close + "' expected");
                }
            }
            if (n < f->min_args || n > f->max_args) error(name + ": wrong number of arguments");
            e_.code.push_back(Instr{Op::call, static_cast<std::uint8_t>(n), f->fn, 0, 0});
            if (f->fn >= Fn::strlen) e_.uses_text = true;
            return;
        }
        p_ = after;
        int n = 0;
        if (s_.index_open && p_ < t_.size() && t_[p_] == s_.index_open) {
            ++p_;
            for (;;) {
                expression(0, depth + 1);
                if (++n > 8) error("Too many indices");
                blanks();
                if (p_ < t_.size() && t_[p_] == ',') {
                    ++p_;
                    continue;
                }
                if (p_ < t_.size() && t_[p_] == s_.index_close) {
                    ++p_;
                    break;
                }
                error(std::string("',' or '") + s_.index_close + "' expected");
            }
        }
        std::uint32_t id = 0;
        while (id < e_.names.size() && e_.names[id] != name) ++id;
        if (id == e_.names.size()) e_.names.push_back(name);
        e_.code.push_back(Instr{Op::variable, static_cast<std::uint8_t>(n), Fn::sin, id, 0});
    }

    // '#' then what names the parameter: a number, another '#', a bracketed expression, or
    // (LinuxCNC) <name>.
    // `op`: Op::param reads the parameter, Op::exists_number asks whether it exists.
    void parameter(int depth, Op op = Op::param) {
        if (depth > kMaxDepth) error("Expression nested too deeply");
        ++p_;
        blanks();
        if (p_ < t_.size() && t_[p_] == '<' && (s_.family & family_linuxcnc)) {
            std::string n = named_parameter();
            emit_named(op == Op::param ? Op::variable : Op::exists, n);
            return;
        }
        if (p_ >= t_.size()) error("Parameter number expected after '#'");
        char c = t_[p_];
        if (c == '#') {
            parameter(depth + 1);
        } else if (c == s_.open) {
            primary(depth + 1);
        } else if (ascii_digit(c) || c == '.') {
            double v;
            if (!read_number(t_, p_, v, false)) error("Bad number");
            e_.code.push_back(Instr{Op::number, 0, Fn::sin, 0, v});
        } else if (c == '-' || c == '+') {
            unary(depth + 1);  // "#-1": refused by the reader of the number
        } else {
            error("Bad parameter number");
        }
        emit(op);
    }
    // <name> of a LinuxCNC named parameter (blanks inside are dropped, case folded); p_ at '<'.
    std::string named_parameter() {
        std::size_t b = ++p_;
        while (p_ < t_.size() && t_[p_] != '>') ++p_;
        if (p_ >= t_.size()) error("Named parameter not terminated");
        std::string name;
        for (std::size_t i = b; i < p_; ++i)
            if (t_[i] != ' ' && t_[i] != '\t') name.push_back(ascii_lower(t_[i]));
        ++p_;
        if (name.empty()) error("Named parameter with no name");
        return name;
    }
    void emit_named(Op op, const std::string& name) {
        std::uint32_t id = 0;
        while (id < e_.names.size() && e_.names[id] != name) ++id;
        if (id == e_.names.size()) e_.names.push_back(name);
        e_.code.push_back(Instr{op, 0, Fn::sin, id, 0});
    }
    // A function of the ISO controls: NAME[arg], ATAN[a]/[b], EXISTS[#<name>]. Bare names
    // are not values there.
    void iso_function(const std::string& name, std::size_t begin, int depth) {
        auto bracketed = [&] {
            blanks();
            if (p_ >= t_.size() || t_[p_] != s_.open) error(std::string("'") + s_.open + "' expected after " + name);
            primary(depth + 1);
        };
        if (name == "EXISTS" && (s_.family & family_linuxcnc)) {
            blanks();
            if (p_ >= t_.size() || t_[p_] != s_.open) error("'[' expected after EXISTS");
            ++p_;
            blanks();
            if (p_ + 1 >= t_.size() || t_[p_] != '#') error("Expected # reading parameter");
            parameter(depth + 1, Op::exists_number);  // #<name>, or a numbered one: #1, ##2, #[2+3]
            blanks();
            if (p_ >= t_.size() || t_[p_] != s_.close) error("Expected ] reading bracketed parameter");
            ++p_;
            return;
        }
        if (name == "ATAN" && s_.atan_slash) {
            bracketed();
            blanks();
            if (p_ >= t_.size() || t_[p_] != '/') error("Slash missing after first atan argument");
            ++p_;
            blanks();
            if (p_ >= t_.size() || t_[p_] != s_.open) error("Left bracket missing after slash with atan");
            bracketed();
            e_.code.push_back(Instr{Op::call, 2, Fn::atan_ratio, 0, 0});
            return;
        }
        const FnName* f = find_function(name, s_.family);
        if (!f) {
            p_ = begin;
            error("Unknown word where unary operation could be");
        }
        bracketed();
        e_.code.push_back(Instr{Op::call, 1, f->fn, 0, 0});
    }

    std::string_view t_;
    std::size_t p_;
    const Syntax& s_;
    Expr e_;
};

double to_deg(double r) { return r * 180.0 / kPi; }
double to_rad(double d) { return d * kPi / 180.0; }
std::int64_t as_int(double v) {
    if (!(std::fabs(v) < 9.2e18)) throw MathError("Value out of the integer range", MathFault::integer_range);
    return static_cast<std::int64_t>(std::llround(v));
}

double call(Fn f, const double* a) {
    switch (f) {
        case Fn::sin: return std::sin(to_rad(a[0]));
        case Fn::cos: return std::cos(to_rad(a[0]));
        case Fn::tan: {
            double c = std::cos(to_rad(a[0]));
            if (std::fabs(c) < 1e-15) throw MathError("TAN of an odd multiple of 90 degrees", MathFault::tan_pole);
            return std::sin(to_rad(a[0])) / c;
        }
        case Fn::asin:
            if (a[0] < -1 || a[0] > 1) throw MathError("ASIN argument outside -1..1", MathFault::asin_domain);
            return to_deg(std::asin(a[0]));
        case Fn::acos:
            if (a[0] < -1 || a[0] > 1) throw MathError("ACOS argument outside -1..1", MathFault::acos_domain);
            return to_deg(std::acos(a[0]));
        case Fn::atan: return to_deg(std::atan(a[0]));
        case Fn::atan2:
            if (a[0] == 0 && a[1] == 0) throw MathError("ATAN2 of (0, 0)", MathFault::atan_origin);
            return to_deg(std::atan2(a[0], a[1]));
        case Fn::sqrt:
            if (a[0] < 0) throw MathError("SQRT of a negative number", MathFault::sqrt_negative);
            return std::sqrt(a[0]);
        case Fn::abs: return std::fabs(a[0]);
        case Fn::exp: return std::exp(a[0]);
        case Fn::ln:
            if (a[0] <= 0) throw MathError("LN of a number not greater than zero", MathFault::ln_domain);
            return std::log(a[0]);
        case Fn::round: return std::round(a[0]);
        case Fn::trunc: return std::trunc(a[0]);
        case Fn::roundup: return std::ceil(a[0]);
        case Fn::square: return a[0] * a[0];
        case Fn::floor: return std::floor(a[0]);
        case Fn::atan_ratio: return to_deg(std::atan2(a[0], a[1]));
        case Fn::ceil: return std::ceil(a[0]);
        case Fn::away: return a[0] < 0 ? -std::ceil(-a[0]) : std::ceil(a[0]);
        case Fn::minval: return std::fmin(a[0], a[1]);
        case Fn::maxval: return std::fmax(a[0], a[1]);
        case Fn::bound:
            if (a[0] > a[1]) throw MathError("BOUND: minimum greater than maximum", MathFault::bound_order);
            return std::fmin(std::fmax(a[2], a[0]), a[1]);
        case Fn::strlen: case Fn::index: case Fn::rindex: case Fn::substr: case Fn::toupper: case Fn::tolower:
        case Fn::number: case Fn::isnumber: case Fn::axname: case Fn::axstring:
            throw MathError("A string function where only numbers are evaluated");  // expr_text.cpp runs them
    }
    return 0;
}

}  // namespace

double apply_function(Fn f, const double* args) {
    const double r = call(f, args);
    if (!std::isfinite(r)) throw MathError("Result out of range", MathFault::out_of_range);
    return r;
}

const Syntax& sinumerik_syntax() {
    // Siemens PGA priorities: NOT; * / DIV MOD; + -; B_AND; B_XOR; B_OR; AND; XOR; OR;
    // "<<" (strings joined); comparisons last (so "R1>1 AND R2<2" needs brackets, as on the
    // control).
    static const Syntax s{'(', ')', '[', ']',
                          {{"*", Op::mul, 10},         {"/", Op::div, 10},         {"DIV", Op::int_div, 10},
                           {"MOD", Op::mod, 10},       {"+", Op::add, 9},          {"-", Op::sub, 9},
                           {"B_AND", Op::bit_and, 8},  {"B_XOR", Op::bit_xor, 7},  {"B_OR", Op::bit_or, 6},
                           {"AND", Op::logical_and, 5}, {"XOR", Op::logical_xor, 4}, {"OR", Op::logical_or, 3},
                           {"<<", Op::concat, 2},
                           {"==", Op::eq, 1},          {"<>", Op::ne, 1},          {"<=", Op::le, 1},
                           {">=", Op::ge, 1},          {"<", Op::lt, 1},           {">", Op::gt, 1}},
                          true};
    static const Syntax with_strings = [] {
        Syntax w = s;
        w.strings = true;
        return w;
    }();
    return with_strings;
    return s;
}

const Syntax& linuxcnc_syntax() {
    // RS274/NGC: ** ; * / MOD ; + - ; EQ NE GT GE LT LE ; AND OR XOR, all left to right.
    // EQ/NE compare within 0.0001 (LinuxCNC's TOLERANCE_EQUAL), the others exactly; MOD's
    // result is never negative ([-7 MOD 3] = 2, [5 MOD -3] = 2).
    static const Syntax s{'[', ']', 0, 0,
                          {{"**", Op::pow, 6},          {"*", Op::mul, 5},           {"/", Op::div, 5},
                           {"MOD", Op::mod, 5},         {"+", Op::add, 4},           {"-", Op::sub, 4},
                           {"EQ", Op::eq, 3},           {"NE", Op::ne, 3},           {"GT", Op::gt, 3},
                           {"GE", Op::ge, 3},           {"LT", Op::lt, 3},           {"LE", Op::le, 3},
                           {"AND", Op::logical_and, 2}, {"OR", Op::logical_or, 2},   {"XOR", Op::logical_xor, 2}},
                          false, family_linuxcnc, true, true, false, 1e-4, true, false};
    return s;
}

const Syntax& fanuc_syntax() {
    // Fanuc Macro B: * / AND MOD ; + - OR XOR ; the comparisons EQ NE GT GE LT LE of IF and
    // WHILE conditions. AND / OR / XOR are read as logical operations (the bitwise reading of
    // the manual agrees on the 0/1 values conditions produce). Vacant values (Syntax::vacant).
    static const Syntax s{'[', ']', 0, 0,
                          {{"*", Op::mul, 5},           {"/", Op::div, 5},           {"AND", Op::logical_and, 5},
                           {"MOD", Op::mod, 5},         {"+", Op::add, 4},           {"-", Op::sub, 4},
                           {"OR", Op::logical_or, 4},   {"XOR", Op::logical_xor, 4}, {"EQ", Op::eq, 3},
                           {"NE", Op::ne, 3},           {"GT", Op::gt, 3},           {"GE", Op::ge, 3},
                           {"LT", Op::lt, 3},           {"LE", Op::le, 3}},
                          false, family_fanuc, true, true, false, 0, false, true};
    return s;
}

bool read_number(std::string_view t, std::size_t& pos, double& value, bool ex_exponent) {
    std::size_t p = pos;
    bool negative = false;
    if (p < t.size() && (t[p] == '-' || t[p] == '+')) negative = t[p++] == '-';
    const std::size_t first = p;
    // Digits with at most one point: one pass gives the end and, for up to 15 digits, the
    // value (a second point ends the number, as a non-digit does).
    const DecimalRun run = scan_decimal_run(t.data(), first, t.size());
    const bool ex = ex_exponent && run.points <= 1 && run.end + 1 < t.size() && ascii_upper(t[run.end]) == 'E' &&
                    ascii_upper(t[run.end + 1]) == 'X';
    if (run.plain() && !ex) {
        value = negative ? -decimal_value(run.m, run.frac) : decimal_value(run.m, run.frac);
        pos = run.end;
        return true;
    }
    bool digits = false;
    while (p < t.size() && ascii_digit(t[p])) ++p, digits = true;
    if (p < t.size() && t[p] == '.') {
        ++p;
        while (p < t.size() && ascii_digit(t[p])) ++p, digits = true;
    }
    if (!digits) return false;
    const std::string_view mantissa = t.substr(first, p - first);
    double v = 0;
    bool read = false;
    if (ex_exponent && p + 1 < t.size() && ascii_upper(t[p]) == 'E' && ascii_upper(t[p + 1]) == 'X') {
        std::size_t q = p + 2;
        std::string buf(mantissa);
        buf += 'e';
        if (q < t.size() && (t[q] == '-' || t[q] == '+')) buf.push_back(t[q++]);
        const std::size_t exp_digits = q;
        while (q < t.size() && ascii_digit(t[q])) buf.push_back(t[q++]);
        if (q > exp_digits) {
            const auto r = std::from_chars(buf.data(), buf.data() + buf.size(), v);
            if (r.ec != std::errc()) return false;
            read = true;
            p = q;
        }
    }
    if (!read && !parse_decimal(mantissa, v)) return false;  // the digits' value, as from_chars rounds
    if (!std::isfinite(v)) return false;
    value = negative ? -v : v;
    pos = p;
    return true;
}

Expr parse(std::string_view text, std::size_t& pos, const Syntax& syntax) {
    Parser p(text, pos, syntax);
    Expr e = p.run();
    pos = p.pos();
    return e;
}

Expr parse_value(std::string_view text, std::size_t& pos, const Syntax& syntax) {
    Parser p(text, pos, syntax);
    Expr e = p.run_value();
    pos = p.pos();
    return e;
}

Expr parse_all(std::string_view text, const Syntax& syntax) {
    std::size_t pos = 0;
    Expr e = parse(text, pos, syntax);
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
    if (pos != text.size()) throw SyntaxError("Unexpected text after the expression", pos);
    return e;
}

namespace {
int run(const Expr& e, Env& env, double* stack, const Syntax* syntax);
}

double evaluate_with_text(const Expr& e, Env& env);  // expr_text.cpp

double evaluate(const Expr& e, Env& env, const Syntax* syntax) {
    if (e.uses_text) return evaluate_with_text(e, env);
    double stack[512];
    int sp;
    try {
        sp = run(e, env, stack, syntax);
    } catch (const TextValue&) {  // a string variable: strings after all
        return evaluate_with_text(e, env);
    }
    return sp == 1 ? stack[0] : 0.0;
}

void evaluate_all(const Expr& e, Env& env, std::vector<double>& out) {
    if (e.uses_text) throw MathError("Strings in an assignment's indices are not supported by toolcomp");
    double stack[512];
    int sp;
    try {
        sp = run(e, env, stack, nullptr);
    } catch (const TextValue&) {
        throw MathError("A string where a number is expected");
    }
    out.assign(stack, stack + sp);
}

namespace {
// Fanuc: a vacant value counts as 0 in arithmetic and functions.
double value_of(double v, const Syntax* s) { return s && s->vacant && std::isnan(v) ? 0.0 : v; }

int run(const Expr& e, Env& env, double* stack, const Syntax* syn) {
    int sp = 0;
    auto push = [&](double v) {
        if (sp >= 512) throw MathError("Expression too complex");
        stack[sp++] = v;
    };
    const double eq_tol = syn ? syn->eq_tolerance : 0;
    for (const Instr& in : e.code) {
        switch (in.op) {
            case Op::number: push(in.value); break;
            case Op::variable: {
                sp -= in.argc;
                double v = env.get(e.names[in.name], std::span<const double>(stack + sp, in.argc));
                push(v);
                break;
            }
            case Op::param: {
                const double n = stack[--sp];
                push(env.param(value_of(n, syn)));
                break;
            }
            case Op::exists: push(env.exists(e.names[in.name]) ? 1.0 : 0.0); break;
            case Op::exists_number: {  // LinuxCNC: any number of 1-5601 is a parameter
                const double n = std::round(value_of(stack[--sp], syn));
                push(n >= 1 && n <= 5601 ? 1.0 : 0.0);
                break;
            }
            case Op::call: {
                sp -= in.argc;
                for (int k = 0; k < in.argc; ++k) stack[sp + k] = value_of(stack[sp + k], syn);
                const double r = call(in.fn, stack + sp);
                if (!std::isfinite(r)) throw MathError("Result out of range", MathFault::out_of_range);
                push(r);
                break;
            }
            case Op::neg: stack[sp - 1] = -value_of(stack[sp - 1], syn); break;
            case Op::logical_not: stack[sp - 1] = value_of(stack[sp - 1], syn) == 0 ? 1 : 0; break;
            case Op::bit_not: stack[sp - 1] = static_cast<double>(~as_int(stack[sp - 1])); break;
            default: {
                double b = stack[--sp];
                double& a = stack[sp - 1];
                if ((in.op == Op::eq || in.op == Op::ne) && syn && syn->vacant && (std::isnan(a) || std::isnan(b))) {
                    // Fanuc: vacant equals only vacant (#1 EQ #0), never 0.
                    const bool same = std::isnan(a) && std::isnan(b);
                    a = (in.op == Op::eq) == same ? 1 : 0;
                    break;
                }
                a = value_of(a, syn);
                b = value_of(b, syn);
                switch (in.op) {
                    case Op::add: a = a + b; break;
                    case Op::sub: a = a - b; break;
                    case Op::mul: a = a * b; break;
                    case Op::div:
                        if (b == 0) throw MathError("Division by zero", MathFault::divide_by_zero);
                        a = a / b;
                        break;
                    case Op::int_div:
                        if (b == 0) throw MathError("Division by zero", MathFault::divide_by_zero);
                        a = std::trunc(a / b);
                        break;
                    case Op::mod:
                        if (b == 0) throw MathError("Division by zero", MathFault::not_a_number);
                        a = std::fmod(a, b);
                        if (syn && syn->mod_floor && a < 0) a += std::fabs(b);
                        break;
                    case Op::pow:
                        if (a < 0 && std::floor(b) != b)
                            throw MathError("Negative base raised to a non-integer power", MathFault::negative_power);
                        a = std::pow(a, b);
                        break;
                    case Op::eq: a = eq_tol > 0 ? std::fabs(a - b) < eq_tol : a == b; break;
                    case Op::ne: a = eq_tol > 0 ? std::fabs(a - b) >= eq_tol : a != b; break;
                    case Op::lt: a = a < b; break;
                    case Op::le: a = a <= b; break;
                    case Op::gt: a = a > b; break;
                    case Op::ge: a = a >= b; break;
                    case Op::logical_and: a = (a != 0) && (b != 0); break;
                    case Op::logical_or: a = (a != 0) || (b != 0); break;
                    case Op::logical_xor: a = (a != 0) != (b != 0); break;
                    case Op::bit_and: a = static_cast<double>(as_int(a) & as_int(b)); break;
                    case Op::bit_or: a = static_cast<double>(as_int(a) | as_int(b)); break;
                    case Op::bit_xor: a = static_cast<double>(as_int(a) ^ as_int(b)); break;
                    default: break;
                }
                if (!std::isfinite(a)) throw MathError("Result out of range", MathFault::out_of_range);
            }
        }
    }
    return sp;
}
}  // namespace

}  // namespace toolcomp::expr
