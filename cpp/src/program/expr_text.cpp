// Expressions with strings (the 840D's STRING): constants "...", string variables, "<<"
// joining values as text, comparisons of two strings, and the string functions STRLEN,
// INDEX, RINDEX, SUBSTR, TOUPPER, TOLOWER, NUMBER, ISNUMBER. Numbers evaluate as in expr.cpp;
// a string where a number is needed (or the reverse) is a MathError.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "toolcomp/program/expr.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::expr {

namespace {

struct Value {
    bool is_text = false;
    double d = 0;
    std::string s;
};

std::string as_text(const Value& v) { return v.is_text ? v.s : shortest_number(v.d); }

double as_number(const Value& v, const char* where) {
    if (v.is_text) throw MathError(std::string("A string (\"") + v.s + "\") where a number is expected" + where);
    return v.d;
}

// NUMBER("12.5"): the whole text must be a number.
bool parse_number(const std::string& s, double& out) {
    std::size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
    if (b == std::string::npos) return false;
    std::string_view t(s.data() + b, e - b + 1);
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    const auto r = std::from_chars(t.data(), t.data() + t.size(), out);
    return r.ec == std::errc() && r.ptr == t.data() + t.size() && std::isfinite(out);
}

Value text_call(Fn f, std::vector<Value>& a) {
    auto text = [&](std::size_t i) {
        if (!a[i].is_text) throw MathError("A string function needs a string argument");
        return a[i].s;
    };
    Value r;
    switch (f) {
        case Fn::strlen: r.d = static_cast<double>(text(0).size()); return r;
        case Fn::index:
        case Fn::rindex: {
            const std::string s = text(0), c = text(1);
            if (c.size() != 1) throw MathError("INDEX / RINDEX look for one character");
            const std::size_t at = f == Fn::index ? s.find(c[0]) : s.rfind(c[0]);
            r.d = at == std::string::npos ? -1.0 : static_cast<double>(at);
            return r;
        }
        case Fn::substr: {
            const std::string s = text(0);
            const double start = as_number(a[1], " (SUBSTR's start)");
            const double len = a.size() > 2 ? as_number(a[2], " (SUBSTR's length)") : static_cast<double>(s.size());
            if (start < 0 || len < 0 || start != std::floor(start) || len != std::floor(len))
                throw MathError("SUBSTR: start and length are whole numbers of 0 or more");
            r.is_text = true;
            if (start < static_cast<double>(s.size())) r.s = s.substr(static_cast<std::size_t>(start), static_cast<std::size_t>(std::min(len, 1e9)));
            return r;
        }
        case Fn::toupper:
        case Fn::tolower:
            r.is_text = true;
            r.s = text(0);
            for (char& c : r.s) c = f == Fn::toupper ? ascii_upper(c) : (c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c);
            return r;
        case Fn::number:
            if (!parse_number(text(0), r.d)) throw MathError("NUMBER: \"" + text(0) + "\" is no number");
            return r;
        case Fn::axstring:  // an AXIS variable reads as its name
            r.is_text = true;
            r.s = text(0);
            return r;
        case Fn::axname:
            throw MathError("AXNAME(...) gives an axis: only where an AXIS is expected");
        case Fn::isnumber: {
            double ignored;
            r.d = parse_number(text(0), ignored) ? 1 : 0;
            return r;
        }
        default: {
            std::vector<double> n;
            for (const Value& v : a) n.push_back(as_number(v, ""));
            r.d = apply_function(f, n.data());
            return r;
        }
    }
}

// An operator on numbers: expr.cpp's arithmetic, run on an expression of the operands.
double numeric(std::initializer_list<double> operands, Op op) {
    struct NoVariables : Env {
        double get(const std::string&, std::span<const double>) override { return 0; }
    } none;
    Expr e;
    for (double v : operands) e.code.push_back(Instr{Op::number, 0, Fn::sin, 0, v});
    e.code.push_back(Instr{op, 0, Fn::sin, 0, 0});
    return evaluate(e, none);
}

Value binary(Op op, const Value& a, const Value& b) {
    Value r;
    if (op == Op::concat) {
        r.is_text = true;
        r.s = as_text(a) + as_text(b);
        return r;
    }
    if (a.is_text || b.is_text) {
        if (!a.is_text || !b.is_text) throw MathError("A string compared with a number");
        const int c = a.s.compare(b.s);
        switch (op) {
            case Op::eq: r.d = c == 0; break;
            case Op::ne: r.d = c != 0; break;
            case Op::lt: r.d = c < 0; break;
            case Op::le: r.d = c <= 0; break;
            case Op::gt: r.d = c > 0; break;
            case Op::ge: r.d = c >= 0; break;
            default: throw MathError("Strings only join (<<) and compare");
        }
        return r;
    }
    r.d = numeric({a.d, b.d}, op);
    return r;
}

Value run_text(const Expr& e, Env& env) {
    std::vector<Value> stack;
    for (const Instr& in : e.code) {
        if (stack.size() > 512) throw MathError("Expression too complex");
        switch (in.op) {
            case Op::number: stack.push_back({false, in.value, {}}); break;
            case Op::text: stack.push_back({true, 0, e.texts[in.name]}); break;
            case Op::variable: {
                std::vector<double> idx;
                for (std::size_t k = stack.size() - in.argc; k < stack.size(); ++k) idx.push_back(as_number(stack[k], " (an index)"));
                stack.resize(stack.size() - in.argc);
                if (auto t = env.text(e.names[in.name], idx)) stack.push_back({true, 0, std::move(*t)});
                else stack.push_back({false, env.get(e.names[in.name], idx), {}});
                break;
            }
            case Op::call: {
                std::vector<Value> a(stack.end() - in.argc, stack.end());
                stack.resize(stack.size() - in.argc);
                stack.push_back(text_call(in.fn, a));
                break;
            }
            case Op::neg: stack.back() = {false, -as_number(stack.back(), ""), {}}; break;
            case Op::logical_not: stack.back() = {false, as_number(stack.back(), "") == 0 ? 1.0 : 0.0, {}}; break;
            case Op::bit_not: stack.back() = {false, numeric({as_number(stack.back(), "")}, Op::bit_not), {}}; break;
            case Op::param: case Op::exists: case Op::exists_number:
                throw MathError("Parameters are not available with strings");
            default: {
                const Value b = stack.back();
                stack.pop_back();
                stack.back() = binary(in.op, stack.back(), b);
            }
        }
    }
    if (stack.size() != 1) throw MathError("Expression expected");
    return stack.back();
}

}  // namespace

double evaluate_with_text(const Expr& e, Env& env) { return as_number(run_text(e, env), ""); }

std::string evaluate_text(const Expr& e, Env& env) { return as_text(run_text(e, env)); }

}  // namespace toolcomp::expr
