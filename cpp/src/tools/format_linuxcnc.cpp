// LinuxCNC .tbl reader and writer.
#include "toolcomp/tools/format_linuxcnc.hpp"
#include "toolcomp/program/codes.hpp"

#include "number_text.hpp"
#include "text_lines.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

#include <map>
#include <string_view>

namespace toolcomp {

namespace {

using tables::TextLine;

// The words of a table line, in LinuxCNC's own writing order.
constexpr std::string_view kWordOrder = "TPDXYZABCUVWIJQ";

struct TblWord {
    char letter;  // upper case
    int column;   // 1-based
};

struct TblLine {
    TextLine line;
    bool is_tool = false;
    int tool = 0;
    Tool snapshot;                // the tool as read, to tell whether it was changed
    std::vector<TblWord> words;   // in the order of the line
    std::string comment_part;     // from the end of the last word to the end of the line
};

struct TblSource : detail::TableSource {
    TableFormat format() const override { return TableFormat::linuxcnc; }
    std::vector<TblLine> lines;
};

bool has_bom(const std::string& s) { return s.compare(0, 3, "\xEF\xBB\xBF") == 0; }

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

[[noreturn]] void error(const char* code, const std::string& msg, int line, int column) {
    throw ToolTableError(code, msg, SourcePos{line, column});
}

// Parses one line; returns false for blank and comment-only lines.
bool parse_line(TblLine& tl, int line_no, double scale) {
    const std::string& s = tl.line.text;
    const std::size_t semi = s.find(';');
    const std::size_t body_end = semi == std::string::npos ? s.size() : semi;

    Tool t;
    CuttingEdge& e = t.edges.front();
    bool have_tool = false;
    std::size_t last_word_end = 0;
    std::size_t i = has_bom(s) ? 3 : 0;  // a UTF-8 byte order mark is not a word
    while (i < body_end) {
        if (is_blank(s[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < body_end && !is_blank(s[i])) ++i;
        last_word_end = i;
        const std::string_view word(s.data() + start, i - start);
        const int col = static_cast<int>(start) + 1;
        const char letter = ascii_upper(word[0]);
        const std::string_view value = word.substr(1);
        if (kWordOrder.find(letter) == std::string_view::npos)
            error(code::tbl_bad_word, "unknown word '" + std::string(word) + "' in tool table", line_no, col);
        for (const auto& w : tl.words)
            if (w.letter == letter)
                error(code::tbl_duplicate_word, std::string("word ") + letter + " appears twice on one line", line_no, col);
        tl.words.push_back({letter, col});

        if (letter == 'T' || letter == 'P' || letter == 'Q') {
            int n = 0;
            if (!tables::parse_integer(value, n))
                error(code::tbl_bad_number, std::string(1, letter) + " word needs a whole number, got '" + std::string(word) + "'",
                      line_no, col);
            if (letter == 'T') {
                if (n < 0) error(code::tbl_bad_number, "negative tool number '" + std::string(word) + "'", line_no, col);
                t.number = n;
                have_tool = true;
            } else if (letter == 'P') {
                if (n < 0) error(code::tbl_bad_number, "negative pocket number '" + std::string(word) + "'", line_no, col);
                t.pocket = n;
            } else {
                if (n < 0 || n > 9)
                    error(code::tbl_bad_orientation, "tool orientation Q must be 0..9, got '" + std::string(word) + "'",
                          line_no, col);
                e.orientation = n;
            }
            continue;
        }
        double v = 0;
        if (!tables::parse_decimal(value, v))
            error(code::tbl_bad_number, "bad number in word '" + std::string(word) + "'", line_no, col);
        switch (letter) {
            case 'X': e.length.x() = v * scale; break;
            case 'Y': e.length.y() = v * scale; break;
            case 'Z': e.length.z() = v * scale; break;
            case 'A': e.rotary[0] = v; break;
            case 'B': e.rotary[1] = v; break;
            case 'C': e.rotary[2] = v; break;
            case 'U': e.uvw[0] = v * scale; break;
            case 'V': e.uvw[1] = v * scale; break;
            case 'W': e.uvw[2] = v * scale; break;
            case 'D': e.radius = v * scale / 2; break;
            case 'I': e.front_angle = v; break;
            case 'J': e.back_angle = v; break;
            default: break;
        }
    }
    if (tl.words.empty()) return false;  // blank or ';' comment line
    if (!have_tool) error(code::tbl_missing_tool, "tool table line without a T word", line_no, tl.words.front().column);
    if (semi != std::string::npos) t.comment = tables::trim(std::string_view(s).substr(semi + 1));
    tl.comment_part = s.substr(last_word_end);
    tl.is_tool = true;
    tl.tool = t.number;
    tl.snapshot = std::move(t);
    return true;
}

// The value of a word for `t` in LinuxCNC spelling; "" for T/P/Q handled by the caller.
std::string word_text(char letter, const Tool& t, double scale) {
    const CuttingEdge& e = t.edges.front();
    auto len = [&](double v) { return tables::spell_linuxcnc(v, scale); };
    auto ang = [&](double v) { return tables::spell_linuxcnc(v, 1.0); };
    switch (letter) {
        case 'T': return std::to_string(t.number);
        case 'P': return std::to_string(t.pocket);
        case 'Q': return std::to_string(e.orientation);
        case 'D': return len(2 * e.radius);
        case 'X': return len(e.length.x());
        case 'Y': return len(e.length.y());
        case 'Z': return len(e.length.z());
        case 'A': return ang(e.rotary[0]);
        case 'B': return ang(e.rotary[1]);
        case 'C': return ang(e.rotary[2]);
        case 'U': return len(e.uvw[0]);
        case 'V': return len(e.uvw[1]);
        case 'W': return len(e.uvw[2]);
        case 'I': return ang(e.front_angle);
        case 'J': return ang(e.back_angle);
        default: return "";
    }
}

bool word_is_default(char letter, const Tool& t) {
    const CuttingEdge& e = t.edges.front();
    switch (letter) {
        case 'T': case 'P': return false;  // always written
        case 'Q': return e.orientation == 0;
        case 'D': return e.radius == 0;
        case 'X': return e.length.x() == 0;
        case 'Y': return e.length.y() == 0;
        case 'Z': return e.length.z() == 0;
        case 'A': return e.rotary[0] == 0;
        case 'B': return e.rotary[1] == 0;
        case 'C': return e.rotary[2] == 0;
        case 'U': return e.uvw[0] == 0;
        case 'V': return e.uvw[1] == 0;
        case 'W': return e.uvw[2] == 0;
        case 'I': return e.front_angle == 0;
        case 'J': return e.back_angle == 0;
        default: return true;
    }
}

// A .tbl line holds one cutting edge and no wear, corner radius or name: refuse to drop them.
void check_representable(const Tool& t) {
    const std::string who = "tool T" + std::to_string(t.number);
    auto refuse = [&](const std::string& what) {
        throw ToolTableError(code::tbl_unrepresentable,
                             who + ": a LinuxCNC tool table cannot hold " + what + "; use CSV or JSON");
    };
    validate_tool(t);
    if (t.edges.size() != 1) refuse("more than one cutting edge");
    const CuttingEdge& e = t.edges.front();
    if (e.number != 1) refuse("cutting edge D" + std::to_string(e.number) + " (only D1)");
    if (e.corner_radius != 0) refuse("a corner radius");
    if (e.length_wear != Eigen::Vector3d::Zero() || e.radius_wear != 0 || e.corner_radius_wear != 0)
        refuse("wear values");
    if (!t.name.empty()) refuse("a tool name (only a comment)");
    if (t.comment.find_first_of("\r\n") != std::string::npos) refuse("a comment with a line break");
}

std::string canonical_comment(const Tool& t) { return t.comment.empty() ? "" : " ;" + t.comment; }

std::string canonical_line(const Tool& t, double scale) {
    std::string out;
    for (char letter : kWordOrder) {
        if (word_is_default(letter, t)) continue;
        if (!out.empty()) out += ' ';
        out += letter;
        out += word_text(letter, t, scale);
    }
    return out + canonical_comment(t);
}

// A changed tool: its words in the line's own order, then words that became non-zero.
std::string rewritten_line(const TblLine& tl, const Tool& t, double scale) {
    std::string out;
    const std::string bom = has_bom(tl.line.text) ? tl.line.text.substr(0, 3) : "";
    std::string present;
    for (const auto& w : tl.words) {
        if (!out.empty()) out += ' ';
        out += w.letter;
        out += word_text(w.letter, t, scale);
        present += w.letter;
    }
    for (char letter : kWordOrder) {
        if (present.find(letter) != std::string::npos || word_is_default(letter, t)) continue;
        out += ' ';
        out += letter;
        out += word_text(letter, t, scale);
    }
    if (t.comment == tl.snapshot.comment)
        out += tl.comment_part;  // unchanged comment: keep it as written
    else
        out += canonical_comment(t);
    return bom + out;
}

}  // namespace

ToolTable read_linuxcnc_table(std::string_view text, LengthUnit units) {
    auto src = std::make_shared<TblSource>();
    src->units = units;
    const double scale = mm_per_unit(units);
    ToolTable table(units);
    std::map<int, int> first_line;  // tool number -> line
    int line_no = 0;
    for (auto& l : tables::split_lines(text)) {
        ++line_no;
        TblLine tl;
        tl.line = std::move(l);
        if (parse_line(tl, line_no, scale)) {
            auto [it, inserted] = first_line.emplace(tl.tool, line_no);
            if (!inserted) {
                int col = 1;
                for (const auto& w : tl.words)
                    if (w.letter == 'T') col = w.column;
                error(code::tbl_duplicate_tool,
                      "tool T" + std::to_string(tl.tool) + " already defined on line " + std::to_string(it->second),
                      line_no, col);
            }
            table.set(tl.snapshot);
        }
        src->lines.push_back(std::move(tl));
    }
    table.set_source(std::move(src));
    return table;
}

std::string write_linuxcnc_table(const ToolTable& table) {
    const double scale = mm_per_unit(table.units());
    for (const Tool& t : table.tools()) check_representable(t);

    std::string out;
    const auto* src = dynamic_cast<const TblSource*>(table.source());
    std::map<int, bool> written;
    std::string eol = "\n";
    if (src && src->units == table.units()) {
        for (const auto& tl : src->lines)
            if (!tl.line.eol.empty()) {
                eol = tl.line.eol;
                break;
            }
        for (const auto& tl : src->lines) {
            if (!tl.is_tool) {
                out += tl.line.text + tl.line.eol;
                continue;
            }
            const Tool* t = table.find(tl.tool);
            if (!t) continue;  // removed
            written[t->number] = true;
            out += (*t == tl.snapshot ? tl.line.text : rewritten_line(tl, *t, scale)) + tl.line.eol;
        }
    }
    for (const Tool& t : table.tools()) {
        if (written.count(t.number)) continue;
        if (!tables::ends_with_line_end(out)) out += eol;
        out += canonical_line(t, scale) + eol;
    }
    return out;
}

}  // namespace toolcomp
