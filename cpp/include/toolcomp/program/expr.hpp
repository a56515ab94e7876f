#pragma once
// Arithmetic expressions of part programs, shared by the dialects: compiled once (front end)
// into a small postfix code, evaluated many times (interpreter) against the parameters of
// the running program.
//
// The grammar is common (numbers, variables with optional [i, j] indices, unary and binary
// operators, function calls); what differs between controls is the spelling and precedence
// of the operators and the brackets, given by a Syntax. Trigonometry works in degrees, as
// on every control toolcomp reads.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace toolcomp::expr {

enum class Op : std::uint8_t {
    number, variable, call,
    neg, logical_not, bit_not,
    add, sub, mul, div, int_div, mod, pow,
    eq, ne, lt, le, gt, ge,
    logical_and, logical_or, logical_xor, bit_and, bit_or, bit_xor,
};

enum class Fn : std::uint8_t {
    sin, cos, tan, asin, acos, atan, atan2, sqrt, abs, exp, ln, round, trunc, roundup, square,
    minval, maxval, bound,
};

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
};
const Syntax& sinumerik_syntax();

// A syntax error: message and the 0-based offset into the text where it was found.
struct SyntaxError : std::runtime_error {
    SyntaxError(const std::string& m, std::size_t offset) : std::runtime_error(m), offset(offset) {}
    std::size_t offset;
};
// A math error while evaluating (division by zero, SQRT of a negative number, ...).
struct MathError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses the expression starting at `pos` (leading blanks skipped) and stops before the first
// text that cannot continue it (so "10 Y20" parses "10" and leaves pos at " Y20"). Throws
// SyntaxError. Nesting deeper than 200 levels is a syntax error, never a stack overflow.
Expr parse(std::string_view text, std::size_t& pos, const Syntax& syntax);
// The whole text must be one expression.
Expr parse_all(std::string_view text, const Syntax& syntax);

// Where the evaluator reads variables: the name (upper case) and the evaluated indices.
class Env {
public:
    virtual ~Env() = default;
    virtual double get(const std::string& name, std::span<const double> indices) = 0;
};

// Evaluates; throws MathError, and whatever Env::get throws.
double evaluate(const Expr& e, Env& env);
// Evaluates code that leaves several values (the indices of an assignment target) into `out`.
void evaluate_all(const Expr& e, Env& env, std::vector<double>& out);

// Reads a number at `pos` ("12", "-1.5", ".5", "1.5EX3" with `ex_exponent`); advances pos.
// Returns false (pos unchanged) when there is none.
bool read_number(std::string_view text, std::size_t& pos, double& value, bool ex_exponent);

}  // namespace toolcomp::expr
