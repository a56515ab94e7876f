#include "qparams.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

class Parser {
public:
    Parser(std::string_view s, const QLookup& q) : s_(s), q_(q) {}

    double formula() {
        double v = sum();
        skip();
        if (i_ != s_.size()) throw std::invalid_argument("unexpected '" + std::string(s_.substr(i_, 1)) + "' in formula");
        return v;
    }
    // A signed operand of an FN statement: +5, -Q3, Q2.
    double operand() {
        skip();
        double sign = 1;
        while (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) {
            if (s_[i_] == '-') sign = -sign;
            ++i_;
            skip();
        }
        return sign * atom_value();
    }
    // A label: a number (5) or a name in quotes ("END"), as the interpreter keys them.
    std::string label() {
        skip();
        if (i_ < s_.size() && s_[i_] == '"') {
            const std::size_t end = s_.find('"', i_ + 1);
            if (end == std::string_view::npos) throw std::invalid_argument("unclosed label name");
            std::string name(s_.substr(i_, end - i_ + 1));
            i_ = end + 1;
            return name;
        }
        return std::to_string(integer());
    }
    std::string word() {
        skip();
        std::string w;
        while (i_ < s_.size() && ascii_alpha(s_[i_]))
            w.push_back(ascii_upper(s_[i_++]));
        return w;
    }
    bool eat(char c) {
        skip();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    int integer() {
        skip();
        std::size_t st = i_;
        while (i_ < s_.size() && ascii_digit(s_[i_])) ++i_;
        if (st == i_) throw std::invalid_argument("number expected");
        if (i_ - st > 6) throw std::invalid_argument("number " + std::string(s_.substr(st, i_ - st)) + " out of range");
        return std::stoi(std::string(s_.substr(st, i_ - st)));
    }
    // The number of a Q parameter after the letter Q: at most five digits, as in words
    // (X+Q12345).
    int q_number() {
        skip();
        std::size_t st = i_;
        while (i_ < s_.size() && ascii_digit(s_[i_])) ++i_;
        if (st == i_) throw std::invalid_argument("Q parameter number expected");
        if (i_ - st > 5)
            throw std::invalid_argument("Q parameter number Q" + std::string(s_.substr(st, i_ - st)) + " out of range");
        return std::stoi(std::string(s_.substr(st, i_ - st)));
    }
    bool done() {
        skip();
        return i_ >= s_.size();
    }

private:
    void skip() {
        while (i_ < s_.size() && ascii_space(s_[i_])) ++i_;
    }
    double sum() {
        double v = product();
        while (true) {
            if (eat('+')) v += product();
            else if (eat('-')) v -= product();
            else return v;
        }
    }
    double product() {
        double v = power();
        while (true) {
            if (eat('*')) {
                v *= power();
            } else if (eat('/')) {
                double d = power();
                if (d == 0) throw std::domain_error("division by zero");
                v /= d;
            } else {
                return v;
            }
        }
    }
    double power() {
        double v = unary();
        if (eat('^')) v = std::pow(v, power());
        return v;
    }
    double unary() {
        // Every nesting passes here: bound it so that a pathological formula is an error,
        // not a stack overflow.
        struct Depth {
            int& d;
            explicit Depth(int& d) : d(d) {
                if (++d > 200) throw std::invalid_argument("formula nested too deeply");
            }
            ~Depth() { --d; }
        } guard(depth_);
        if (eat('-')) return -unary();
        if (eat('+')) return unary();
        return atom_value();
    }
    int depth_ = 0;
    double atom_value() {
        skip();
        if (eat('(')) {
            double v = sum();
            if (!eat(')')) throw std::invalid_argument("')' expected");
            return v;
        }
        if (i_ < s_.size() && (ascii_digit(s_[i_]) || s_[i_] == '.' || s_[i_] == ',')) {
            std::string num;
            while (i_ < s_.size() && (ascii_digit(s_[i_]) || s_[i_] == '.' || s_[i_] == ','))
                num.push_back(s_[i_] == ',' ? '.' : s_[i_]), ++i_;
            double v = 0;
            const auto res = std::from_chars(num.data(), num.data() + num.size(), v);
            if (res.ec != std::errc() || res.ptr != num.data() + num.size() || !std::isfinite(v))
                throw std::invalid_argument("bad number " + num);
            return v;
        }
        if (i_ < s_.size() && (s_[i_] == 'Q' || s_[i_] == 'q') && i_ + 1 < s_.size() &&
            ascii_digit(s_[i_ + 1])) {
            ++i_;
            return q_(q_number());
        }
        const std::string f = word();
        if (f.empty()) throw std::invalid_argument("operand expected");
        if (f == "PI") return 3.14159265358979323846;
        const double x = f == "NEG" ? -unary() : unary();
        if (f == "NEG") return x;
        if (f == "SIN") return std::sin(x * kDeg);
        if (f == "COS") return std::cos(x * kDeg);
        if (f == "TAN") return std::tan(x * kDeg);
        if (f == "ASIN" || f == "ACOS") {
            if (x < -1 || x > 1) throw std::domain_error(f + " of a value outside -1..1");
            return (f == "ASIN" ? std::asin(x) : std::acos(x)) / kDeg;
        }
        if (f == "ATAN") return std::atan(x) / kDeg;
        if (f == "SQRT") {
            if (x < 0) throw std::domain_error("square root of a negative value");
            return std::sqrt(x);
        }
        if (f == "SQ") return x * x;
        if (f == "ABS") return std::fabs(x);
        if (f == "INT") return std::trunc(x);
        if (f == "FRAC") return x - std::trunc(x);
        if (f == "LN" || f == "LOG") {
            if (x <= 0) throw std::domain_error("logarithm of a value <= 0");
            return f == "LN" ? std::log(x) : std::log10(x);
        }
        if (f == "EXP") return std::exp(x);
        if (f == "SGN") return x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0;
        throw std::invalid_argument("unknown function " + f);
    }

    std::string_view s_;
    std::size_t i_ = 0;
    const QLookup& q_;
};

int target_q(Parser& p) {
    const std::string w = p.word();
    if (w != "Q") throw std::invalid_argument("Q parameter expected");
    const int n = p.q_number();
    if (!p.eat('=')) throw std::invalid_argument("'=' expected");
    return n;
}

}  // namespace

double evaluate_formula(std::string_view text, const QLookup& q) {
    const double v = Parser(text, q).formula();
    if (!std::isfinite(v)) throw std::domain_error("result out of range");
    return v;
}

QResult run_statement(std::string_view text, const QLookup& q) {
    Parser p(text, q);
    QResult r;
    const std::string head = p.word();
    if (head == "Q") {  // Qn = formula
        const int n = p.q_number();
        if (!p.eat('=')) throw std::invalid_argument("'=' expected");
        r.assign = n;
        r.value = p.formula();
        if (!std::isfinite(r.value)) throw std::domain_error("result out of range");
        return r;
    }
    if (head != "FN") throw std::invalid_argument("FN or Q expected");
    const int fn = p.integer();
    if (!p.eat(':')) throw std::invalid_argument("':' expected after FN " + std::to_string(fn));
    switch (fn) {
        case 0: r.assign = target_q(p); r.value = p.operand(); break;
        case 1: case 2: case 3: case 4: case 8: case 13: {
            r.assign = target_q(p);
            const double a = p.operand();
            const std::string op = fn == 1 || fn == 2 ? std::string(1, "+-"[fn - 1]) : p.word();
            if (fn == 1 && !p.eat('+')) throw std::invalid_argument("'+' expected");
            if (fn == 2 && !p.eat('-')) throw std::invalid_argument("'-' expected");
            if (fn == 3 && !p.eat('*')) throw std::invalid_argument("'*' expected");
            if ((fn == 4 && op != "DIV") || (fn == 8 && op != "LEN") || (fn == 13 && op != "ANG"))
                throw std::invalid_argument("unexpected operator in FN " + std::to_string(fn));
            const double b = p.operand();
            switch (fn) {
                case 1: r.value = a + b; break;
                case 2: r.value = a - b; break;
                case 3: r.value = a * b; break;
                case 4:
                    if (b == 0) throw std::domain_error("division by zero");
                    r.value = a / b;
                    break;
                case 8: r.value = std::hypot(a, b); break;
                default: r.value = std::atan2(b, a) / kDeg; break;
            }
            break;
        }
        case 5: case 6: case 7: {
            r.assign = target_q(p);
            const std::string f = p.word();
            const double x = p.operand();
            if (fn == 5 && f == "SQRT") {
                if (x < 0) throw std::domain_error("square root of a negative value");
                r.value = std::sqrt(x);
            } else if (fn == 6 && f == "SIN") {
                r.value = std::sin(x * kDeg);
            } else if (fn == 7 && f == "COS") {
                r.value = std::cos(x * kDeg);
            } else {
                throw std::invalid_argument("unexpected function in FN " + std::to_string(fn));
            }
            break;
        }
        case 9: case 10: case 11: case 12: {
            if (p.word() != "IF") throw std::invalid_argument("IF expected");
            const double a = p.operand();
            const std::string op = p.word();
            const double b = p.operand();
            static const char* ops[4] = {"EQU", "NE", "GT", "LT"};
            if (op != ops[fn - 9]) throw std::invalid_argument("FN " + std::to_string(fn) + " needs " + ops[fn - 9]);
            if (p.word() != "GOTO" || p.word() != "LBL") throw std::invalid_argument("GOTO LBL expected");
            const std::string label = p.label();
            const bool cond = fn == 9 ? a == b : fn == 10 ? a != b : fn == 11 ? a > b : a < b;
            if (cond) r.jump = label;
            break;
        }
        case 14: {
            if (p.word() != "ERROR" || !p.eat('=')) throw std::invalid_argument("ERROR = n expected");
            r.error = p.integer();
            break;
        }
        default:
            throw std::invalid_argument("FN " + std::to_string(fn) + " is not supported by toolcomp");
    }
    if (!p.done()) throw std::invalid_argument("unexpected text after the statement");
    if (!std::isfinite(r.value)) throw std::domain_error("result out of range");
    return r;
}

}  // namespace toolcomp::heidenhain
