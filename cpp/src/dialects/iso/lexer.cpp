#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/program/text.hpp"

#include <cctype>
#include <charconv>
#include <string>

namespace toolcomp::iso {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Letters that are address words in ISO G-code (LinuxCNC's set for a machine with axes
// XYZABC; O, #, [ are the programming features of a later stage, reported as unsupported).
bool is_word_letter(char u, Dialect d) {
    // Fanuc and 9/Series: U V W are words too (incremental X Y Z on lathes, extra axes on mills).
    if ((u == 'U' || u == 'V' || u == 'W') && (d == Dialect::fanuc || d == Dialect::rockwell)) return true;
    switch (u) {
        case 'A': case 'B': case 'C': case 'D': case 'E': case 'F': case 'G': case 'H': case 'I':
        case 'J': case 'K': case 'L': case 'M': case 'N': case 'P': case 'Q': case 'R':
        case 'S': case 'T': case 'X': case 'Y': case 'Z':
            return true;
        default:
            return false;
    }
}

class LineLexer {
public:
    LineLexer(std::string_view line, int line_no, Program& prog)
        : s_(line), line_(line_no), prog_(prog) {}

    void run() {
        skip_blanks();
        bool block_delete = false;
        if (i_ < s_.size() && s_[i_] == '/') {
            block_delete = true;
            ++i_;
        }
        prog_.begin_block(line_, block_delete);
        bool first_word = true;
        while (true) {
            skip_blanks();
            if (i_ >= s_.size()) break;
            char c = s_[i_];
            if (c == '(') {
                comment_paren();
                continue;
            }
            if (c == ';') {
                prog_.add_comment({std::string(s_.substr(i_ + 1)), col()});
                break;
            }
            char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            if (u == '#' || u == '[')
                fail("parameters_not_supported",
                     "Parameters and expressions ('#', '[') are not supported yet");
            if (u == '$') fail("bad_character", "Unknown word where unary operation could be");
            if (u == 'O' && first_word)
                fail("o_word_not_supported", "O-word subprograms and control flow are not supported yet");
            if (!is_word_letter(u, prog_.dialect) || (u == 'N' && !first_word)) {
                char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
                fail("bad_character", std::string("Bad character '") + lower + "' used");
            }
            int column = col();
            ++i_;
            prog_.add_word({u, number(), column});
            first_word = false;
        }
    }

private:
    int col() const { return static_cast<int>(i_) + 1; }
    [[noreturn]] void fail(const char* code, const std::string& msg) {
        throw ParseError(code, msg, {line_, col()});
    }
    void skip_blanks() {
        while (i_ < s_.size() && is_blank(s_[i_])) ++i_;
    }
    void comment_paren() {
        int column = col();
        std::size_t start = ++i_;
        while (i_ < s_.size() && s_[i_] != ')') {
            if (s_[i_] == '(') fail("nested_comment", "Nested comment found");
            ++i_;
        }
        if (i_ >= s_.size()) {
            i_ = static_cast<std::size_t>(column - 1);
            fail("unclosed_comment", "Unclosed comment found");
        }
        prog_.add_comment({std::string(s_.substr(start, i_ - start)), column});
        ++i_;
    }
    // A real number: signs, then a run of digits and points; blanks may appear anywhere
    // inside (LinuxCNC strips them before reading). Messages are LinuxCNC's.
    double number() {
        bool negative = false;
        skip_blanks();
        const std::size_t start = i_;  // errors point at the number's first character
        while (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) {
            if (s_[i_] == '-') negative = !negative;
            ++i_;
            skip_blanks();
        }
        std::string text;
        int points = 0;
        bool digits = false;
        while (true) {
            skip_blanks();
            if (i_ >= s_.size()) break;
            char c = s_[i_];
            if (c >= '0' && c <= '9') {
                digits = true;
            } else if (c == '.') {
                ++points;
            } else {
                break;
            }
            text.push_back(c);
            ++i_;
        }
        const std::size_t end = i_;
        i_ = start;
        if (text.empty()) fail("bad_number_format", "No characters found in reading real value");
        if (points > 1)
            fail("bad_number_format", "bad number format (trailing characters) parsing '" + text + "'");
        if (!digits) fail("bad_number_format", "bad number format (conversion failed) parsing '" + text + "'");
        i_ = end;
        if (text.front() == '.') text.insert(text.begin(), '0');
        double v = 0;
        std::from_chars(text.data(), text.data() + text.size(), v);
        return negative ? -v : v;
    }

    std::string_view s_;
    std::size_t i_ = 0;
    int line_;
    Program& prog_;
};

bool blank_line(std::string_view l) {
    for (char c : l)
        if (!is_blank(c)) return false;
    return true;
}

std::string_view trimmed(std::string_view l) {
    while (!l.empty() && is_blank(l.front())) l.remove_prefix(1);
    while (!l.empty() && is_blank(l.back())) l.remove_suffix(1);
    return l;
}

}  // namespace

Program parse(std::string_view text, Dialect dialect, std::string name, bool strict) {
    text = skip_bom(text);
    Program prog;
    prog.name = std::move(name);
    prog.dialect = dialect;
    prog.reserve(text.size() / 24 + 1, text.size() / 6 + 1);
    std::size_t pos = 0;
    int line_no = 0;
    bool seen_content = false, percent_open = false;
    while (pos <= text.size()) {
        std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        std::string_view line = text.substr(pos, nl - pos);
        ++line_no;
        pos = nl + 1;
        if (blank_line(line)) {
            if (nl == text.size()) break;
            continue;
        }
        if (trimmed(line) == "%") {
            // "%" on the first non-blank line opens the program; the next one closes it.
            prog.last_line = line_no;
            if (percent_open) {
                prog.percent_closed = true;
                break;
            }
            if (!seen_content) percent_open = prog.percent_open = true;
            seen_content = true;
            continue;
        }
        seen_content = true;
        prog.last_line = line_no;
        try {
            LineLexer(line, line_no, prog).run();
        } catch (const ParseError& e) {
            if (strict) throw;
            prog.drop_last_block();
            prog.syntax_error = e.diagnostic();
            break;
        }
        if (nl == text.size()) break;
    }
    return prog;
}

}  // namespace toolcomp::iso
