// Subprograms with parameters: PROC name(REAL A, INT N, BOOL B, VAR REAL OUT, ...). A value
// parameter takes the value of its argument (INT rounds, BOOL is the value != 0; an omitted
// argument is 0); a VAR parameter is the caller's variable itself (a user variable, one of its
// elements, or an R parameter): a change is the caller's at once. Alarms as the 840D raises
// them: 12340 more arguments than parameters, 14010 a VAR parameter without its argument,
// 12320 a VAR argument that is not a variable, 12330 one of another type.
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::sinumerik {

namespace {

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

bool identifier(const std::string& s) {
    if (s.empty() || !(ascii_alpha(s[0]) || s[0] == '_')) return false;
    for (char ch : s)
        if (!(ascii_alpha(ch) || ascii_digit(ch) || ch == '_')) return false;
    return true;
}

}  // namespace

// PROC's parameter list: [VAR] REAL|INT|BOOL|STRING[n] name, ... (other types refused by name).
std::vector<Formal> Interp::parse_formals(const std::string& text, int line, int column) {
    std::vector<Formal> out;
    for (const std::string& raw : split_args(text)) {
        std::string s = to_upper_ascii(raw);  // names are not case sensitive
        Formal f;
        if (s.rfind("VAR ", 0) == 0 || s.rfind("VAR\t", 0) == 0) f.by_reference = true, s = trimmed(s.substr(4));
        if (s.rfind("STRING", 0) == 0) {  // STRING[n] NAME: its length
            const auto open = s.find('['), close = s.find(']');
            const std::string n = open == 6 && close != std::string::npos ? trimmed(s.substr(7, close - 7)) : "";
            if (n.empty() || n.size() > 3 || n.find_first_not_of("0123456789") != std::string::npos || std::stoi(n) < 1)
                throw ProgramError(code::syntax_error, "PROC parameter '" + raw + "': STRING[length] expected", {line, column, {}});
            f.text = static_cast<std::size_t>(std::stoi(n));
            s = "STRING " + trimmed(s.substr(close + 1));
        }
        const auto blank = s.find_first_of(" \t");
        const std::string type = blank == std::string::npos ? s : s.substr(0, blank);
        std::string name = blank == std::string::npos ? std::string() : trimmed(s.substr(blank));
        if (const auto open = name.find('['); open != std::string::npos) {  // VAR REAL A[3] / A[,3]
            if (!f.by_reference || name.back() != ']')
                throw ProgramError(code::syntax_error, "PROC parameter '" + raw + "': an array is a VAR parameter",
                                   {line, column, {}});
            f.array = true;
            name = trimmed(name.substr(0, open));
        }
        if (type != "REAL" && type != "INT" && type != "BOOL" && type != "STRING" && type != "AXIS")
            throw ProgramError(code::unsupported_word,
                               "PROC parameter '" + raw + "': toolcomp takes REAL, INT, BOOL, STRING and AXIS parameters (VAR too)",
                               {line, column, {}});
        if (type == "AXIS") f.axis = true, f.text = 8;
        if (!identifier(name))
            throw ProgramError(code::unsupported_word,
                               "PROC parameter '" + raw + "': toolcomp takes single variables (no arrays)",
                               {line, column, {}});
        f.name = name;
        f.integer = type == "INT" || type == "BOOL";
        f.boolean = type == "BOOL";
        out.push_back(std::move(f));
    }
    return out;
}

std::map<std::string, Variable> Interp::bind_arguments(const std::string& name, const ProgramInfo& callee,
                                                       const std::string& args, int column) {
    std::map<std::string, Variable> locals;
    std::vector<std::string> actual = trimmed(args).empty() ? std::vector<std::string>{} : split_args(args);
    if (actual.size() > callee.formals.size())
        fail(code::alarm_12340, "12340 Number of parameters too high: " + name + " takes " +
                                    std::to_string(callee.formals.size()),
             column);
    for (std::size_t i = 0; i < callee.formals.size(); ++i) {
        const Formal& f = callee.formals[i];
        const std::string a = i < actual.size() ? actual[i] : std::string();
        if (f.by_reference) {
            if (a.empty())
                fail(code::alarm_14010, "14010 Invalid default parameter in subprogram call: VAR " + f.name + " of " + name +
                                            " needs its argument",
                     column);
            locals.emplace(f.name, reference_to(a, f, name, column));
            continue;
        }
        Variable v;
        if (f.axis) {  // AXIS: an axis name or AXIS variable; one cannot be left out
            if (a.empty())
                fail(code::alarm_14010, "14010 Invalid default parameter in subprogram call: AXIS " + f.name + " of " + name +
                                            " needs its argument",
                     column);
            v.text = v.axis = true;
            v.length = 8;
            v.v.assign(1, 0.0);
            try {
                v.s.assign(1, axis_value(expr::parse_all(a, expr::sinumerik_syntax()), column));
            } catch (const expr::SyntaxError& err) {
                fail(code::syntax_error, std::string("12080 Syntax error: ") + err.what(), column);
            }
            locals.emplace(f.name, std::move(v));
            continue;
        }
        if (f.text) {  // STRING[n]: the argument's text (omitted: empty)
            v.text = true;
            v.length = f.text;
            v.v.assign(1, 0.0);  // the shape at() reads
            v.s.assign(1, a.empty() ? std::string() : eval_text_string(a, column));
            if (v.s[0].size() > v.length)
                fail(code::string_too_long, f.name + " of " + name + ": \"" + v.s[0] + "\" is longer than its STRING[" +
                                                std::to_string(v.length) + "]", column);
            locals.emplace(f.name, std::move(v));
            continue;
        }
        v.integer = f.integer;
        double x = a.empty() ? 0.0 : eval_text(a, column);
        if (f.boolean) x = x != 0;
        else if (f.integer) x = std::round(x);
        v.v.assign(1, x);
        locals.emplace(f.name, std::move(v));
    }
    return locals;
}

// A VAR argument: R5, R[expr], NAME or NAME[i] / NAME[i,j] of the caller (its own VAR
// parameters followed to what they stand for).
Variable Interp::reference_to(const std::string& actual, const Formal& f, const std::string& name, int column) {
    std::string var = to_upper_ascii(actual), index;  // names are not case sensitive
    if (const auto open = actual.find('['); open != std::string::npos && actual.back() == ']') {
        var = to_upper_ascii(trimmed(actual.substr(0, open)));
        index = actual.substr(open + 1, actual.size() - open - 2);
    }
    auto not_a_variable = [&]() {
        fail(code::alarm_12320, "12320 Parameter " + f.name + " of " + name + " is not a variable: " + actual, column);
    };
    if (!identifier(var)) not_a_variable();
    if (f.array) {  // the caller's whole array (or the whole array its own VAR parameter names)
        Variable* target = index.empty() ? find_variable(var) : nullptr;
        if (!target || target->r_index >= 0 || (target->ref && !target->whole)) not_a_variable();
        Variable* store = target->ref ? target->ref : target;
        if (store->integer != f.integer || store->text != (f.text > 0) || store->axis != f.axis || store->v.size() < 2)
            fail(code::alarm_12330, "12330 Type of parameter " + f.name + " of " + name + " incorrect: " + actual +
                                        (store->v.size() < 2 ? " is no array" : ""),
                 column);
        Variable ref;
        ref.integer = f.integer;
        ref.text = f.text > 0;
        ref.ref = store;
        ref.whole = true;
        return ref;
    }
    std::vector<double> idx;
    if (!index.empty())
        for (const std::string& part : split_args(index)) idx.push_back(eval_text(part, column));
    Variable ref;
    ref.integer = f.integer;
    ref.v.assign(1, 0.0);
    const bool r_param = var == "R" ? idx.size() == 1
                                    : var[0] == 'R' && var.size() > 1 && var.find_first_not_of("0123456789", 1) == std::string::npos &&
                                          idx.empty();
    if (r_param) {
        if (f.integer || f.text) fail(code::alarm_12330, "12330 Type of parameter " + f.name + " of " + name + " incorrect: " + actual + " is REAL", column);
        const int n = var == "R" ? int_value(idx[0]) : std::stoi(var.substr(1));
        if (n < 0 || n >= static_cast<int>(r_.size())) fail(code::alarm_17020, "17020 Illegal array index: " + actual, column);
        ref.r_index = n;
        return ref;
    }
    Variable* target = find_variable(var);
    if (!target) not_a_variable();
    if (target->r_index >= 0 || (target->ref && !target->whole)) {  // the caller's own VAR parameter
        if (!idx.empty()) not_a_variable();
        ref.r_index = target->r_index;
        ref.ref = target->ref;
        ref.ref_at = target->ref_at;
        const bool text = target->ref && target->ref->text, axis = target->ref && target->ref->axis;
        if (target->integer != f.integer || text != (f.text > 0) || axis != f.axis)
            fail(code::alarm_12330, "12330 Type of parameter " + f.name + " of " + name + " incorrect: " + actual, column);
        return ref;
    }
    Variable* store = target->ref ? target->ref : target;  // an element of a whole array the caller was given
    const auto flat = store->at(idx);
    if (!flat) fail(code::alarm_17020, "17020 Illegal array index of " + var, column);
    if (store->integer != f.integer || store->text != (f.text > 0) || store->axis != f.axis)
        fail(code::alarm_12330, "12330 Type of parameter " + f.name + " of " + name + " incorrect: " + actual, column);
    ref.text = store->text;
    ref.ref = store;
    ref.ref_at = *flat;
    return ref;
}

}  // namespace toolcomp::sinumerik
