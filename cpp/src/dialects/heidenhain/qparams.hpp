#pragma once
// Q parameters of TNC conversational programs: the formula evaluator (Qn = ...) and the FN
// functions (FN 0..8, 13 arithmetic, FN 9..12 conditional jumps, FN 14 error).
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace toolcomp::heidenhain {

using QLookup = std::function<double(int)>;

// Evaluates a formula: numbers, Qn, + - * / ^, parentheses, functions SIN COS TAN ASIN ACOS
// ATAN (degrees) SQRT SQ ABS INT FRAC NEG LN LOG EXP and PI. Throws std::invalid_argument
// with a message on a syntax error, std::domain_error on a math error (division by zero...).
double evaluate_formula(std::string_view text, const QLookup& q);

struct QResult {
    std::optional<int> assign;   // Q number to set
    double value = 0;
    std::optional<std::string> jump;  // label to go to (FN 9..12 when the condition holds): 5 or "NAME"
    std::optional<int> error;    // FN 14: error number
};

// Runs one statement: "FN n: ..." or "Qn = formula". Throws std::invalid_argument on bad syntax.
QResult run_statement(std::string_view text, const QLookup& q);

}  // namespace toolcomp::heidenhain
