#include "json_value.hpp"
#include "toolcomp/program/codes.hpp"

#include "toolcomp/program/diagnostic.hpp"

#include <cstdio>

namespace toolcomp::tables {

const JsonValue* JsonValue::get(std::string_view key) const {
    for (const auto& m : members)
        if (m.key == key) return &m.value;
    return nullptr;
}

SourcePosLC json_position(std::string_view text, std::size_t offset) {
    int line = 1, col = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return {line, col};
}

namespace {

constexpr int kMaxDepth = 128;

class Parser {
public:
    explicit Parser(std::string_view t) : t_(t) {}

    JsonValue document() {
        skip_ws();
        JsonValue v = value(0);
        skip_ws();
        if (p_ != t_.size()) fail("unexpected text after the JSON document");
        return v;
    }

private:
    std::string_view t_;
    std::size_t p_ = 0;

    [[noreturn]] void fail(const std::string& msg, const char* code = code::json_syntax) { fail_at(p_, msg, code); }
    [[noreturn]] void fail_at(std::size_t at, const std::string& msg, const char* code = code::json_syntax) {
        const auto lc = json_position(t_, at);
        throw ToolTableError(code, msg, SourcePos{lc.line, lc.column});
    }

    void skip_ws() {
        while (p_ < t_.size() && (t_[p_] == ' ' || t_[p_] == '\t' || t_[p_] == '\n' || t_[p_] == '\r')) ++p_;
    }

    bool literal(std::string_view word) {
        if (t_.substr(p_, word.size()) != word) return false;
        p_ += word.size();
        return true;
    }

    JsonValue value(int depth) {
        if (depth > kMaxDepth) fail("JSON nested too deeply");
        JsonValue v;
        v.begin = p_;
        if (p_ >= t_.size()) fail("unexpected end of the JSON text");
        const char c = t_[p_];
        if (c == '{') {
            v.kind = JsonValue::Kind::object;
            ++p_;
            skip_ws();
            if (p_ < t_.size() && t_[p_] == '}') {
                ++p_;
            } else {
                for (;;) {
                    skip_ws();
                    if (p_ >= t_.size() || t_[p_] != '"') fail("expected a string key");
                    JsonMember m;
                    m.key_begin = p_;
                    m.key = string_body();
                    m.key_end = p_;
                    for (const auto& other : v.members)
                        if (other.key == m.key) fail_at(m.key_begin, "key \"" + m.key + "\" appears twice", code::json_duplicate_key);
                    skip_ws();
                    if (p_ >= t_.size() || t_[p_] != ':') fail("expected ':'");
                    ++p_;
                    skip_ws();
                    m.value = value(depth + 1);
                    v.members.push_back(std::move(m));
                    skip_ws();
                    if (p_ < t_.size() && t_[p_] == ',') {
                        ++p_;
                        continue;
                    }
                    if (p_ < t_.size() && t_[p_] == '}') {
                        ++p_;
                        break;
                    }
                    fail("expected ',' or '}'");
                }
            }
        } else if (c == '[') {
            v.kind = JsonValue::Kind::array;
            ++p_;
            skip_ws();
            if (p_ < t_.size() && t_[p_] == ']') {
                ++p_;
            } else {
                for (;;) {
                    skip_ws();
                    v.items.push_back(value(depth + 1));
                    skip_ws();
                    if (p_ < t_.size() && t_[p_] == ',') {
                        ++p_;
                        continue;
                    }
                    if (p_ < t_.size() && t_[p_] == ']') {
                        ++p_;
                        break;
                    }
                    fail("expected ',' or ']'");
                }
            }
        } else if (c == '"') {
            v.kind = JsonValue::Kind::string;
            v.text = string_body();
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            v.kind = JsonValue::Kind::number;
            v.text = number();
        } else if (literal("true")) {
            v.kind = JsonValue::Kind::boolean;
            v.boolean = true;
        } else if (literal("false")) {
            v.kind = JsonValue::Kind::boolean;
        } else if (literal("null")) {
            v.kind = JsonValue::Kind::null;
        } else {
            fail("unexpected character in JSON");
        }
        v.end = p_;
        return v;
    }

    std::string number() {
        const std::size_t b = p_;
        auto digits = [&] {
            const std::size_t s = p_;
            while (p_ < t_.size() && t_[p_] >= '0' && t_[p_] <= '9') ++p_;
            return p_ - s;
        };
        if (t_[p_] == '-') ++p_;
        if (p_ < t_.size() && t_[p_] == '0')
            ++p_;
        else if (digits() == 0)
            fail("bad JSON number");
        if (p_ < t_.size() && t_[p_] == '.') {
            ++p_;
            if (digits() == 0) fail("bad JSON number");
        }
        if (p_ < t_.size() && (t_[p_] == 'e' || t_[p_] == 'E')) {
            ++p_;
            if (p_ < t_.size() && (t_[p_] == '+' || t_[p_] == '-')) ++p_;
            if (digits() == 0) fail("bad JSON number");
        }
        return std::string(t_.substr(b, p_ - b));
    }

    unsigned hex4() {
        if (p_ + 4 > t_.size()) fail("bad \\u escape");
        unsigned v = 0;
        for (int i = 0; i < 4; ++i) {
            const char c = t_[p_++];
            v <<= 4;
            if (c >= '0' && c <= '9') v |= static_cast<unsigned>(c - '0');
            else if (c >= 'a' && c <= 'f') v |= static_cast<unsigned>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') v |= static_cast<unsigned>(c - 'A' + 10);
            else fail("bad \\u escape");
        }
        return v;
    }

    static void put_utf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    // At the opening quote; returns the decoded string and leaves p_ after the closing one.
    std::string string_body() {
        const std::size_t open = p_;
        ++p_;
        std::string out;
        for (;;) {
            if (p_ >= t_.size()) fail_at(open, "string is never closed");
            const char c = t_[p_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail_at(p_ - 1, "control character in a JSON string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (p_ >= t_.size()) fail_at(open, "string is never closed");
            const char e = t_[p_++];
            switch (e) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    unsigned cp = hex4();
                    if (cp >= 0xD800 && cp < 0xDC00) {
                        if (t_.substr(p_, 2) != "\\u") fail("unpaired surrogate in \\u escape");
                        p_ += 2;
                        const unsigned lo = hex4();
                        if (lo < 0xDC00 || lo >= 0xE000) fail("unpaired surrogate in \\u escape");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                    } else if (cp >= 0xDC00 && cp < 0xE000) {
                        fail("unpaired surrogate in \\u escape");
                    }
                    put_utf8(out, cp);
                    break;
                }
                default: fail_at(p_ - 2, "bad escape in a JSON string");
            }
        }
    }
};

}  // namespace

JsonValue parse_json(std::string_view text) { return Parser(text).document(); }

std::string json_quote(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

}  // namespace toolcomp::tables
