#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/decimal.hpp"
#include "toolcomp/program/text.hpp"
#include "line_lexer.hpp"
#include "words.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>
#include <optional>
#include <tuple>
#include <utility>

namespace toolcomp::heidenhain {

namespace {

// A line ending in '~' (after its comment, as the TNC writes cycle definitions, or inside a
// long comment it wraps) goes on in the next: the line without it, whether it continues, and
// whether it ended inside a comment.
struct Continuation {
    std::string_view line;
    bool goes_on = false, in_comment = false;
};
Continuation continuation(std::string_view line) {
    std::size_t e = line.size();
    while (e > 0 && blank(line[e - 1])) --e;
    if (e == 0 || line[e - 1] != '~') return {line};
    std::size_t first = 0;  // a structure block (after its number) is all comment
    while (first < e && (blank(line[first]) || ascii_digit(line[first]))) ++first;
    return {line.substr(0, e - 1), true, line.find(';') < e - 1 || line[first] == '*'};
}

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

// Where the lines of a piece's blocks that end in it end: a block continued with '~' past
// the piece's last line is held back from the start of its first line (text.size(): none).
// Lines end at LF or CR (a CR before LF makes an empty line here, blank as the CR is to the
// lexer).
std::size_t complete_blocks(std::string_view text) {
    std::size_t from = text.size(), end = text.size();
    while (true) {
        std::size_t start = end;
        while (start > 0 && text[start - 1] != '\n' && text[start - 1] != '\r') --start;
        const std::string_view line = text.substr(start, end - start);
        if (!is_blank_line(line)) {
            if (!continuation(line).goes_on) break;  // a block ends here
            from = start;
        }
        if (start == 0) break;
        end = start - 1;
    }
    return from;
}

}  // namespace

PieceParser::PieceParser(std::string name, bool strict, std::size_t piece_bytes)
    : name_(std::move(name)), strict_(strict), piece_bytes_(piece_bytes) {}

void PieceParser::start_piece(Program& prog) const {
    prog.clear();
    prog.name = name_;
    prog.dialect = Dialect::heidenhain;
    prog.inch = inch_;
    prog.blank = blank_;
    prog.last_line = last_line_;
}

// The lines of `text` (whole blocks, starting with a block), after those read before.
void PieceParser::lex(std::string_view text, Program& prog) {
    std::size_t pos = 0;
    Continuation before;  // the line before: did it end with '~'
    const auto find = [&](char c, std::size_t from, std::size_t to) {  // `to` when not found
        const void* p = from < to ? std::memchr(text.data() + from, c, to - from) : nullptr;
        return p ? static_cast<std::size_t>(static_cast<const char*>(p) - text.data()) : to;
    };
    while (pos <= text.size()) {
        if (pos == text.size() && piece_bytes_ > 0) break;  // a piece ends with its line end
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
        const int line_no = ++line_;
        pos = nl + 1;
        if (!is_blank_line(line)) {
            const bool goes_on = before.goes_on;
            const Continuation now = continuation(line);
            line = now.line;
            try {
                if (goes_on || !lex_line_fast(line, line_no, prog)) lex_line(line, line_no, prog, goes_on, before.in_comment);
                before = now;
                check_path_words(prog.tokens(prog.blocks().back()), line_no);
            } catch (const ParseError& e) {
                if (strict_) throw;
                if (prog.size() && (goes_on || prog.blocks().back().line == line_no)) prog.drop_last_block();  // if begun
                prog.syntax_error = e.diagnostic();
                failed_ = done_ = true;
                break;
            }
            const Block& b = prog.blocks().back();
            prog.last_line = line_no;
            auto t = prog.tokens(b);
            if (t.size() >= 2 && t[0].is("BEGIN") && t[1].is("PGM"))
                for (const Token& k : t) prog.inch = prog.inch || k.is("INCH");
            read_blank(prog, b);
            if (t.size() >= 2 && t[0].is("END") && t[1].is("PGM")) {
                ended_ = done_ = true;
                break;
            }
        }
        if (nl == text.size()) break;
    }
}

// After a piece's lines: what goes on to the next piece, the frame's first blocks; at END
// PGM the frame's check.
void PieceParser::finish_piece(Program& prog) {
    inch_ = prog.inch;
    blank_ = prog.blank;
    last_line_ = prog.last_line;
    for (std::size_t i = 0; i < prog.size() && !found_; ++i) {
        const Block& b = prog.blocks()[i];
        if (!any_block_) any_block_ = true, first_line_ = b.line;
        if (b.token_count == 0) continue;  // comments before BEGIN PGM are tolerated
        auto t = prog.tokens(b);
        found_ = true;
        begins_ = t.size() >= 2 && t[0].is("BEGIN") && t[1].is("PGM");
        found_line_ = b.line;
        found_column_ = t[0].column;
    }
    if (ended_ && !failed_) check_frame(prog);
}

// A program starts with BEGIN PGM and ends with END PGM: without them, a file cut short in
// a transfer would run as if it were complete.
void PieceParser::check_frame(Program& prog) {
    std::optional<ParseError> e;
    if (!found_)
        e.emplace(code::begin_pgm_missing, "The program does not start with BEGIN PGM (no blocks)",
                  SourcePos{any_block_ ? first_line_ : 1, 1});
    else if (!begins_)
        e.emplace(code::begin_pgm_missing, "The program does not start with BEGIN PGM", SourcePos{found_line_, found_column_});
    else if (!ended_)
        e.emplace(code::end_pgm_missing, "END PGM missing: the program ends without END PGM (cut short?)",
                  SourcePos{last_line_, 1});
    if (!e) return;
    if (strict_) throw *e;
    prog.syntax_error = e->diagnostic();
}

Program PieceParser::parse(std::string_view text, Program prog) {
    start_piece(prog);
    if (first_) text = skip_bom(text);
    first_ = false;
    std::string joined;  // a block held back, and this piece
    if (!held_.empty()) {
        joined = std::move(held_);
        held_.clear();
        joined.append(text);
        text = joined;
    }
    // About 27 bytes and 4 tokens a line in CAM output ("12 L X+100 Y+2.5 F600"): the
    // tokens' vector is not moved as it grows (two strings each). Pieces: room for a whole
    // piece.
    const std::size_t room = std::max(text.size(), piece_bytes_);
    prog.reserve(room / 24 + 1, 0, room / 7 + 1);
    const std::size_t whole = piece_bytes_ > 0 ? complete_blocks(text) : text.size();
    if (!done_) lex(text.substr(0, whole), prog);
    if (!done_ && whole < text.size()) held_ = std::string(text.substr(whole));
    finish_piece(prog);
    if (piece_bytes_ == 0 && !done_) {  // the text read whole ends here
        check_frame(prog);
        done_ = true;
    }
    return prog;
}

Program PieceParser::end(Program prog) {
    start_piece(prog);
    if (!done_) {
        first_ = false;
        if (!held_.empty()) {
            const std::string text = std::move(held_);
            held_.clear();
            lex(text, prog);
        }
        finish_piece(prog);
        if (!done_) check_frame(prog);
    }
    done_ = true;
    return prog;
}

Program parse(std::string_view text, std::string name, bool strict) {
    return PieceParser(std::move(name), strict).parse(text);
}

}  // namespace toolcomp::heidenhain
