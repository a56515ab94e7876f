#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "control_statements.hpp"
#include "line_lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

#include <array>
#include <cmath>
#include <cstring>

namespace toolcomp::sinumerik {

bool is_address(std::string_view n) {
    if (n.size() == 1) return n[0] != 'R' && n[0] >= 'A' && n[0] <= 'Z';
    static constexpr std::array<std::string_view, 24> multi = {"CR", "AR", "TURN", "DISC", "OFFN", "RPL", "I1", "J1",
                                                               "K1", "ADIS", "ADISPOS", "TCARR", "AP", "RP", "DL",
                                                               "SF", "FAD", "DISR", "LIMS", "RND", "RNDM", "CHF",
                                                               "CHR", "ANG"};
    for (std::string_view m : multi)
        if (m == n) return true;
    return false;
}

bool is_value_call(std::string_view n) { return n == "GETTCOR" || n == "SETTCOR" || n == "LENTOAX"; }

namespace detail {

bool word_char(char c) { return ascii_alpha(c) || ascii_digit(c) || c == '_' || c == '$'; }

// DEFINE name AS text: a macro of the program; its name replaced by its text in the lines
// after it (whole words, outside strings and comments). The line itself is no block.
class Macros {
public:
    // True when `l` defines a macro (taken); throws ParseError for a bad definition.
    bool define(std::string_view l, int line) {
        std::size_t i = l.find_first_not_of(" \t");
        if (i == std::string_view::npos || l.size() - i < 7) return false;
        for (std::size_t k = 0; k < 6; ++k)
            if (ascii_upper(l[i + k]) != "DEFINE"[k]) return false;
        if (l[i + 6] != ' ' && l[i + 6] != '\t') return false;
        i = l.find_first_not_of(" \t", i + 6);
        std::size_t e = i;
        while (e < l.size() && word_char(l[e])) ++e;
        std::string name;
        for (std::size_t k = i; k < e; ++k) name.push_back(ascii_upper(l[k]));
        std::size_t as = l.find_first_not_of(" \t", e);
        if (name.empty() || as == std::string_view::npos || l.size() - as < 2 || ascii_upper(l[as]) != 'A' ||
            ascii_upper(l[as + 1]) != 'S' || (as + 2 < l.size() && l[as + 2] != ' ' && l[as + 2] != '\t'))
            throw ParseError(code::syntax_error, "12080 Syntax error: DEFINE name AS text", {line, static_cast<int>(i) + 1, {}});
        std::string_view body = l.substr(std::min(l.size(), as + 2));
        if (const auto c = body.find(';'); c != std::string_view::npos) body = body.substr(0, c);
        const auto b = body.find_first_not_of(" \t");
        body = b == std::string_view::npos ? std::string_view() : body.substr(b, body.find_last_not_of(" \t") - b + 1);
        for (const auto& [n, t] : list_)
            if (n == name)
                throw ParseError(code::syntax_error, "12270 Macro name " + name + " already defined", {line, static_cast<int>(i) + 1, {}});
        list_.emplace_back(std::move(name), expand(body, line));  // macros in its text: theirs (defined before)
        return true;
    }
    bool empty() const { return list_.empty(); }
    // `l` with the macros' names replaced by their text (at most kMaxExpanded characters: macros
    // of macros would otherwise grow without bound).
    static constexpr std::size_t kMaxExpanded = 1 << 16;
    std::string expand(std::string_view l, int line = 0) const {
        std::string out;
        bool quoted = false;
        for (std::size_t i = 0; i < l.size();) {
            const char c = l[i];
            if (!quoted && c == ';') {
                out.append(l.substr(i));
                break;
            }
            if (c == '"') quoted = !quoted;
            if (quoted || !word_char(c) || (i > 0 && word_char(l[i - 1]))) {
                out.push_back(c);
                ++i;
                continue;
            }
            std::size_t e = i;
            std::string word;
            while (e < l.size() && word_char(l[e])) word.push_back(ascii_upper(l[e++]));
            const std::string* text = nullptr;
            for (const auto& [n, t] : list_)
                if (n == word) text = &t;
            if (text) out += *text;
            else out.append(l.substr(i, e - i));
            if (out.size() > kMaxExpanded)
                throw ParseError(code::syntax_error, "12080 Syntax error: a line with its macros is longer than " +
                                                         std::to_string(kMaxExpanded) + " characters",
                                 {line, static_cast<int>(i) + 1, {}});
            i = e;
        }
        return out;
    }

private:
    std::vector<std::pair<std::string, std::string>> list_;
};

}  // namespace detail

PieceParser::PieceParser(std::string name, bool strict, std::size_t piece_bytes)
    : name_(std::move(name)), strict_(strict), piece_bytes_(piece_bytes), macros_(std::make_unique<detail::Macros>()) {}
PieceParser::~PieceParser() = default;
PieceParser::PieceParser(PieceParser&&) noexcept = default;
PieceParser& PieceParser::operator=(PieceParser&&) noexcept = default;

Program PieceParser::parse(std::string_view text, Program prog) {
    prog.clear();
    prog.name = name_;
    prog.dialect = Dialect::sinumerik;
    if (first_) text = skip_bom(text);
    first_ = false;
    // At most a token per 4 characters on CAM lines ("G1 X95 Y7.5 I0 J2.5": 5 in 20), about a
    // block per 24: the tokens' strings are not all moved again when the vector grows (pages
    // reserved and never written are not memory taken). Pieces: room for a whole piece.
    const std::size_t room = std::max(text.size(), piece_bytes_);
    prog.reserve(room / 24 + 1, 0, room / 4 + 16);
    const auto find = [&](char c, std::size_t from, std::size_t to) {  // `to` when not found
        const void* p = from < to ? std::memchr(text.data() + from, c, to - from) : nullptr;
        return p ? static_cast<std::size_t>(static_cast<const char*>(p) - text.data()) : to;
    };
    std::size_t pos = 0;
    while (pos <= text.size() && !done_) {
        const std::size_t end = find('\r', pos, find('\n', pos, text.size()));  // the first CR or LF
        if (end == text.size() && pos == end && piece_bytes_ > 0) break;  // a piece ends with its line end
        const int line = ++line_;
        std::string_view l = text.substr(pos, end - pos);
        if (l.find('\0') != std::string_view::npos) {
            ParseError e(code::syntax_error, "NUL character in the program text", {line, static_cast<int>(l.find('\0')) + 1});
            if (strict_) throw e;
            prog.syntax_error = e.diagnostic();
            done_ = true;
            break;
        }
        const std::size_t before = prog.size();
        std::string expanded;
        try {
            if (macros_->define(l, line)) {
                if (end >= text.size()) break;
                pos = end + ((text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') ? 2 : 1);
                continue;
            }
            if (!macros_->empty()) l = expanded = macros_->expand(l, line);
            if (!lex_line_fast(l, line, prog)) {  // a plain line (address words) has no control statement
                lex_line(l, line, prog);
                if (prog.size() > before && !prog.control_statements) {
                    const auto t = statements(prog.tokens(prog.blocks().back()));
                    prog.control_statements = !t.empty() && is_control_statement(t[0].key);
                }
            }
        } catch (const ParseError& e) {
            if (prog.size() > before) prog.drop_last_block();
            if (strict_) throw;
            prog.syntax_error = e.diagnostic();
            done_ = true;
            break;
        }
        if (prog.size() > before) prog.last_line = line;
        if (end >= text.size()) break;
        pos = end + ((text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') ? 2 : 1);
    }
    return prog;
}

Program parse(std::string_view text, std::string name, bool strict) {
    return PieceParser(std::move(name), strict).parse(text);
}

}  // namespace toolcomp::sinumerik
