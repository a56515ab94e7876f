// CSV tool-table reader and writer.
#include "toolcomp/tools/format_csv.hpp"
#include "toolcomp/program/codes.hpp"

#include "fields.hpp"
#include "number_text.hpp"
#include "text_lines.hpp"
#include "toolcomp/program/diagnostic.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace toolcomp {

namespace {

using tables::Field;
using tables::FieldInfo;
using tables::FieldKind;

struct Cell {
    std::string value;       // unquoted; trimmed when it was not quoted
    std::size_t begin = 0;   // raw extent in the text, quotes and spaces included
    std::size_t end = 0;
    bool quoted = false;
};

enum class RecordKind { blank, comment, header, row };

struct Record {
    std::size_t begin = 0, end = 0;  // raw extent without the line ending
    std::string eol;
    RecordKind kind = RecordKind::row;
    std::vector<Cell> cells;
};

// What the writer needs of a record read from the file.
struct KeptRecord {
    std::string text;  // without the line ending
    std::string eol;
    RecordKind kind;
    int tool = 0;
    int edge = 1;
    std::vector<std::string> raw_cells;
};

struct CsvSource : detail::TableSource {
    TableFormat format() const override { return TableFormat::csv; }
    bool has_header = false;
    std::vector<const FieldInfo*> columns;  // nullptr: a column this library does not know
    std::vector<KeptRecord> records;
    std::map<int, Tool> snapshots;
    std::map<int, std::vector<int>> file_edges;  // tool -> edge numbers with a row
    std::map<int, std::size_t> last_row;        // tool -> index of its last record
    std::string eol = "\n";
};

// 1-based line and column of a byte offset.
class Positions {
public:
    explicit Positions(std::string_view text) {
        starts_.push_back(0);
        for (std::size_t i = 0; i < text.size();) {
            const std::size_t n = tables::line_end_length(text, i);
            i += n ? n : 1;
            if (n) starts_.push_back(i);
        }
    }
    SourcePos at(std::size_t offset) const {
        auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
        const std::size_t line = static_cast<std::size_t>(it - starts_.begin());
        return {static_cast<int>(line), static_cast<int>(offset - starts_[line - 1]) + 1};
    }

private:
    std::vector<std::size_t> starts_;
};

bool is_space(char c) { return c == ' ' || c == '\t'; }

std::vector<Record> split_records(std::string_view text, const Positions& pos) {
    std::vector<Record> out;
    const std::size_t n = text.size();
    // A UTF-8 byte order mark (spreadsheet exports) stays in the first record's raw text.
    std::size_t p = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    while (p < n) {
        Record rec;
        rec.begin = out.empty() ? 0 : p;
        std::size_t q = p;
        while (q < n && is_space(text[q])) ++q;
        if (q < n && text[q] == '#') {  // comment line, taken as it is
            const std::size_t end = std::min(text.find_first_of("\r\n", p), n);
            rec.end = end;
            rec.eol = std::string(text.substr(end, tables::line_end_length(text, end)));
            rec.kind = RecordKind::comment;
            p = end + rec.eol.size();
            out.push_back(std::move(rec));
            continue;
        }
        bool end_of_record = false;
        while (!end_of_record) {
            Cell cell;
            cell.begin = p;
            q = p;
            while (q < n && is_space(text[q])) ++q;
            std::size_t after = 0;  // position of the separator / line end after the cell
            if (q < n && text[q] == '"') {
                cell.quoted = true;
                std::size_t r = q + 1;
                for (;;) {
                    const std::size_t quote = text.find('"', r);
                    if (quote == std::string_view::npos)
                        throw ToolTableError(code::csv_bad_quote, "quoted field is never closed", pos.at(q));
                    cell.value.append(text.substr(r, quote - r));
                    if (quote + 1 < n && text[quote + 1] == '"') {
                        cell.value += '"';
                        r = quote + 2;
                        continue;
                    }
                    r = quote + 1;
                    break;
                }
                while (r < n && is_space(text[r])) ++r;
                if (r < n && text[r] != ',' && !tables::line_end_length(text, r))
                    throw ToolTableError(code::csv_bad_quote, "text after the closing quote of a field", pos.at(r));
                after = r;
                cell.end = r;
            } else {
                std::size_t r = p;
                while (r < n && text[r] != ',' && !tables::line_end_length(text, r)) ++r;
                after = r;
                cell.end = r;
                const std::string_view raw = text.substr(p, r - p);
                const std::size_t quote = raw.find('"');
                if (quote != std::string_view::npos)
                    throw ToolTableError(code::csv_bad_quote, "quote inside an unquoted field", pos.at(p + quote));
                cell.value = tables::trim(raw);
            }
            rec.cells.push_back(std::move(cell));
            if (after < n && text[after] == ',') {
                p = after + 1;
                if (p == n) {  // a trailing comma at the very end: one more empty cell
                    Cell last;
                    last.begin = last.end = n;
                    rec.cells.push_back(last);
                    rec.end = n;
                    end_of_record = true;
                }
                continue;
            }
            // end of record
            rec.end = rec.cells.back().end;
            if (after < n) {  // a line ending starts at text[after]
                rec.eol = std::string(text.substr(after, tables::line_end_length(text, after)));
                p = after + rec.eol.size();
            } else {
                p = n;
            }
            end_of_record = true;
        }
        if (rec.cells.size() == 1 && !rec.cells[0].quoted && rec.cells[0].value.empty()) rec.kind = RecordKind::blank;
        out.push_back(std::move(rec));
    }
    return out;
}

std::string quote_if_needed(const std::string& s) {
    const bool needs = s.find_first_of(",\"\r\n") != std::string::npos ||
                       (!s.empty() && (is_space(s.front()) || is_space(s.back()) || s.front() == '#'));
    if (!needs) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

bool is_default(const Tool& t, const CuttingEdge& e, const FieldInfo& f) {
    switch (f.id) {
        case Field::tool: return false;
        case Field::pocket: return t.pocket == 0;
        case Field::name: return t.name.empty();
        case Field::comment: return t.comment.empty();
        case Field::edge: return e.number == 1;
        default: return tables::get_edge_number(e, f.id) == 0;
    }
}

std::string cell_text(const Tool& t, const CuttingEdge& e, const FieldInfo& f, double scale) {
    switch (f.id) {
        case Field::tool: return std::to_string(t.number);
        case Field::pocket: return std::to_string(t.pocket);
        case Field::name: return quote_if_needed(t.name);
        case Field::comment: return quote_if_needed(t.comment);
        case Field::edge: return std::to_string(e.number);
        case Field::orientation: return std::to_string(e.orientation);
        default:
            return tables::spell_shortest(tables::get_edge_number(e, f.id),
                                          f.kind == FieldKind::length ? scale : 1.0);
    }
}

// One row of a changed or new tool: known columns from the model, unknown columns as they
// were; an empty cell stays empty while its value is the default.
std::string row_text(const std::vector<const FieldInfo*>& columns, const Tool& t, const CuttingEdge& e,
                     const std::vector<std::string>* raw, double scale) {
    std::string out;
    for (std::size_t i = 0; i < columns.size(); ++i) {
        if (i) out += ',';
        const std::string* old = raw && i < raw->size() ? &(*raw)[i] : nullptr;
        const FieldInfo* f = columns[i];
        if (!f) {
            if (old) out += *old;
            continue;
        }
        if ((!old || tables::trim(*old).empty()) && is_default(t, e, *f)) continue;
        out += cell_text(t, e, *f, scale);
    }
    return out;
}

const std::vector<Field>& canonical_columns() {
    static const std::vector<Field> cols = [] {
        std::vector<Field> c{Field::tool, Field::edge, Field::pocket, Field::name};
        for (Field f : tables::canonical_edge_fields()) c.push_back(f);
        c.push_back(Field::comment);
        return c;
    }();
    return cols;
}

}  // namespace

ToolTable read_csv_table(std::string_view text, LengthUnit units) {
    const Positions pos(text);
    const double scale = mm_per_unit(units);
    auto src = std::make_shared<CsvSource>();
    src->units = units;

    std::vector<Tool> tools;
    std::map<int, std::size_t> index;                  // tool -> position in tools
    std::map<std::pair<int, int>, int> first_line;     // (tool, edge) -> line
    std::size_t tool_column = 0;
    bool eol_known = false;

    for (Record& rec : split_records(text, pos)) {
        KeptRecord kept;
        kept.text = std::string(text.substr(rec.begin, rec.end - rec.begin));
        kept.eol = rec.eol;
        kept.kind = rec.kind;
        if (!rec.eol.empty() && !eol_known) {
            src->eol = rec.eol;
            eol_known = true;
        }
        if (rec.kind == RecordKind::row && !src->has_header) {
            // The header row.
            rec.kind = kept.kind = RecordKind::header;
            src->has_header = true;
            std::set<int> slots;
            bool have_tool = false;
            for (std::size_t i = 0; i < rec.cells.size(); ++i) {
                const FieldInfo* f = tables::find_field(tables::to_lower(rec.cells[i].value));
                if (f) {
                    if (!slots.insert(f->slot).second)
                        throw ToolTableError(code::csv_duplicate_column,
                                             "column '" + rec.cells[i].value + "' given twice", pos.at(rec.cells[i].begin));
                    if (f->id == Field::tool) {
                        have_tool = true;
                        tool_column = i;
                    }
                }
                src->columns.push_back(f);
            }
            if (!have_tool)
                throw ToolTableError(code::csv_missing_tool_column, "the CSV header has no 'tool' column", pos.at(rec.begin));
        } else if (rec.kind == RecordKind::row) {
            Tool row;
            CuttingEdge& e = row.edges.front();
            std::vector<bool> given(src->columns.size(), false);
            for (std::size_t i = 0; i < rec.cells.size(); ++i) {
                const Cell& c = rec.cells[i];
                const SourcePos at = pos.at(c.begin);
                if (i >= src->columns.size()) {
                    if (c.value.empty()) continue;
                    throw ToolTableError(code::csv_extra_field, "more fields than the header has columns", at);
                }
                const FieldInfo* f = src->columns[i];
                if (!f) continue;
                given[i] = !c.value.empty();
                if (f->kind == FieldKind::text) {
                    (f->id == Field::name ? row.name : row.comment) = c.value;
                    continue;
                }
                if (c.value.empty()) continue;
                if (f->kind == FieldKind::integer) {
                    int v = 0;
                    if (!tables::parse_integer(c.value, v))
                        throw ToolTableError(code::csv_bad_number,
                                             std::string(f->name) + " needs a whole number, got '" + c.value + "'", at);
                    if (v < 0 && f->id != Field::orientation)
                        throw ToolTableError(code::csv_bad_number, "negative " + std::string(f->name) + " '" + c.value + "'", at);
                    if (f->id == Field::orientation && (v < 0 || v > 9))
                        throw ToolTableError(code::csv_bad_orientation, "orientation must be 0..9, got '" + c.value + "'", at);
                    if (f->id == Field::tool)
                        row.number = v;
                    else if (f->id == Field::pocket)
                        row.pocket = v;
                    else
                        tables::set_edge_number(e, f->id, v);
                    continue;
                }
                double v = 0;
                if (!tables::parse_decimal(c.value, v))
                    throw ToolTableError(code::csv_bad_number, "bad number '" + c.value + "' in column " + std::string(f->name), at);
                tables::set_edge_number(e, f->id, f->kind == FieldKind::length ? v * scale : v);
            }
            const SourcePos tool_at = tool_column < rec.cells.size() ? pos.at(rec.cells[tool_column].begin) : pos.at(rec.begin);
            if (tool_column >= rec.cells.size() || rec.cells[tool_column].value.empty())
                throw ToolTableError(code::csv_missing_tool, "row without a tool number", tool_at);

            auto [fl, fresh] = first_line.emplace(std::make_pair(row.number, e.number), tool_at.line);
            if (!fresh)
                throw ToolTableError(code::csv_duplicate_tool,
                                     "tool " + std::to_string(row.number) + " edge " + std::to_string(e.number) +
                                         " already defined on line " + std::to_string(fl->second),
                                     tool_at);
            auto it = index.find(row.number);
            if (it == index.end()) {
                index.emplace(row.number, tools.size());
                tools.push_back(row);
            } else {
                Tool& t = tools[it->second];
                // Tool-level cells repeated on further edge rows must agree with the first row.
                for (std::size_t i = 0; i < src->columns.size(); ++i) {
                    const FieldInfo* f = src->columns[i];
                    if (!f || !given[i]) continue;
                    const bool differs = (f->id == Field::pocket && row.pocket != t.pocket) ||
                                         (f->id == Field::name && row.name != t.name) ||
                                         (f->id == Field::comment && row.comment != t.comment);
                    if (differs)
                        throw ToolTableError(code::csv_inconsistent_tool,
                                             std::string(f->name) + " of tool " + std::to_string(t.number) +
                                                 " differs from its first row",
                                             pos.at(rec.cells[i].begin));
                }
                t.edges.push_back(e);
            }
            kept.tool = row.number;
            kept.edge = e.number;
            src->file_edges[row.number].push_back(e.number);
            src->last_row[row.number] = src->records.size();
        }
        for (const Cell& c : rec.cells) kept.raw_cells.emplace_back(text.substr(c.begin, c.end - c.begin));
        src->records.push_back(std::move(kept));
    }

    ToolTable table(units);
    for (Tool& t : tools) {
        src->snapshots.emplace(t.number, t);
        table.set(std::move(t));
    }
    table.set_source(std::move(src));
    return table;
}

std::string write_csv_table(const ToolTable& table) {
    const double scale = mm_per_unit(table.units());
    for (const Tool& t : table.tools()) validate_tool(t);

    const auto* kept = dynamic_cast<const CsvSource*>(table.source());
    std::string out;
    if (!kept || !kept->has_header || kept->units != table.units()) {
        CsvSource canon;
        for (Field f : canonical_columns()) canon.columns.push_back(&tables::field_info(f));
        for (std::size_t i = 0; i < canon.columns.size(); ++i) {
            if (i) out += ',';
            out += canon.columns[i]->name;
        }
        out += '\n';
        for (const Tool& t : table.tools())
            for (const CuttingEdge& e : t.edges) {
                for (std::size_t i = 0; i < canon.columns.size(); ++i) {
                    if (i) out += ',';
                    out += cell_text(t, e, *canon.columns[i], scale);
                }
                out += '\n';
            }
        return out;
    }

    const CsvSource& src = *kept;
    // A changed or new tool may carry a value the file has no column for: such columns are
    // added at the end of the header (rows left as they were simply have fewer cells).
    std::vector<const FieldInfo*> columns = src.columns;
    {
        std::set<int> slots;
        for (const FieldInfo* f : columns)
            if (f) slots.insert(f->slot);
        for (Field id : canonical_columns()) {
            const FieldInfo& f = tables::field_info(id);
            if (slots.count(f.slot)) continue;
            bool needed = false;
            for (const Tool& t : table.tools()) {
                auto snap = src.snapshots.find(t.number);
                if (snap != src.snapshots.end() && snap->second == t) continue;
                for (const CuttingEdge& e : t.edges) needed = needed || !is_default(t, e, f);
            }
            if (needed) columns.push_back(&f);
        }
    }
    std::set<int> written;
    for (std::size_t r = 0; r < src.records.size(); ++r) {
        const KeptRecord& rec = src.records[r];
        if (rec.kind == RecordKind::header) {
            out += rec.text;
            for (std::size_t i = src.columns.size(); i < columns.size(); ++i) out += "," + std::string(columns[i]->name);
            out += rec.eol;
            continue;
        }
        if (rec.kind != RecordKind::row) {
            out += rec.text + rec.eol;
            continue;
        }
        const Tool* t = table.find(rec.tool);
        if (!t) continue;  // removed
        written.insert(t->number);
        const bool changed = *t != src.snapshots.at(rec.tool);
        if (!changed) {
            out += rec.text + rec.eol;
            continue;
        }
        if (t->has_edge(rec.edge)) out += row_text(columns, *t, t->edge(rec.edge), &rec.raw_cells, scale) + rec.eol;
        if (src.last_row.at(rec.tool) == r) {  // edges added to this tool go after its last row
            const auto& had = src.file_edges.at(rec.tool);
            for (const CuttingEdge& e : t->edges) {
                if (std::find(had.begin(), had.end(), e.number) != had.end()) continue;
                if (!tables::ends_with_line_end(out)) out += src.eol;
                out += row_text(columns, *t, e, nullptr, scale) + src.eol;
            }
        }
    }
    for (const Tool& t : table.tools()) {
        if (written.count(t.number)) continue;
        for (const CuttingEdge& e : t.edges) {
            if (!tables::ends_with_line_end(out)) out += src.eol;
            out += row_text(columns, t, e, nullptr, scale) + src.eol;
        }
    }
    return out;
}

}  // namespace toolcomp
