#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/decimal.hpp"
#include "toolcomp/program/text.hpp"
#include "words.hpp"

#include <cctype>
#include <charconv>
#include <cstring>
#include <optional>

namespace toolcomp::heidenhain {

namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

class LineLexer {
public:
    LineLexer(std::string_view line, int line_no, Program& prog) : s_(line), line_(line_no), prog_(prog) {}

    void run() {
        skip();
        // Block number.
        while (i_ < s_.size() && ascii_digit(s_[i_])) ++i_;
        skip();
        prog_.begin_block(line_, false);
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
            if (program_name_next()) {
                program_name();
                continue;
            }
            token();
        }
    }

private:
    int col() const { return static_cast<int>(i_) + 1; }
    // After CALL PGM comes a file name (SUB1, PART.H, TNC:\DIR\SUB.H), not words.
    bool program_name_next() const {
        auto t = prog_.tokens(prog_.blocks().back());
        return t.size() == 2 && t[0].is("CALL") && t[1].is("PGM") && !t[1].has_value;
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
                                  s_[i_] == '_')) {
            // A '.' belongs to the key only between letters (CUR.TIME); "0.1" is a number.
            if (s_[i_] == '.' && (t.key.empty() || i_ + 1 >= s_.size() || !ascii_alpha(s_[i_ + 1])))
                break;
            t.key.push_back(ascii_upper(s_[i_]));
            ++i_;
        }
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
};

bool is_blank_line(std::string_view l) {
    for (char c : l)
        if (!blank(c)) return false;
    return true;
}

// BLK FORM 0.1 <axis> X Y Z (minimum corner) and 0.2 X Y Z (maximum), kept as the blank.
void read_blank(Program& prog, const Block& b) {
    auto t = prog.tokens(b);
    if (t.size() < 3 || !t[0].is("BLK") || !t[1].is("FORM") || !t[2].has_value) return;
    Blank bl = prog.blank.value_or(Blank{});
    const bool first = t[2].value < 0.15;
    Vec3& corner = first ? bl.min : bl.max;
    for (std::size_t i = 3; i < t.size(); ++i) {
        const std::string_view k = t[i].key;
        int axis = k == "X" || k == "IX" ? 0 : k == "Y" || k == "IY" ? 1 : k == "Z" || k == "IZ" ? 2 : -1;
        if (axis < 0) continue;
        if (!t[i].has_value) {  // the tool axis letter of BLK FORM 0.1
            bl.axis = axis;
            continue;
        }
        corner[axis] = (k[0] == 'I' ? bl.min[axis] : 0) + t[i].value;
    }
    prog.blank = bl;
}

// A program starts with BEGIN PGM and ends with END PGM: without them, a file cut short in
// a transfer would run as if it were complete.
void check_frame(Program& prog, bool ended, bool strict) {
    std::optional<ParseError> e;
    const Block* first = nullptr;  // comments before BEGIN PGM are tolerated
    for (const Block& b : prog.blocks())
        if (b.token_count > 0) {
            first = &b;
            break;
        }
    if (!first) {
        e.emplace(code::begin_pgm_missing, "The program does not start with BEGIN PGM (no blocks)",
                  SourcePos{prog.size() ? prog.blocks().front().line : 1, 1});
    } else {
        auto t = prog.tokens(*first);
        if (t.size() < 2 || !t[0].is("BEGIN") || !t[1].is("PGM"))
            e.emplace(code::begin_pgm_missing, "The program does not start with BEGIN PGM", SourcePos{first->line, t[0].column});
        else if (!ended)
            e.emplace(code::end_pgm_missing, "END PGM missing: the program ends without END PGM (cut short?)",
                      SourcePos{prog.last_line, 1});
    }
    if (!e) return;
    if (strict) throw *e;
    prog.syntax_error = e->diagnostic();
}

}  // namespace

Program parse(std::string_view text, std::string name, bool strict) {
    text = skip_bom(text);
    Program prog;
    prog.name = std::move(name);
    prog.dialect = Dialect::heidenhain;
    // About 27 bytes and 4 tokens a line in CAM output ("12 L X+100 Y+2.5 F600"): the
    // tokens' vector is not moved as it grows (two strings each).
    prog.reserve(text.size() / 24 + 1, 0, text.size() / 7 + 1);
    std::size_t pos = 0;
    int line_no = 0;
    bool ended = false;  // END PGM seen
    const auto find = [&](char c, std::size_t from, std::size_t to) {  // `to` when not found
        const void* p = std::memchr(text.data() + from, c, to - from);
        return p ? static_cast<std::size_t>(static_cast<const char*>(p) - text.data()) : to;
    };
    while (pos <= text.size()) {
        // A line ends with "\n" (CRs right before it are blanks: "\r\n", "\r\r\n") or with a
        // lone "\r" (old Mac line ends). nl: the last character of the line ending.
        const std::size_t lf = find('\n', pos, text.size());
        std::size_t nl = find('\r', pos, lf);  // the first CR or LF
        if (nl < text.size() && text[nl] == '\r') {
            std::size_t j = nl;
            while (j < text.size() && text[j] == '\r') ++j;
            if (j < text.size() && text[j] == '\n') nl = j;
        }
        std::string_view line = text.substr(pos, nl - pos);
        ++line_no;
        pos = nl + 1;
        if (!is_blank_line(line)) {
            try {
                LineLexer(line, line_no, prog).run();
                check_path_words(prog.tokens(prog.blocks().back()), line_no);
            } catch (const ParseError& e) {
                if (strict) throw;
                if (prog.size() && prog.blocks().back().line == line_no) prog.drop_last_block();  // if begun
                prog.syntax_error = e.diagnostic();
                break;
            }
            const Block& b = prog.blocks().back();
            prog.last_line = line_no;
            auto t = prog.tokens(b);
            if (t.size() >= 2 && t[0].is("BEGIN") && t[1].is("PGM"))
                for (const Token& k : t) prog.inch = prog.inch || k.is("INCH");
            read_blank(prog, b);
            if (t.size() >= 2 && t[0].is("END") && t[1].is("PGM")) {
                ended = true;
                break;
            }
        }
        if (nl == text.size()) break;
    }
    if (!prog.syntax_error) check_frame(prog, ended, strict);
    return prog;
}

}  // namespace toolcomp::heidenhain
