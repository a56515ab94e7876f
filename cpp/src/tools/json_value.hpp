#pragma once
// A small JSON parser that remembers where every value is in the text, so a tool table can
// be written back with only the changed parts replaced (private to cpp/src/tools).
#include <string>
#include <string_view>
#include <vector>

namespace toolcomp::tables {

struct JsonMember;

struct JsonValue {
    enum class Kind { null, boolean, number, string, array, object };
    Kind kind = Kind::null;
    std::size_t begin = 0, end = 0;  // extent in the text
    std::string text;                // decoded string, or the number as written
    bool boolean = false;
    std::vector<JsonValue> items;    // array
    std::vector<JsonMember> members; // object, in text order

    const JsonValue* get(std::string_view key) const;
};

struct JsonMember {
    std::string key;                     // decoded
    std::size_t key_begin = 0, key_end = 0;  // the key's extent, quotes included
    JsonValue value;
};

// Throws ToolTableError("json_syntax") with line/column; ("json_duplicate_key") for a key
// repeated in one object.
JsonValue parse_json(std::string_view text);

// 1-based line and column of a byte offset of `text`.
struct SourcePosLC { int line, column; };
SourcePosLC json_position(std::string_view text, std::size_t offset);

// A JSON string literal (quotes included) for UTF-8 `s`.
std::string json_quote(std::string_view s);

}  // namespace toolcomp::tables
