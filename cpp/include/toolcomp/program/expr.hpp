#pragma once
// Arithmetic expressions of part programs, shared by the dialects: compiled once (front end)
// into a small postfix code, evaluated many times (interpreter) against the parameters of
// the running program.
//
// The grammar is common (numbers, variables with optional [i, j] indices, unary and binary
// operators, function calls); what differs between controls is the spelling and precedence
// of the operators and the brackets, given by a Syntax. Trigonometry works in degrees, as
// on every control toolcomp reads.
//
// ISO macro forms (LinuxCNC, Fanuc Macro B) read parameters with '#': "#5", "##2" (the
// parameter whose number is in #2), "#[1+2]" and, LinuxCNC only, "#<name>". Fanuc's
// parameters can be vacant (never set): a vacant value travels as NaN through a plain copy
// and counts as 0 in arithmetic (Syntax::vacant).
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace toolcomp::expr {

enum class Op : std::uint8_t {
    number, variable, call,
    param,   // ISO '#': pops a parameter number, pushes its value
    exists,  // LinuxCNC EXISTS[#<name>]: 1 when the named parameter is defined
    exists_number,  // LinuxCNC EXISTS[#n]: pops a parameter number, 1 when it is one (1-5601)
    neg, logical_not, bit_not,
    add, sub, mul, div, int_div, mod, pow,
    eq, ne, lt, le, gt, ge,
    logical_and, logical_or, logical_xor, bit_and, bit_or, bit_xor,
    text,    // 840D: pushes the string Expr::texts[name]
    concat,  // 840D "<<": two values joined as text
};

enum class Fn : std::uint8_t {
    sin, cos, tan, asin, acos, atan, atan2, sqrt, abs, exp, ln, round, trunc, roundup, square,
    minval, maxval, bound,
    floor, ceil, away,  // LinuxCNC FIX / FUP; Fanuc FUP (away from zero)
    atan_ratio,         // ATAN[a]/[b]: atan2 in degrees, 0 for 0/0
    // 840D string functions (expr_text.cpp)
    strlen, index, rindex, substr, toupper, tolower, number, isnumber,
    axname, axstring,  // AXNAME("X"): the axis of that name; AXSTRING(axis): its name
};

// Which controls know a function name.
enum Family : std::uint8_t { family_sinumerik = 1, family_linuxcnc = 2, family_fanuc = 4 };

struct Instr {
    Op op = Op::number;
    std::uint8_t argc = 0;  // variable: number of indices; call: number of arguments
    Fn fn = Fn::sin;
    std::uint32_t name = 0;  // variable: index into Expr::names
    double value = 0;        // number
};

struct Expr {
    std::vector<Instr> code;
    std::vector<std::string> names;  // upper case
    std::vector<std::string> texts;  // string constants (Op::text)
    bool uses_text = false;          // a string constant, "<<" or a string function: see evaluate_text
    bool constant() const { return code.size() == 1 && code[0].op == Op::number; }
};

// How a control spells its expressions.
struct BinaryOp {
    std::string_view spelling;  // "+", "==", "MOD" (words match whole identifiers only)
    Op op;
    int precedence;  // higher binds tighter
};
struct Syntax {
    char open = '(', close = ')';              // grouping and function arguments
    char index_open = '[', index_close = ']';  // array indices of variables (0: none)
    std::vector<BinaryOp> binary;              // longest spellings first where they overlap
    bool unary_not = true;                     // NOT / B_NOT prefixes
    std::uint8_t family = family_sinumerik;    // function names of this control
    bool hash_parameters = false;              // '#' parameters; no bare names
    bool atan_slash = false;                   // ATAN[a]/[b]
    bool ex_exponent = true;                   // numbers with EX exponents (1.5EX3)
    double eq_tolerance = 0;                   // EQ / NE compare within this
    bool mod_floor = false;                    // MOD takes the divisor's sign (never negative for b > 0)
    bool vacant = false;                       // NaN parameters are vacant (Fanuc)
    bool strings = false;                      // "..." constants, "<<", string functions (840D)
};
const Syntax& sinumerik_syntax();
const Syntax& linuxcnc_syntax();
const Syntax& fanuc_syntax();

// A syntax error: message and the 0-based offset into the text where it was found.
struct SyntaxError : std::runtime_error {
    SyntaxError(const std::string& m, std::size_t offset) : std::runtime_error(m), offset(offset) {}
    std::size_t offset;
};
// A math error while evaluating (division by zero, SQRT of a negative number, ...). `fault`
// lets a dialect word it the way its control does.
enum class MathFault : std::uint8_t {
    other, divide_by_zero, sqrt_negative, ln_domain, asin_domain, acos_domain, tan_pole, atan_origin,
    negative_power, out_of_range, not_a_number, integer_range, bound_order,
};
struct MathError : std::runtime_error {
    explicit MathError(const std::string& m, MathFault f = MathFault::other) : std::runtime_error(m), fault(f) {}
    MathFault fault;
};

// Parses the expression starting at `pos` (leading blanks skipped) and stops before the first
// text that cannot continue it (so "10 Y20" parses "10" and leaves pos at " Y20"). Throws
// SyntaxError. Nesting deeper than 200 levels is a syntax error, never a stack overflow.
Expr parse(std::string_view text, std::size_t& pos, const Syntax& syntax);
// One operand only (signs, then a number, a variable or parameter, a bracketed expression or
// a function): the value of a LinuxCNC word ("X#1", "X[1+2]", "Xsin[30]").
Expr parse_value(std::string_view text, std::size_t& pos, const Syntax& syntax);
// The whole text must be one expression.
Expr parse_all(std::string_view text, const Syntax& syntax);

// Where the evaluator reads variables: the name (upper case) and the evaluated indices.
class Env {
public:
    virtual ~Env() = default;
    virtual double get(const std::string& name, std::span<const double> indices) = 0;
    // ISO '#n' (Syntax::hash_parameters); NaN = vacant where the syntax has vacant values.
    virtual double param(double number) { (void)number; throw MathError("Parameters are not available here"); }
    virtual bool exists(const std::string& name) { (void)name; return false; }
    // A string variable's value (840D STRING); nothing for a numeric name. Where get() is asked
    // for a string variable it throws TextValue: the expression is then evaluated with strings.
    virtual std::optional<std::string> text(const std::string& name, std::span<const double> indices) {
        (void)name;
        (void)indices;
        return std::nullopt;
    }
};
struct TextValue {};

// Evaluates; throws MathError, and whatever Env::get throws.
// `syntax` (optional) gives the comparison tolerance, MOD's sign and vacant values.
double evaluate(const Expr& e, Env& env, const Syntax* syntax = nullptr);
// A numeric function's value (MathError for a domain error or a result out of range).
double apply_function(Fn f, const double* args);
// With strings (Expr::uses_text, or a string variable met): the value as text, numbers
// written as shortest_number writes them; evaluate() of such an expression takes this way
// and refuses a string result (MathError).
std::string evaluate_text(const Expr& e, Env& env);
// Evaluates code that leaves several values (the indices of an assignment target) into `out`.
void evaluate_all(const Expr& e, Env& env, std::vector<double>& out);

// Reads a number at `pos` ("12", "-1.5", ".5", "1.5EX3" with `ex_exponent`); advances pos.
// Returns false (pos unchanged) when there is none.
bool read_number(std::string_view text, std::size_t& pos, double& value, bool ex_exponent);

}  // namespace toolcomp::expr
