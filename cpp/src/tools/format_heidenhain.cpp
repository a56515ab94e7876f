// Heidenhain TOOL.T reader and writer (rules in format_heidenhain.hpp).
#include "toolcomp/tools/format_heidenhain.hpp"
#include "toolcomp/program/codes.hpp"

#include "number_text.hpp"
#include "text_lines.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace toolcomp {

namespace {

using tables::TextLine;

constexpr std::size_t kNoLimit = std::numeric_limits<std::size_t>::max();

// ---- characters -------------------------------------------------------------------------
// Columns are counted in characters: a valid UTF-8 sequence is one character, any other
// byte is one character.

std::size_t sequence_length(std::string_view s, std::size_t i) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = 1;
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF)
        n = 3;
    else if (c >= 0xF0 && c <= 0xF4)
        n = 4;
    if (n == 1 || i + n > s.size()) return 1;
    for (std::size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 1;
    return n;
}

// Byte offset of every character, and the byte size at the end.
std::vector<std::size_t> char_starts(std::string_view s) {
    std::vector<std::size_t> out;
    out.reserve(s.size() + 1);
    for (std::size_t i = 0; i < s.size(); i += sequence_length(s, i)) out.push_back(i);
    out.push_back(s.size());
    return out;
}

std::size_t char_count(std::string_view s) { return char_starts(s).size() - 1; }

// A stray '\r' (a line ending "\r\r\n") counts as a blank too.
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

struct Word {
    std::string text;
    std::size_t column = 0;  // 0-based character column
};

// The runs of non-blank characters, starting at character `first`.
std::vector<Word> words_of(std::string_view s, std::size_t first = 0) {
    const auto cs = char_starts(s);
    std::vector<Word> out;
    const std::size_t n = cs.size() - 1;
    std::size_t i = first;
    while (i < n) {
        if (is_blank(s[cs[i]])) {
            ++i;
            continue;
        }
        const std::size_t b = i;
        while (i < n && !is_blank(s[cs[i]])) ++i;
        out.push_back({std::string(s.substr(cs[b], cs[i] - cs[b])), b});
    }
    return out;
}


bool blank_only(std::string_view s) {
    for (char c : s)
        if (!is_blank(c) && c != '\r' && c != '\v' && c != '\f') return false;
    return true;
}

// ---- columns ----------------------------------------------------------------------------

enum class Role { other, t, name, doc, l, r, r2, dl, dr, dr2 };

Role role_of(std::string_view title) {
    const std::string u = to_upper_ascii(title);
    if (u == "T") return Role::t;
    if (u == "NAME") return Role::name;
    if (u == "DOC") return Role::doc;
    if (u == "L") return Role::l;
    if (u == "R") return Role::r;
    if (u == "R2") return Role::r2;
    if (u == "DL") return Role::dl;
    if (u == "DR") return Role::dr;
    if (u == "DR2") return Role::dr2;
    return Role::other;
}

bool is_mapped(Role r) { return r != Role::other; }

constexpr Role kMappedRoles[] = {Role::t, Role::name, Role::l, Role::r, Role::r2, Role::dl, Role::dr, Role::dr2, Role::doc};

const char* title_of(Role r) {
    switch (r) {
        case Role::t: return "T";
        case Role::name: return "NAME";
        case Role::doc: return "DOC";
        case Role::l: return "L";
        case Role::r: return "R";
        case Role::r2: return "R2";
        case Role::dl: return "DL";
        case Role::dr: return "DR";
        case Role::dr2: return "DR2";
        default: return "?";
    }
}

double model_value(const Tool& t, Role r) {
    const CuttingEdge& e = t.edges.front();
    switch (r) {
        case Role::l: return e.length.z();
        case Role::r: return e.radius;
        case Role::r2: return e.corner_radius;
        case Role::dl: return e.length_wear.z();
        case Role::dr: return e.radius_wear;
        case Role::dr2: return e.corner_radius_wear;
        default: return 0;
    }
}

void set_model_value(Tool& t, Role r, double v) {
    CuttingEdge& e = t.edges.front();
    switch (r) {
        case Role::l: e.length.z() = v; break;
        case Role::r: e.radius = v; break;
        case Role::r2: e.corner_radius = v; break;
        case Role::dl: e.length_wear.z() = v; break;
        case Role::dr: e.radius_wear = v; break;
        case Role::dr2: e.corner_radius_wear = v; break;
        default: break;
    }
}

// TNC spelling: a sign always, fixed point, the fewest decimals that read back exactly.
std::string spell_number(double model, double scale) {
    if (!std::isfinite(model)) throw ToolTableError(code::table_bad_value, "a tool value is not a finite number");
    if (model == 0) return "+0";
    auto fixed = [](double x) {
        char buf[1100];
        const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed);
        return std::string(buf, r.ptr);
    };
    auto reads_back = [&](const std::string& s) {
        double d = 0;
        return tables::parse_decimal(s, d) && d * scale == model;
    };
    const double v = model / scale;
    std::string s = fixed(v);
    if (!reads_back(s)) {
        // Dividing by the unit may have lost the last bit: a neighbour may read back.
        double up = v, down = v;
        for (int i = 0; i < 4; ++i) {
            up = std::nextafter(up, std::numeric_limits<double>::infinity());
            down = std::nextafter(down, -std::numeric_limits<double>::infinity());
            if (reads_back(fixed(up))) {
                s = fixed(up);
                break;
            }
            if (reads_back(fixed(down))) {
                s = fixed(down);
                break;
            }
        }
    }
    return s[0] == '-' ? s : "+" + s;
}

bool is_default(const Tool& t, Role r) {
    switch (r) {
        case Role::name: return t.name.empty();
        case Role::doc: return t.comment.empty();
        case Role::t: return false;
        case Role::other: return true;
        default: return model_value(t, r) == 0;
    }
}

bool field_changed(const Tool& now, const Tool& was, Role r) {
    switch (r) {
        case Role::name: return now.name != was.name;
        case Role::doc: return now.comment != was.comment;
        case Role::t: case Role::other: return false;
        default: return model_value(now, r) != model_value(was, r);
    }
}

// The text of a mapped field, unpadded.
std::string field_text(const Tool& t, Role r, double scale) {
    switch (r) {
        case Role::t: return std::to_string(t.number);
        case Role::name: return t.name;
        case Role::doc: return t.comment;
        case Role::other: return "";
        default: return spell_number(model_value(t, r), scale);
    }
}

[[noreturn]] void refuse(const Tool& t, const std::string& what) {
    throw ToolTableError(code::heidenhain_unrepresentable,
                         "tool T" + std::to_string(t.number) + ": a Heidenhain TOOL.T cannot hold " + what +
                             "; use CSV or JSON");
}

void check_representable(const Tool& t) {
    validate_tool(t);
    if (t.edges.size() != 1) refuse(t, "more than one cutting edge");
    const CuttingEdge& e = t.edges.front();
    if (e.number != 1) refuse(t, "cutting edge D" + std::to_string(e.number) + " (only D1)");
    if (e.length.x() != 0 || e.length.y() != 0) refuse(t, "an X or Y length offset (only L along the tool axis)");
    if (e.length_wear.x() != 0 || e.length_wear.y() != 0) refuse(t, "an X or Y length wear (only DL)");
    if (e.rotary != std::array<double, 3>{0, 0, 0}) refuse(t, "A B C offsets");
    if (e.uvw != std::array<double, 3>{0, 0, 0}) refuse(t, "U V W offsets");
    if (e.orientation != 0) refuse(t, "a lathe orientation");
    if (e.front_angle != 0 || e.back_angle != 0) refuse(t, "front or back angles");
    auto breaks = [](const std::string& s) { return s.find_first_of("\r\n") != std::string::npos; };
    if (breaks(t.name)) refuse(t, "a name with a line break");
    if (breaks(t.comment)) refuse(t, "a DOC comment with a line break");
}

// ---- what the reader keeps ---------------------------------------------------------------

struct Column {
    std::string title;
    Role role = Role::other;
    std::size_t start = 0;  // 0-based character column of the field (0 for the first)
};

struct Row {
    int tool = 0;
    Tool snapshot;
    std::vector<std::string> fields;  // raw text of every column's field (may be shorter / empty)
    std::size_t length = 0;           // characters
    bool trailing_blank = false;      // the line ends with a blank
};

struct HhSource : detail::TableSource {
    TableFormat format() const override { return TableFormat::heidenhain; }
    std::vector<TextLine> lines;
    std::vector<Column> columns;
    std::size_t header_length = 0;  // characters
    bool header_padded = false;     // the header line ends with a blank
    std::vector<int> row_of_line;   // index into rows, or -1
    std::vector<Row> rows;
    std::size_t end_line = 0;       // index of the [END] line
    std::string eol = "\n";

    bool has(Role r) const {
        for (const auto& c : columns)
            if (c.role == r) return true;
        return false;
    }
    // Field width in characters; kNoLimit for the last column.
    std::size_t width(std::size_t k) const {
        return k + 1 < columns.size() ? columns[k + 1].start - columns[k].start : kNoLimit;
    }
};

[[noreturn]] void error(const char* code, const std::string& msg, std::size_t line, std::size_t column) {
    throw ToolTableError(code, msg, SourcePos{static_cast<int>(line), static_cast<int>(column)});
}

// ---- writing fields -----------------------------------------------------------------------

[[noreturn]] void too_wide(const Tool& t, const std::string& title, const std::string& value, std::size_t limit) {
    throw ToolTableError(code::heidenhain_value_too_wide,
                         "tool T" + std::to_string(t.number) + ": " + title + " value '" + value +
                             "' does not fit its column (at most " + std::to_string(limit) + " characters)");
}

std::string spaces(std::size_t n) { return std::string(n, ' '); }

// A changed value in place of `old` (the field's old raw text), keeping the old alignment.
std::string place_value(const Tool& t, const Column& col, const std::string& value, const std::string& old,
                        std::size_t width) {
    const std::size_t vlen = char_count(value);
    const auto cs = char_starts(old);
    const std::size_t old_len = cs.size() - 1;
    std::size_t lead = 0, trail = 0;
    while (lead < old_len && is_blank(old[cs[lead]])) ++lead;
    while (trail < old_len - lead && is_blank(old[cs[old_len - 1 - trail]])) ++trail;
    const std::size_t old_value_len = old_len - lead - trail;

    long start = 0;
    if (old_value_len > 0) {
        if (lead > trail)  // right-aligned: keep where the old value ended
            start = static_cast<long>(lead + old_value_len) - static_cast<long>(vlen);
        else
            start = static_cast<long>(lead);
    }
    if (width != kNoLimit) {
        const std::size_t limit = width - 1;  // one blank before the next column
        if (vlen > limit) too_wide(t, col.title, value, limit);
        if (start + static_cast<long>(vlen) > static_cast<long>(limit)) start = static_cast<long>(limit - vlen);
    }
    if (start < 0) start = 0;
    std::string out = spaces(static_cast<std::size_t>(start)) + value;
    const std::size_t len = static_cast<std::size_t>(start) + vlen;
    const std::size_t target = width != kNoLimit ? width : old_len;
    if (len < target) out += spaces(target - len);
    return out;
}

std::string rstrip(std::string s, std::size_t keep_bytes = 0) {
    while (s.size() > keep_bytes && is_blank(s.back())) s.pop_back();
    return s;
}

// Appends `piece` so that it starts at character column `start` of `out`.
void put_at(std::string& out, std::size_t& out_chars, std::size_t start, const std::string& piece) {
    if (piece.empty()) return;
    if (out_chars < start) {
        out += spaces(start - out_chars);
        out_chars = start;
    }
    out += piece;
    out_chars += char_count(piece);
}

// The row of a changed tool: the old fields, with the mapped fields whose value changed
// rewritten in place.
std::string rewritten_row(const HhSource& src, const Row& row, const Tool& t, double scale) {
    std::string out;
    std::size_t out_chars = 0;
    for (std::size_t k = 0; k < src.columns.size(); ++k) {
        const Column& col = src.columns[k];
        const std::string& old = row.fields[k];
        if (field_changed(t, row.snapshot, col.role))
            put_at(out, out_chars, col.start, place_value(t, col, field_text(t, col.role, scale), old, src.width(k)));
        else
            put_at(out, out_chars, col.start, old);
    }
    if (!row.trailing_blank) return rstrip(out);
    // Keep the old line's own trailing blanks, but no padding past its old length.
    if (out_chars <= row.length) return out;
    const auto cs = char_starts(out);
    return rstrip(out, cs[row.length]);
}

// The row of a tool that is not in the file: mapped columns filled, the others empty.
std::string new_row(const HhSource& src, const Tool& t, double scale) {
    std::string out;
    std::size_t out_chars = 0;
    for (std::size_t k = 0; k < src.columns.size(); ++k) {
        const Column& col = src.columns[k];
        if (!is_mapped(col.role)) continue;
        const std::string value = field_text(t, col.role, scale);
        const std::size_t w = src.width(k);
        if (w != kNoLimit && char_count(value) > w - 1) too_wide(t, col.title, value, w - 1);
        put_at(out, out_chars, col.start, value);
    }
    if (src.header_padded && out_chars < src.header_length) out += spaces(src.header_length - out_chars);
    return out;
}

// ---- the canonical layout ------------------------------------------------------------------

struct CanonColumn {
    const char* title;
    Role role;
    std::size_t width;  // TNC 426 width, widened to fit the values
};

std::string write_canonical(const ToolTable& table) {
    const double scale = mm_per_unit(table.units());
    std::vector<CanonColumn> cols = {
        {"T", Role::t, 5},         {"NAME", Role::name, 17},  {"L", Role::l, 12},      {"R", Role::r, 12},
        {"R2", Role::r2, 12},      {"DL", Role::dl, 8},       {"DR", Role::dr, 8},     {"DR2", Role::dr2, 8},
        {"LCUTS", Role::other, 8}, {"ANGLE", Role::other, 8}, {"TL", Role::other, 3},  {"RT", Role::other, 4},
        {"TIME1", Role::other, 6}, {"TIME2", Role::other, 6}, {"CUR.TIME", Role::other, 9},
        {"DOC", Role::doc, 17},    {"PLC", Role::other, 9}};
    std::vector<std::vector<std::string>> rows;
    for (const Tool& t : table.tools()) {
        std::vector<std::string> r;
        for (auto& c : cols) {
            r.push_back(field_text(t, c.role, scale));
            c.width = std::max(c.width, char_count(r.back()) + 1);
        }
        rows.push_back(std::move(r));
    }
    const std::string eol = "\r\n";
    auto line = [&](const std::vector<std::string>& cells) {
        std::string out;
        for (std::size_t k = 0; k < cols.size(); ++k) out += cells[k] + spaces(cols[k].width - char_count(cells[k]));
        return out + eol;
    };
    std::string out = std::string("BEGIN TOOL .T ") + (table.units() == LengthUnit::inch ? "INCH" : "MM") + eol;
    std::vector<std::string> titles;
    for (const auto& c : cols) titles.emplace_back(c.title);
    out += line(titles);
    for (const auto& r : rows) out += line(r);
    return out + "[END]" + eol;
}

}  // namespace

// ---- reading -------------------------------------------------------------------------------

ToolTable read_heidenhain_table(std::string_view text, LengthUnit units) {
    auto src = std::make_shared<HhSource>();
    src->lines = tables::split_lines(text);
    const auto& lines = src->lines;
    for (const auto& l : lines)
        if (!l.eol.empty()) {
            src->eol = l.eol;
            break;
        }

    // Line 1: BEGIN <name>.T [MM|INCH]
    {
        const std::string first = lines.empty() ? std::string() : lines[0].text;
        const bool bom = first.compare(0, 3, "\xEF\xBB\xBF") == 0;
        const auto w = words_of(first, bom ? 1 : 0);
        if (w.empty() || to_upper_ascii(w[0].text) != "BEGIN")
            error(code::heidenhain_missing_begin, "a TOOL.T file starts with a line like 'BEGIN TOOL .T MM'", 1,
                  w.empty() ? 1 : w[0].column + 1);
        std::size_t name_end = w.size();
        if (w.size() >= 3) {
            const std::string u = to_upper_ascii(w.back().text);
            if (u == "MM" || u == "INCH") {
                units = u == "MM" ? LengthUnit::mm : LengthUnit::inch;
                name_end = w.size() - 1;
            }
        }
        std::string name;
        for (std::size_t i = 1; i < name_end; ++i) name += w[i].text;
        const std::string un = to_upper_ascii(name);
        if (un.size() < 2 || un.compare(un.size() - 2, 2, ".T") != 0)
            error(code::heidenhain_not_tool_table,
                  "'" + first.substr(bom ? 3 : 0) + "' is not the BEGIN line of a tool table (TOOL .T)", 1,
                  w.size() > 1 ? w[1].column + 1 : w[0].column + w[0].text.size() + 1);
    }
    src->units = units;
    const double scale = mm_per_unit(units);

    // Line 2: the column titles.
    if (lines.size() < 2)
        error(code::heidenhain_missing_header, "the BEGIN line must be followed by the line of column titles", 2, 1);
    {
        const std::string& h = lines[1].text;
        std::set<std::string> seen;
        bool have_t = false;
        for (const Word& w : words_of(h)) {
            const std::string u = to_upper_ascii(w.text);
            if (u == "[END]") break;
            // Column titles start with a letter; a number means line 2 is already a tool row.
            if (ascii_digit(u[0]) || u[0] == '+' || u[0] == '-' || u[0] == '.')
                error(code::heidenhain_missing_header,
                      "line 2 must be the column titles of the tool table (T NAME L R ...), not a tool row", 2,
                      w.column + 1);
            if (!seen.insert(u).second)
                error(code::heidenhain_duplicate_column, "column '" + w.text + "' appears twice in the header", 2,
                      w.column + 1);
            Column c{w.text, role_of(w.text), src->columns.empty() ? 0 : w.column};
            have_t = have_t || c.role == Role::t;
            src->columns.push_back(std::move(c));
        }
        if (!have_t)
            error(code::heidenhain_missing_header,
                  "line 2 must be the column titles of the tool table, with a T column", 2, 1);
        src->header_length = char_count(h);
        src->header_padded = !h.empty() && is_blank(h.back());
    }

    ToolTable table(units);
    std::map<int, std::size_t> first_line;  // tool -> line number
    src->row_of_line.assign(lines.size(), -1);
    bool ended = false;
    for (std::size_t li = 2; li < lines.size(); ++li) {
        const std::string& s = lines[li].text;
        const std::size_t line_no = li + 1;
        if (blank_only(s)) continue;
        const auto w = words_of(s);
        if (ended)
            error(code::heidenhain_text_after_end, "text after the [END] line", line_no, w.front().column + 1);
        if (to_upper_ascii(tables::trim(s)) == "[END]") {
            ended = true;
            src->end_line = li;
            continue;
        }
        const auto cs = char_starts(s);
        const std::size_t n = cs.size() - 1;
        Row row;
        row.length = n;
        row.trailing_blank = is_blank(s.back());
        Tool t;
        bool have_t = false;
        std::size_t t_column = w.front().column + 1;
        for (std::size_t k = 0; k < src->columns.size(); ++k) {
            const Column& col = src->columns[k];
            const std::size_t b = std::min(col.start, n);
            const std::size_t e = std::min(k + 1 < src->columns.size() ? src->columns[k + 1].start : n, n);
            row.fields.emplace_back(s.substr(cs[b], cs[e] - cs[b]));
            const std::string& raw = row.fields.back();
            const std::string value = tables::trim(raw);
            std::size_t vcol = b;  // 0-based column of the value
            while (vcol < e && is_blank(s[cs[vcol]])) ++vcol;
            if (vcol == e) vcol = b;
            const std::size_t at = vcol + 1;
            switch (col.role) {
                case Role::other: break;
                case Role::name: t.name = value; break;
                case Role::doc: t.comment = value; break;
                case Role::t: {
                    if (value.empty()) break;
                    t_column = at;
                    int num = 0;
                    if (!tables::parse_integer(value, num) || num < 0) {
                        const auto dot = value.find('.');
                        int whole = 0, index = 0;
                        if (dot != std::string::npos && tables::parse_integer(value.substr(0, dot), whole) &&
                            whole >= 0 && tables::parse_integer(value.substr(dot + 1), index) && index >= 0 &&
                            value[dot + 1] != '+' && value[dot + 1] != '-')
                            error(code::heidenhain_tool_index_unsupported,
                                  "indexed tool '" + value + "' (T number.index) is not supported", line_no, at);
                        error(code::heidenhain_bad_number, "T needs a whole tool number >= 0, got '" + value + "'",
                              line_no, at);
                    }
                    t.number = num;
                    have_t = true;
                    break;
                }
                default: {
                    if (value.empty()) break;
                    double v = 0;
                    if (!tables::parse_decimal(value, v))
                        error(code::heidenhain_bad_number, "bad number '" + value + "' in column " + col.title, line_no, at);
                    set_model_value(t, col.role, v * scale);
                    break;
                }
            }
        }
        if (!have_t) error(code::heidenhain_missing_tool, "tool table row without a T number", line_no, t_column);
        const auto [it, fresh] = first_line.emplace(t.number, line_no);
        if (!fresh)
            error(code::heidenhain_duplicate_tool,
                  "tool T" + std::to_string(t.number) + " already defined on line " + std::to_string(it->second),
                  line_no, t_column);
        row.tool = t.number;
        row.snapshot = t;
        table.set(std::move(t));
        src->row_of_line[li] = static_cast<int>(src->rows.size());
        src->rows.push_back(std::move(row));
    }
    if (!ended)
        error(code::heidenhain_missing_end, "the tool table does not end with an [END] line (truncated file?)",
              lines.size() + 1, 1);
    table.set_source(std::move(src));
    return table;
}

std::optional<std::string> heidenhain_field(const ToolTable& table, int number, std::string_view title) {
    const auto* src = dynamic_cast<const HhSource*>(table.source());
    if (!src) return std::nullopt;
    const std::string want = to_upper_ascii(title);
    std::size_t k = 0;
    while (k < src->columns.size() && to_upper_ascii(src->columns[k].title) != want) ++k;
    if (k == src->columns.size()) return std::nullopt;
    for (const Row& r : src->rows) {
        if (r.tool != number) continue;
        if (k >= r.fields.size()) return std::string();
        std::string_view f = r.fields[k];
        while (!f.empty() && is_blank(f.front())) f.remove_prefix(1);
        while (!f.empty() && is_blank(f.back())) f.remove_suffix(1);
        return std::string(f);
    }
    return std::nullopt;
}

// ---- writing -------------------------------------------------------------------------------

std::string write_heidenhain_table(const ToolTable& table) {
    const auto* src = dynamic_cast<const HhSource*>(table.source());
    if (!src || src->units != table.units()) {
        for (const Tool& t : table.tools()) check_representable(t);
        return write_canonical(table);
    }
    const double scale = mm_per_unit(table.units());

    // Which tools the file has; the changed and new ones must fit TOOL.T and its columns
    // (an unchanged row is written as it was, whatever it holds).
    std::map<int, const Row*> in_file;
    for (const Row& r : src->rows) in_file.emplace(r.tool, &r);
    for (const Tool& t : table.tools()) {
        auto it = in_file.find(t.number);
        if (it != in_file.end() && t == it->second->snapshot) continue;
        check_representable(t);
        for (Role r : kMappedRoles)
            if (!src->has(r) && !is_default(t, r))
                refuse(t, std::string("a ") + title_of(r) + " value: the file has no " + title_of(r) + " column");
    }

    std::string out;
    for (std::size_t li = 0; li < src->lines.size(); ++li) {
        const TextLine& l = src->lines[li];
        if (li == src->end_line) {
            for (const Tool& t : table.tools())
                if (!in_file.count(t.number)) out += new_row(*src, t, scale) + src->eol;
        }
        const int r = src->row_of_line[li];
        if (r < 0) {
            out += l.text + l.eol;
            continue;
        }
        const Row& row = src->rows[static_cast<std::size_t>(r)];
        const Tool* t = table.find(row.tool);
        if (!t) continue;  // removed
        out += (*t == row.snapshot ? l.text : rewritten_row(*src, row, *t, scale)) + l.eol;
    }
    return out;
}

}  // namespace toolcomp
