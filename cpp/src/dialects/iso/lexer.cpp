#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/decimal.hpp"
#include "toolcomp/program/text.hpp"

#include "codes.hpp"
#include "line_lexer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

namespace toolcomp::iso {

namespace {

// 1 for the characters that end a run of ordinary ones: blanks, '(' and ';'.
constexpr auto kCharClass = [] {
    std::array<std::uint8_t, 256> t{};
    for (unsigned char c : {' ', '\t', '\r', '\f', '\v', '(', ';'}) t[c] = 1;
    return t;
}();

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

std::optional<double> LineLexer::constant_value(const expr::Expr& e) const {
    for (const expr::Instr& in : e.code)
        if (in.op == expr::Op::variable || in.op == expr::Op::param || in.op == expr::Op::exists) return std::nullopt;
    struct NoParameters : expr::Env {
        double get(const std::string&, std::span<const double>) override { return 0; }
    } none;
    try {
        return expr::evaluate(e, none, &syntax());
    } catch (const expr::MathError&) {
        return std::nullopt;  // [1/0]: an error when (and only if) the block runs
    }
}

LineLexer::LineLexer(std::string_view line, int line_no, Program& prog, LineBuffers& b)
    : s_(b.text), shifts_(b.shifts), raw_(line), line_(line_no), prog_(prog),
      macros_(prog.dialect == Dialect::linuxcnc || prog.dialect == Dialect::fanuc) {
    // LinuxCNC's reading: blanks dropped outside comments; comment texts kept as written.
    // Where blanks were dropped, `shifts_` records how far the source columns move on.
    shifts_.clear();
    const std::size_t n = line.size();
    s_.resize(n);  // the buffer keeps its capacity from line to line
    char* out = s_.data();
    std::size_t o = 0, k = 0;
    while (k < n) {
        const char c = line[k];
        if (kCharClass[static_cast<unsigned char>(c)] == 0) {
            out[o++] = c;
            ++k;
        } else if (c == '(') {
            const std::size_t close = line.find(')', k);
            const std::size_t end = close == std::string_view::npos ? n : close + 1;
            std::copy(line.data() + k, line.data() + end, out + o);
            o += end - k;
            k = end;
        } else if (c == ';') {
            std::copy(line.data() + k, line.data() + n, out + o);
            o += n - k;
            k = n;
        } else {
            while (k < n && is_blank(line[k])) ++k;
            shifts_.push_back({o, static_cast<int>(k)});
        }
    }
    s_.resize(o);
    std::size_t last = line.size();
    while (last > 0 && is_blank(line[last - 1])) --last;
    end_col_ = static_cast<int>(last) + 1;
}

void LineLexer::fail_at(const char* code, const std::string& msg, std::size_t i) const {
    throw ParseError(code, msg, {line_, col_at(i)});
}

void LineLexer::run() {
    bool block_delete = false;
    if (!at_end() && s_[i_] == '/') {
        block_delete = true;
        ++i_;
    }
    prog_.begin_block(line_, block_delete);
    while (!at_end()) {
        const char c = s_[i_];
        if (c == '(') {
            comment_paren();
            continue;
        }
        if (c == ';') {
            prog_.add_comment({s_.substr(i_ + 1), col(), true});
            break;
        }
        const char u = c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c;
        if (macros()) {
            if (u == 'O' && first_word_) {
                o_word();
                return;
            }
            if (u == '#') {
                assignment();
                first_word_ = false;
                continue;
            }
            if (first_word_ && prog_.dialect == Dialect::fanuc && fanuc_statement()) continue;
        } else if (u == '#' || u == '[') {
            fail(code::parameters_not_supported, "Parameters and expressions ('#', '[') are not supported in this dialect");
        } else if (u == 'O' && first_word_) {
            fail(code::o_word_not_supported, "O-word subprograms and control flow are not supported in this dialect");
        }
        if (u == '$' && prog_.dialect != Dialect::linuxcnc)
            fail(code::bad_character, "Unknown word where unary operation could be");
        if (!is_word_letter(u, prog_.dialect) || (u == 'N' && (!first_word_ || prog_.blocks().back().word_count > 0))) {
            // LinuxCNC writes a byte beyond ASCII as an octal escape ('\303')
            const auto byte = static_cast<unsigned char>(c);
            std::string shown(1, ascii_lower(c));
            if (byte >= 0x80) shown = {'\\', static_cast<char>('0' + (byte >> 6)), static_cast<char>('0' + ((byte >> 3) & 7)),
                                       static_cast<char>('0' + (byte & 7))};
            fail(code::bad_character, "Bad character '" + shown + "' used");
        }
        Word w{u, 0, col()};
        ++i_;
        // LinuxCNC reads a line number as unsigned digits
        if (u == 'N' && prog_.dialect == Dialect::linuxcnc && i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-'))
            fail(code::bad_line_number, "Bad format unsigned integer");
        word_value(w);
        // LinuxCNC 2.9's Fanuc-style subprogram call and return, as a line's first word.
        if (u == 'M' && prog_.dialect == Dialect::linuxcnc && first_word_ && w.expr < 0 && (w.value == written(M98) || w.value == written(M99))) {
            Statement st;
            st.kind = w.value == written(M98) ? Stmt::m98_call : Stmt::m99_return;
            st.column = w.column;
            prog_.add_statement(std::move(st));
            first_word_ = false;
            if (w.value == written(M98)) {  // the call is the statement; M99 stays a word for the main program
                m98_ = true;
                continue;
            }
        }
        prog_.add_word(w);
        if (u != 'N') first_word_ = false;
    }
    if (m98_) {  // LinuxCNC reads the call's P when it reads the line
        bool p = false;
        for (const Word& w : prog_.words(prog_.blocks().back())) p = p || w.letter == 'P';
        if (!p) fail_at(code::program_number_missing, "Found 'm98' code with no P-word", 0);
    }
}

void LineLexer::comment_paren() {
    const std::size_t open = i_;
    std::size_t start = ++i_;
    while (i_ < s_.size() && s_[i_] != ')') {
        if (s_[i_] == '(') fail(code::nested_comment, "Nested comment found");
        ++i_;
    }
    if (i_ >= s_.size()) fail_at(code::unclosed_comment, "Unclosed comment found", open);
    prog_.add_comment({s_.substr(start, i_ - start), col_at(open)});
    ++i_;
}

void LineLexer::word_value(Word& w) {
    if (macros() && !at_end()) {
        std::size_t k = i_;
        while (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
        const char c = k < s_.size() ? s_[k] : 0;
        const bool letter = prog_.dialect == Dialect::linuxcnc && ascii_alpha(c);
        if (c == '#' || c == '[' || letter) {
            const std::int32_t e = expression(true);
            if (auto v = constant_value(prog_.expression(e))) {
                w.value = *v;  // "X[2*3]" is X6: nothing to evaluate at run time
                prog_.drop_last_expression();
            } else {
                w.expr = e;
            }
            return;
        }
    }
    w.value = number();
}

// A real number, read as LinuxCNC's read_real_value does: a sign followed by anything but a
// digit or a point is a unary operator; then the number itself, one sign and a run of
// digits and points. Messages are LinuxCNC's, quoting what the number read.
// Up to 15 digits the value is taken in the same pass (parse_decimal's fast path).
double LineLexer::number() {
    const char* const s = s_.data();
    const std::size_t n = s_.size();
    std::size_t i = i_;
    bool negative = false;
    const std::size_t start = i;  // errors point at the number's first character
    if (i >= n) fail_at(code::bad_number_format, "No characters found in reading real value", start);
    const auto sign = [&](std::size_t k) { return k < n && (s[k] == '+' || s[k] == '-'); };
    while (sign(i) && i + 1 < n && !ascii_digit(s[i + 1]) && s[i + 1] != '.') {
        if (s[i] == '-') negative = !negative;
        ++i;
    }
    const std::size_t own = i;  // the number's own sign, if any, is part of its text
    if (sign(i)) {
        if (s[i] == '-') negative = !negative;
        ++i;
    }
    const std::size_t first = i;  // the line has no blanks here: the number is one run
    const DecimalRun run = scan_decimal_run(s, i, n);
    i_ = run.end;
    const std::string_view text(s + first, run.end - first), quoted(s + own, run.end - own);
    if (run.points > 1)
        fail_at(code::bad_number_format, "bad number format (trailing characters) parsing '" + std::string(quoted) + "'", start);
    if (!run.digits)
        fail_at(code::bad_number_format, "bad number format (conversion failed) parsing '" + std::string(quoted) + "'", start);
    double v = 0;
    if (run.plain())
        v = decimal_value(run.m, run.frac);
    else if (!parse_decimal(text, v) || !std::isfinite(v))
        fail_at(code::bad_number_format, "bad number format (conversion failed) parsing '" + std::string(quoted) + "'", start);
    return negative ? -v : v;
}

Program parse(std::string_view text, Dialect dialect, std::string name, bool strict) {
    return PieceParser(dialect, std::move(name), strict).parse(text);
}

Program PieceParser::parse(std::string_view text, Program prog) {
    if (cr_ends_line(dialect_) && has_lone_cr(text)) {  // CR line ends (file pieces come as LF)
        std::string lf(text);
        cr_line_ends_to_lf(lf.data(), lf.size(), true);
        return parse(std::string_view(lf), std::move(prog));
    }
    if (first_) text = skip_bom(text);
    first_ = false;
    prog.clear();
    prog.name = name_;
    prog.dialect = dialect_;
    {
        // Room for the blocks and words of the text (of a whole piece, for pieces) at the most
        // blocks and words a byte the pieces before had, with an eighth to spare: the columns
        // grow if it is more (and keep that room when parsed over). A text parsed whole has
        // a block a line at most.
        const double room = static_cast<double>(std::max(text.size(), piece_bytes_)) * 1.125;
        const std::size_t blocks = piece_bytes_ > 0
                                       ? static_cast<std::size_t>(room * blocks_per_byte_) + 16
                                       : line_ends(text) + 1;
        prog.reserve(blocks, static_cast<std::size_t>(room * words_per_byte_) + 16);
    }
    LineBuffers buffers;
    for (std::size_t pos = 0; pos < text.size() && !done_;) {
        std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        std::string_view line = text.substr(pos, nl - pos);
        ++line_no_;
        pos = nl + 1;
        if (blank_line(line)) continue;
        if (trimmed(line) == "%") {
            last_line_ = line_no_;
            if (dialect_ == Dialect::linuxcnc && seen_content_ && !percent_open_) {
                // A "%" line in a program that did not open with one: LinuxCNC reads it like
                // any other line, a bad character, when it gets there; a program that ends
                // before it (M2 / M30 ... %, a common ending) never does. So the program stops
                // here, with the error kept for a run that reaches it, even when reading strictly.
                const int at = static_cast<int>(line.find('%')) + 1;
                prog.syntax_error = ParseError(code::bad_character, "Bad character '%' used", {line_no_, at}).diagnostic();
                done_ = true;
                break;
            }
            // "%" on the first non-blank line opens the program; the next one closes it.
            if (percent_open_) {
                percent_closed_ = done_ = true;
                break;
            }
            if (!seen_content_) percent_open_ = true;
            seen_content_ = true;
            continue;
        }
        seen_content_ = true;
        last_line_ = line_no_;
        const std::size_t exprs = prog.expression_count();
        try {
            // LinuxCNC reads at most 252 characters a line (a CR of a CRLF end counts).
            if (dialect_ == Dialect::linuxcnc && line.size() > 252)
                throw ParseError(code::line_too_long, "Command too long", {line_no_, 253});
            if (!lex_line_fast(line, line_no_, prog)) LineLexer(line, line_no_, prog, buffers).run();
        } catch (const ParseError& e) {
            if (strict_) throw;
            // The block of the failing line, if it was begun (a line refused for its length
            // never is: the block before it stays).
            if (prog.size() && prog.blocks().back().line == line_no_) prog.drop_last_block();
            prog.drop_expressions_from(exprs);  // and the expressions it had read
            prog.syntax_error = e.diagnostic();
            done_ = true;
        }
    }
    if (text.size() >= 4096) {
        const double bytes = static_cast<double>(text.size());
        blocks_per_byte_ = std::max(blocks_per_byte_, static_cast<double>(prog.size()) / bytes);
        words_per_byte_ = std::max(words_per_byte_, static_cast<double>(prog.word_count()) / bytes);
    }
    prog.last_line = last_line_;
    prog.percent_open = percent_open_;
    prog.percent_closed = percent_closed_;
    return prog;
}

}  // namespace toolcomp::iso
