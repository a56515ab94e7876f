// The general lexer of one Klartext line: block skip and number, structure blocks, Q
// parameter statements kept as text, and the words of a function with their values as
// written (signs, Q parameters, spaced values, decimal commas, F MAX, program names).
#include "line_lexer.hpp"

#include <string>
#include <utility>

#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/decimal.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::heidenhain {

namespace {

// Addresses whose value may stand apart from them ("L Z 25.000 FMAX", "L Z + Q13", "IZ - 2.5",
// as hand-written programs and some posts put it): the value is read across the blanks.
bool spaced_address(std::string_view k) {
    static constexpr std::string_view kAddresses[] = {"X",  "Y",  "Z",  "A",  "B",   "C",   "U",  "V",  "W",
                                                      "IX", "IY", "IZ", "IA", "IB",  "IC",  "IU", "IV", "IW",
                                                      "F",  "S",  "R",  "DR", "PR",  "PA",  "IPR", "IPA",
                                                      "CCA", "LEN", "MB"};
    for (std::string_view a : kAddresses)
        if (k == a) return true;
    return false;
}

class LineLexer {
public:
    // `continued`: the line goes on with the block of the line before, which ended with '~'
    // (a cycle definition's parameters, one a line; or a long comment wrapped: `in_comment`).
    LineLexer(std::string_view line, int line_no, Program& prog, bool continued = false, bool in_comment = false)
        : s_(line), line_(line_no), prog_(prog), continued_(continued), in_comment_(in_comment) {}

    void run() {
        skip();
        if (continued_) {
            if (in_comment_ && !cycle_parameter_next()) {  // the rest of a wrapped comment
                prog_.add_comment({std::string(s_.substr(i_)), col()});
                return;
            }
            words();
            return;
        }
        // The block skip '/' (before or after the block number), the block number.
        bool skipped = false;
        if (i_ < s_.size() && s_[i_] == '/') skipped = true, ++i_, skip();
        while (i_ < s_.size() && ascii_digit(s_[i_])) ++i_;
        skip();
        if (i_ < s_.size() && s_[i_] == '/') skipped = true, ++i_, skip();
        prog_.begin_block(line_, skipped);
        if (i_ < s_.size() && s_[i_] == '*') {  // structure block
            prog_.add_comment({std::string(s_.substr(i_ + 1)), col()});
            return;
        }
        // Q parameter statements (FN n: ..., Qn = formula) are kept as text for the evaluator.
        {
            std::size_t j = i_;
            bool q_formula = false;
            if (j < s_.size() && (s_[j] == 'Q' || s_[j] == 'q')) {
                std::size_t k = j + 1;
                while (k < s_.size() && ascii_digit(s_[k])) ++k;
                while (k < s_.size() && blank(s_[k])) ++k;
                q_formula = k > j + 1 && k < s_.size() && s_[k] == '=';
            }
            const bool fn = s_.size() >= j + 2 && ascii_upper(s_[j]) == 'F' &&
                            ascii_upper(s_[j + 1]) == 'N' &&
                            (j + 2 >= s_.size() || !ascii_alpha(s_[j + 2]));
            if (q_formula || fn) {
                std::size_t end = s_.find(';', j);
                Token t;
                t.key = fn ? "FN" : "Q=";
                t.text = std::string(s_.substr(j, end == std::string_view::npos ? std::string_view::npos : end - j));
                t.column = col();
                prog_.add_token(std::move(t));
                if (end != std::string_view::npos) prog_.add_comment({std::string(s_.substr(end + 1)), static_cast<int>(end) + 1});
                return;
            }
        }
        words();
    }

private:
    void words() {
        while (true) {
            skip();
            if (i_ >= s_.size()) break;
            if (s_[i_] == ';') {
                prog_.add_comment({std::string(s_.substr(i_ + 1)), col()});
                break;
            }
            if (s_[i_] == '"') {
                quoted();
                continue;
            }
            if (s_[i_] == '#' && i_ + 1 < s_.size() && ascii_digit(s_[i_ + 1])) {  // CYCL DEF 7.1 #5: a table row
                Token t;
                t.key = "#";
                t.column = col();
                std::size_t end = ++i_;
                while (end < s_.size() && ascii_digit(s_[end])) ++end;
                t.value = std::stod(std::string(s_.substr(i_, end - i_)));
                t.has_value = true;
                i_ = end;
                prog_.add_token(std::move(t));
                continue;
            }
            if (s_[i_] == '(' || s_[i_] == ')') {  // PATTERN DEF: POS1 ( X+25 Y+33.5 Z+0 )
                Token t;
                t.key = std::string(1, s_[i_]);
                t.column = col();
                prog_.add_token(std::move(t));
                ++i_;
                continue;
            }
            if (program_name_next()) {
                program_name();
                continue;
            }
            token();
        }
    }

    int col() const { return static_cast<int>(i_) + 1; }
    bool cycle_parameter_next() const {  // Q200=...
        std::size_t j = i_;
        if (j >= s_.size() || ascii_upper(s_[j]) != 'Q') return false;
        ++j;
        const std::size_t digits = j;
        while (j < s_.size() && ascii_digit(s_[j])) ++j;
        while (j < s_.size() && blank(s_[j])) ++j;
        return j > digits && j < s_.size() && s_[j] == '=';
    }
    // After CALL PGM comes a file name (SUB1, PART.H, TNC:\DIR\SUB.H), after BEGIN PGM and
    // END PGM the program's name (letters, digits, '.', '_', '-' in any order: 0TREF,
    // 11setup, contour-cut), not words.
    bool program_name_next() const {
        auto t = prog_.tokens(prog_.blocks().back());
        return t.size() == 2 && (t[0].is("CALL") || t[0].is("BEGIN") || t[0].is("END")) && t[1].is("PGM") &&
               !t[1].has_value;
    }
    // After a blank: a sign, a number or a Q parameter (the value of a spaced address).
    bool value_after_blanks() const {
        std::size_t j = i_;
        while (j < s_.size() && blank(s_[j])) ++j;
        if (j == i_ || j >= s_.size()) return false;
        const char c = s_[j];
        return c == '+' || c == '-' || ascii_digit(c) || c == '.' ||
               ((c == 'Q' || c == 'q') && j + 1 < s_.size() && ascii_digit(s_[j + 1]));
    }
    bool word_after_blanks(std::string_view word) const {
        std::size_t j = i_;
        while (j < s_.size() && blank(s_[j])) ++j;
        if (j == i_ || s_.size() - j < word.size()) return false;
        for (std::size_t k = 0; k < word.size(); ++k)
            if (ascii_upper(s_[j + k]) != word[k]) return false;
        return j + word.size() == s_.size() || blank(s_[j + word.size()]) || s_[j + word.size()] == ';';
    }
    void program_name() {
        Token t;
        t.column = col();
        const std::size_t start = i_;
        while (i_ < s_.size() && !blank(s_[i_]) && s_[i_] != ';') ++i_;
        t.text = std::string(s_.substr(start, i_ - start));
        prog_.add_token(std::move(t));
    }
    void skip() {
        while (i_ < s_.size() && blank(s_[i_])) ++i_;
    }
    [[noreturn]] void fail(const char* code, const std::string& msg, int column) {
        throw ParseError(code, msg, {line_, column});
    }
    void quoted() {
        int column = col();
        std::size_t end = s_.find('"', i_ + 1);
        if (end == std::string_view::npos) fail(code::unclosed_name, "Unclosed quotation mark", column);
        Token t;
        t.text = std::string(s_.substr(i_ + 1, end - i_ - 1));
        t.column = column;
        prog_.add_token(std::move(t));
        i_ = end + 1;
    }
    void token() {
        Token& t = prog_.new_token();  // filled in place; a failure drops the block
        t.column = col();
        while (i_ < s_.size() && (ascii_alpha(s_[i_]) || s_[i_] == '.' || s_[i_] == ':' ||
                                  s_[i_] == '_' || s_[i_] == '-')) {
            // A '.' or '-' belongs to the key only between letters (CUR.TIME, HSC-MODE); "0.1" is
            // a number, "X-5" a word with its sign.
            if ((s_[i_] == '.' || s_[i_] == '-') &&
                (t.key.empty() || i_ + 1 >= s_.size() || !ascii_alpha(s_[i_ + 1])))
                break;
            if (s_[i_] == '-' && ascii_upper(s_[i_ + 1]) == 'Q' && i_ + 2 < s_.size() && ascii_digit(s_[i_ + 2]))
                break;  // Y-Q1: the sign of a Q parameter
            t.key.push_back(ascii_upper(s_[i_]));
            ++i_;
        }
        if (t.is("F") && word_after_blanks("MAX")) {  // F MAX: FMAX
            skip();
            i_ += 3;
            t.key = "FMAX";
            return;
        }
        if (t.is("MB") && word_after_blanks("MAX")) {  // M140 MB MAX: the retraction to the travel's end
            skip();
            i_ += 3;
            t.text = "MAX";
            return;
        }
        if (t.is("FQ") && i_ < s_.size() && ascii_digit(s_[i_])) {  // FQ58: the feed in Q58
            t.key = "F";
            --i_;
        }
        // A cycle parameter of a definition's continuation line: Q200=2 (its key Q200).
        if (continued_ && t.is("Q")) {
            std::size_t e = i_;
            while (e < s_.size() && ascii_digit(s_[e])) ++e;
            std::size_t eq = e;
            while (eq < s_.size() && blank(s_[eq])) ++eq;
            if (e > i_ && eq < s_.size() && s_[eq] == '=') {
                t.key.append(s_.substr(i_, e - i_));
                i_ = eq + 1;
                skip();
                for (std::string_view w : {"FMAX", "FAUTO", "MAX"}) {  // Q208=MAX: a feed word
                    if (s_.size() - i_ >= w.size() && s_.substr(i_, w.size()) == w &&
                        (i_ + w.size() == s_.size() || blank(s_[i_ + w.size()]) || s_[i_ + w.size()] == ';')) {
                        t.text = std::string(w);
                        i_ += w.size();
                        return;
                    }
                }
            }
        }
        if (value_after_blanks() && spaced_address(t.key)) skip();  // the cheap test first: a blank next
        // Digits followed by a sign belong to the address (R2+3, DR2-0.1, DR2+).
        std::size_t j = i_;
        while (j < s_.size() && ascii_digit(s_[j])) ++j;
        if (j > i_ && j < s_.size() && (s_[j] == '+' || s_[j] == '-') && !t.key.empty()) {
            t.key.append(s_.substr(i_, j - i_));
            i_ = j;
        }
        int sign = 1;
        bool have_sign = false;
        if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) {
            sign = s_[i_] == '-' ? -1 : 1;
            have_sign = true;
            ++i_;
            if (i_ < s_.size() && blank(s_[i_]) && spaced_address(t.key)) {  // "Z + Q13", "IZ - 2.5"
                std::size_t k = i_;
                while (k < s_.size() && blank(s_[k])) ++k;
                if (k < s_.size() && (ascii_digit(s_[k]) || s_[k] == '.' || s_[k] == 'Q' || s_[k] == 'q')) i_ = k;
            }
        }
        if (i_ + 1 < s_.size() && (s_[i_] == 'Q' || s_[i_] == 'q') && ascii_digit(s_[i_ + 1]) &&
            !t.key.empty()) {
            // A Q parameter in place of the number: X+Q5
            ++i_;
            std::string digits;
            while (i_ < s_.size() && ascii_digit(s_[i_])) digits.push_back(s_[i_++]);
            if (digits.size() > 5) fail(code::bad_word, "Q parameter number Q" + digits + " out of range", col());
            t.param = std::stoi(digits) + 1;  // the Q number + 1: Q0 is a parameter too
            t.value = sign;
            t.has_value = true;
            if (i_ < s_.size() && !blank(s_[i_]) && s_[i_] != ';')
                fail(code::bad_word, "Unexpected character '" + std::string(1, s_[i_]) + "'", col());
            return;
        }
        const std::size_t num_begin = i_;
        bool comma = false;
        while (i_ < s_.size() && (ascii_digit(s_[i_]) || s_[i_] == '.' || s_[i_] == ',')) comma |= s_[i_++] == ',';
        // The number's text as written; a decimal comma or a leading point: rewritten.
        std::string_view num(s_.data() + num_begin, i_ - num_begin);
        std::string rewritten;
        if (comma || (!num.empty() && num.front() == '.')) {
            if (num.front() == '.' || num.front() == ',') rewritten = "0";
            for (char c : num) rewritten.push_back(c == ',' ? '.' : c);
            num = rewritten;
        }
        if ((t.is("REP") || t.key.empty()) && i_ < s_.size() && s_[i_] == '/')  // REP 2/2: the count of passes left
            while (i_ < s_.size() && !blank(s_[i_])) ++i_;
        if (i_ < s_.size() && !blank(s_[i_]) && s_[i_] != ';')
            fail(code::bad_word, "Unexpected character '" + std::string(1, s_[i_]) + "'", col());
        if (!num.empty()) {
            double v = 0;
            if (!parse_decimal(num, v)) fail(code::bad_number_format, "Bad number '" + std::string(num) + "'", t.column);
            t.value = sign * v;
            t.has_value = true;
        } else if (have_sign) {
            t.value = sign;
            t.sign_only = true;
        } else if (t.key.empty()) {
            fail(code::bad_word, "Unexpected character", t.column);
        }
    }

    std::string_view s_;
    std::size_t i_ = 0;
    int line_;
    Program& prog_;
    bool continued_ = false, in_comment_ = false;
};

}  // namespace

void lex_line(std::string_view line, int line_no, Program& prog, bool continued, bool in_comment) {
    LineLexer(line, line_no, prog, continued, in_comment).run();
}

}  // namespace toolcomp::heidenhain
