// JSON tool-table reader and writer.
#include "toolcomp/tools/format_json.hpp"
#include "toolcomp/program/codes.hpp"

#include "fields.hpp"
#include "json_value.hpp"
#include "number_text.hpp"
#include "toolcomp/program/diagnostic.hpp"

#include <cmath>
#include <map>
#include <set>

namespace toolcomp {

namespace {

using tables::Field;
using tables::FieldInfo;
using tables::FieldKind;
using tables::JsonMember;
using tables::JsonValue;
using Kind = JsonValue::Kind;

struct JsonSource : detail::TableSource {
    TableFormat format() const override { return TableFormat::json; }
    std::string text;
    JsonValue root;
    const JsonValue* tools = nullptr;  // the "tools" array inside root
    std::vector<int> element_tool;     // tool number of each element of the array
    std::map<int, Tool> snapshots;
};

class Reader {
public:
    Reader(std::string_view text, double scale) : text_(text), scale_(scale) {}

    [[noreturn]] void fail(const char* code, const std::string& msg, std::size_t at) const {
        const auto lc = tables::json_position(text_, at);
        throw ToolTableError(code, msg, SourcePos{lc.line, lc.column});
    }

    int integer(const JsonValue& v, std::string_view key) const {
        int n = 0;
        if (v.kind != Kind::number || !tables::parse_integer(v.text, n))
            fail(code::json_bad_number, "\"" + std::string(key) + "\" needs a whole number", v.begin);
        return n;
    }

    double number(const JsonValue& v, std::string_view key) const {
        double d = 0;
        if (v.kind != Kind::number || !tables::parse_decimal(v.text, d))
            fail(code::json_bad_value, "\"" + std::string(key) + "\" needs a number", v.begin);
        return d;
    }

    std::string string(const JsonValue& v, std::string_view key) const {
        if (v.kind != Kind::string) fail(code::json_bad_value, "\"" + std::string(key) + "\" needs a string", v.begin);
        return v.text;
    }

    // Reads the edge keys of `obj` into `e`; returns whether there were any.
    bool edge_fields(const JsonValue& obj, CuttingEdge& e) const {
        bool any = false;
        std::set<int> slots;
        for (const JsonMember& m : obj.members) {
            const FieldInfo* f = tables::find_field(m.key);
            if (!f || !f->edge_level) continue;
            if (!slots.insert(f->slot).second)
                fail(code::json_duplicate_key, "\"" + m.key + "\" gives a value already given", m.key_begin);
            any = true;
            if (f->kind == FieldKind::integer) {
                const int n = integer(m.value, m.key);
                if (f->id == Field::orientation && (n < 0 || n > 9))
                    fail(code::json_bad_orientation, "orientation must be 0..9", m.value.begin);
                if (f->id == Field::edge && n < 0) fail(code::json_bad_number, "negative edge number", m.value.begin);
                tables::set_edge_number(e, f->id, n);
            } else {
                const double d = number(m.value, m.key);
                tables::set_edge_number(e, f->id, f->kind == FieldKind::length ? d * scale_ : d);
            }
        }
        return any;
    }

    Tool tool(const JsonValue& obj) const {
        if (obj.kind != Kind::object) fail(code::json_bad_schema, "each entry of \"tools\" must be an object", obj.begin);
        Tool t;
        const JsonValue* num = obj.get("tool");
        if (!num) fail(code::json_missing_tool, "tool entry without \"tool\" number", obj.begin);
        t.number = integer(*num, "tool");
        if (t.number < 0) fail(code::json_bad_number, "negative tool number", num->begin);
        if (const JsonValue* v = obj.get("pocket")) {
            t.pocket = integer(*v, "pocket");
            if (t.pocket < 0) fail(code::json_bad_number, "negative pocket number", v->begin);
        }
        if (const JsonValue* v = obj.get("name")) t.name = string(*v, "name");
        if (const JsonValue* v = obj.get("comment")) t.comment = string(*v, "comment");

        const bool flat = edge_fields(obj, t.edges.front());
        if (const JsonValue* edges = obj.get("edges")) {
            if (flat) fail(code::json_mixed_edges, "give either \"edges\" or edge values in the tool, not both", edges->begin);
            if (edges->kind != Kind::array || edges->items.empty())
                fail(code::json_bad_schema, "\"edges\" must be a non-empty array of objects", edges->begin);
            t.edges.clear();
            for (const JsonValue& eo : edges->items) {
                if (eo.kind != Kind::object) fail(code::json_bad_schema, "each edge must be an object", eo.begin);
                CuttingEdge e;
                edge_fields(eo, e);
                if (t.has_edge(e.number))
                    fail(code::json_duplicate_edge, "edge " + std::to_string(e.number) + " appears twice", eo.begin);
                t.edges.push_back(e);
            }
        }
        return t;
    }

private:
    std::string_view text_;
    double scale_;
};

// ---- writing --------------------------------------------------------------------------

std::string spelled(const Tool& t, const CuttingEdge& e, const FieldInfo& f, double scale) {
    switch (f.id) {
        case Field::tool: return std::to_string(t.number);
        case Field::pocket: return std::to_string(t.pocket);
        case Field::name: return tables::json_quote(t.name);
        case Field::comment: return tables::json_quote(t.comment);
        case Field::edge: return std::to_string(e.number);
        case Field::orientation: return std::to_string(e.orientation);
        default:
            return tables::spell_shortest(tables::get_edge_number(e, f.id), f.kind == FieldKind::length ? scale : 1.0);
    }
}

bool edge_value_default(const CuttingEdge& e, Field f) {
    return f == Field::edge ? e.number == 1 : tables::get_edge_number(e, f) == 0;
}

// {"edge": 2, "x": 1, ...}: canonical edge object (for "edges" arrays).
std::string edge_object(const CuttingEdge& e, double scale) {
    std::string out = "{\"edge\": " + std::to_string(e.number);
    for (Field f : tables::canonical_edge_fields()) {
        if (edge_value_default(e, f)) continue;
        const auto& info = tables::field_info(f);
        out += ", \"" + std::string(info.name) + "\": " + spelled(Tool{}, e, info, scale);
    }
    return out + "}";
}

std::string edges_array(const Tool& t, double scale) {
    std::string out = "[";
    for (std::size_t i = 0; i < t.edges.size(); ++i) {
        if (i) out += ", ";
        out += edge_object(t.edges[i], scale);
    }
    return out + "]";
}

struct Member {
    std::string key;    // as written, quotes included
    std::string value;  // as written
};

// The members a tool has in canonical form, in canonical order (single-edge tools flat).
std::vector<Member> canonical_members(const Tool& t, double scale) {
    std::vector<Member> m;
    auto add = [&](std::string_view key, std::string value) { m.push_back({tables::json_quote(key), std::move(value)}); };
    add("tool", std::to_string(t.number));
    add("pocket", std::to_string(t.pocket));
    if (!t.name.empty()) add("name", tables::json_quote(t.name));
    if (t.edges.size() == 1) {
        const CuttingEdge& e = t.edges.front();
        if (e.number != 1) add("edge", std::to_string(e.number));
        for (Field f : tables::canonical_edge_fields())
            if (!edge_value_default(e, f)) add(tables::field_info(f).name, spelled(t, e, tables::field_info(f), scale));
    } else {
        add("edges", edges_array(t, scale));
    }
    if (!t.comment.empty()) add("comment", tables::json_quote(t.comment));
    return m;
}

std::string join_object(const std::vector<Member>& members, const std::string& open_ws, const std::string& colon,
                        const std::string& sep, const std::string& close_ws) {
    std::string out = "{" + open_ws;
    for (std::size_t i = 0; i < members.size(); ++i) {
        if (i) out += sep;
        out += members[i].key + colon + members[i].value;
    }
    return out + close_ws + "}";
}

std::string canonical_object(const Tool& t, double scale) {
    return join_object(canonical_members(t, scale), "", ": ", ", ", "");
}

struct ObjectStyle {
    std::string open_ws, colon = ": ", sep = ", ", close_ws;
};

// The spacing an object was written with, to write its replacement the same way.
ObjectStyle style_of(const std::string& text, const JsonValue& obj) {
    auto slice = [&](std::size_t b, std::size_t e) { return text.substr(b, e - b); };
    ObjectStyle st;
    const auto& ms = obj.members;
    if (!ms.empty()) {
        st.open_ws = slice(obj.begin + 1, ms.front().key_begin);
        st.colon = slice(ms.front().key_end, ms.front().value.begin);
        st.close_ws = slice(ms.back().value.end, obj.end - 1);
        if (ms.size() > 1) st.sep = slice(ms[0].value.end, ms[1].key_begin);
    }
    return st;
}

// Joins array elements with the spacing of the original array `arr`.
std::string join_array(const std::string& text, const JsonValue& arr, const std::vector<std::string>& pieces) {
    auto slice = [&](std::size_t b, std::size_t e) { return text.substr(b, e - b); };
    const auto& items = arr.items;
    std::string prefix, suffix, sep = ", ";
    if (!items.empty()) {
        prefix = slice(arr.begin + 1, items.front().begin);
        suffix = slice(items.back().end, arr.end - 1);
        if (items.size() > 1) sep = slice(items[0].end, items[1].begin);
    }
    std::string out = "[" + prefix;
    for (std::size_t i = 0; i < pieces.size(); ++i) out += (i ? sep : "") + pieces[i];
    return out + suffix + "]";
}

// A changed edge written over its original object: its keys and order, unknown keys as
// they were, values that are new appended.
std::string merged_edge_object(const std::string& text, const JsonValue& obj, const CuttingEdge& e, double scale) {
    std::vector<Member> out;
    std::set<int> slots;
    for (const JsonMember& m : obj.members) {
        const std::string key = text.substr(m.key_begin, m.key_end - m.key_begin);
        const FieldInfo* f = tables::find_field(m.key);
        if (!f || !f->edge_level) {
            out.push_back({key, text.substr(m.value.begin, m.value.end - m.value.begin)});
            continue;
        }
        slots.insert(f->slot);
        out.push_back({key, spelled(Tool{}, e, *f, scale)});
    }
    for (Field id : tables::canonical_edge_fields()) {
        const FieldInfo& f = tables::field_info(id);
        if (!slots.count(f.slot) && !edge_value_default(e, id))
            out.push_back({tables::json_quote(f.name), spelled(Tool{}, e, f, scale)});
    }
    if (!slots.count(tables::field_info(Field::edge).slot) && e.number != 1)
        out.insert(out.begin(), Member{"\"edge\"", std::to_string(e.number)});
    const ObjectStyle st = style_of(text, obj);
    return join_object(out, st.open_ws, st.colon, st.sep, st.close_ws);
}

// The "edges" array of a changed tool, each edge over its original object where there is one.
std::string merged_edges_array(const std::string& text, const JsonValue& arr, const Tool& t, double scale) {
    if (arr.kind != Kind::array) return edges_array(t, scale);
    std::vector<std::string> pieces;
    for (const CuttingEdge& e : t.edges) {
        const JsonValue* orig = nullptr;
        for (const JsonValue& item : arr.items) {
            int number = 1;
            if (const JsonValue* n = item.get("edge")) tables::parse_integer(n->text, number);
            if (item.kind == Kind::object && number == e.number) orig = &item;
        }
        pieces.push_back(orig ? merged_edge_object(text, *orig, e, scale) : edge_object(e, scale));
    }
    return join_array(text, arr, pieces);
}

// A changed tool: the object's own keys, order and spacing; known keys get the model's
// values, unknown keys stay as written; keys that now carry a value are appended.
std::string rewritten_object(const std::string& text, const JsonValue& obj, const Tool& t, double scale) {
    const bool had_edges = obj.get("edges") != nullptr;
    const bool flat = !had_edges && t.edges.size() == 1;

    std::vector<Member> out;
    std::set<int> slots;  // known fields already written
    for (const JsonMember& m : obj.members) {
        const std::string key = text.substr(m.key_begin, m.key_end - m.key_begin);
        const FieldInfo* f = tables::find_field(m.key);
        if (m.key == "edges") {
            out.push_back({key, merged_edges_array(text, m.value, t, scale)});
            continue;
        }
        if (!f) {
            out.push_back({key, text.substr(m.value.begin, m.value.end - m.value.begin)});
            continue;
        }
        slots.insert(f->slot);
        if (f->edge_level && !flat) continue;  // the edges moved into an "edges" array
        out.push_back({key, spelled(t, t.edges.front(), *f, scale)});
    }
    for (Member& c : canonical_members(t, scale)) {
        const std::string name = c.key.substr(1, c.key.size() - 2);
        const FieldInfo* f = tables::find_field(name);
        if (name == "edges") {
            if (!had_edges) out.push_back(std::move(c));
            continue;
        }
        if (f && slots.count(f->slot)) continue;
        if (f && f->edge_level && !flat) continue;
        if (f && f->id == Field::pocket && t.pocket == 0) continue;  // canonical only for new tools
        out.push_back(std::move(c));
    }
    const ObjectStyle st = style_of(text, obj);
    return join_object(out, st.open_ws, st.colon, st.sep, st.close_ws);
}

std::string canonical_document(const ToolTable& table, double scale) {
    std::string out = "{\n  \"units\": " + tables::json_quote(to_string(table.units())) + ",\n  \"tools\": [";
    const auto& tools = table.tools();
    for (std::size_t i = 0; i < tools.size(); ++i) {
        out += i ? ",\n    " : "\n    ";
        out += canonical_object(tools[i], scale);
    }
    out += tools.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

}  // namespace

ToolTable read_json_table(std::string_view text, LengthUnit units) {
    std::size_t bom = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    auto src = std::make_shared<JsonSource>();
    src->text = std::string(text);
    JsonValue root = tables::parse_json(std::string_view(src->text).substr(bom));
    // Positions of a parse of the text after a BOM are shifted back onto the whole text.
    if (bom) {
        struct Shift {
            std::size_t by;
            void operator()(JsonValue& v) const {
                v.begin += by;
                v.end += by;
                for (auto& i : v.items) (*this)(i);
                for (auto& m : v.members) {
                    m.key_begin += by;
                    m.key_end += by;
                    (*this)(m.value);
                }
            }
        } shift{bom};
        shift(root);
    }
    Reader probe(text, 1.0);
    if (root.kind != Kind::object)
        probe.fail(code::json_bad_schema, "a JSON tool table is an object with a \"tools\" array", root.begin);
    if (const JsonValue* u = root.get("units")) {
        if (u->kind != Kind::string) probe.fail(code::json_bad_units, "\"units\" must be \"mm\" or \"inch\"", u->begin);
        try {
            units = length_unit_from_string(u->text);
        } catch (const ToolTableError&) {
            probe.fail(code::json_bad_units, "\"units\" must be \"mm\" or \"inch\", not \"" + u->text + "\"", u->begin);
        }
    }
    const JsonValue* tools = root.get("tools");
    if (!tools || tools->kind != Kind::array)
        probe.fail(code::json_bad_schema, "a JSON tool table needs a \"tools\" array", tools ? tools->begin : root.begin);

    const Reader reader(text, mm_per_unit(units));
    ToolTable table(units);
    std::map<int, std::size_t> first;  // tool number -> offset of its first entry
    for (const JsonValue& item : tools->items) {
        Tool t = reader.tool(item);
        if (auto it = first.find(t.number); it != first.end()) {
            const auto lc = tables::json_position(text, it->second);
            reader.fail(code::json_duplicate_tool,
                        "tool " + std::to_string(t.number) + " already defined on line " + std::to_string(lc.line),
                        item.get("tool")->begin);
        }
        first.emplace(t.number, item.begin);
        src->element_tool.push_back(t.number);
        src->snapshots.emplace(t.number, t);
        table.set(std::move(t));
    }
    src->units = units;
    src->root = std::move(root);
    src->tools = src->root.get("tools");
    table.set_source(std::move(src));
    return table;
}

std::string write_json_table(const ToolTable& table) {
    const double scale = mm_per_unit(table.units());
    for (const Tool& t : table.tools()) validate_tool(t);
    const auto* src = dynamic_cast<const JsonSource*>(table.source());
    if (!src || src->units != table.units()) return canonical_document(table, scale);

    const std::string& text = src->text;
    const JsonValue& arr = *src->tools;
    const auto& items = arr.items;
    auto slice = [&](std::size_t b, std::size_t e) { return text.substr(b, e - b); };

    // The array's own spacing: before the first element, between elements, after the last.
    std::string prefix, suffix, sep;
    std::vector<std::string> seps;
    if (items.empty()) {
        prefix = "\n    ";
        sep = ",\n    ";
        suffix = "\n  ";
    } else {
        prefix = slice(arr.begin + 1, items.front().begin);
        suffix = slice(items.back().end, arr.end - 1);
        for (std::size_t i = 1; i < items.size(); ++i) seps.push_back(slice(items[i - 1].end, items[i].begin));
        sep = seps.empty() ? ", " : seps.front();
    }

    std::vector<std::string> pieces;
    std::set<int> written;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const int n = src->element_tool[i];
        const Tool* t = table.find(n);
        if (!t) continue;
        written.insert(n);
        pieces.push_back(*t == src->snapshots.at(n) ? slice(items[i].begin, items[i].end)
                                                    : rewritten_object(text, items[i], *t, scale));
    }
    for (const Tool& t : table.tools())
        if (!written.count(t.number)) pieces.push_back(canonical_object(t, scale));

    std::string body;
    if (!pieces.empty()) {
        body = prefix;
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            if (i) body += i - 1 < seps.size() ? seps[i - 1] : sep;
            body += pieces[i];
        }
        body += suffix;
    } else {
        body = items.empty() ? slice(arr.begin + 1, arr.end - 1) : "";
    }
    return text.substr(0, arr.begin + 1) + body + text.substr(arr.end - 1);
}

}  // namespace toolcomp
