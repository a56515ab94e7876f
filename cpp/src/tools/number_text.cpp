#include "number_text.hpp"
#include "toolcomp/program/codes.hpp"

#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace toolcomp::tables {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Checks the shape of a decimal number without converting it.
bool decimal_shape(std::string_view s) {
    std::size_t i = 0, n = s.size();
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < n && is_digit(s[i])) ++i, ++digits;
    if (i < n && s[i] == '.') {
        ++i;
        while (i < n && is_digit(s[i])) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
        std::size_t ed = 0;
        while (i < n && is_digit(s[i])) ++i, ++ed;
        if (ed == 0) return false;
    }
    return i == n;
}

double read_back(const std::string& text, double mm_per_unit) {
    double v = 0;
    parse_decimal(text, v);
    return v * mm_per_unit;
}

void require_finite(double v) {
    if (!std::isfinite(v))
        throw ToolTableError(code::table_bad_value, "a tool value is not a finite number");
}

std::string shortest(double v) {
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

}  // namespace

bool parse_decimal(std::string_view s, double& out) {
    if (!decimal_shape(s)) return false;
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    // from_chars does not take a lone leading '.', so give it a zero.
    std::string buf;
    if (!s.empty() && (s[0] == '.' || (s[0] == '-' && s.size() > 1 && s[1] == '.'))) {
        buf.assign(s);
        buf.insert(s[0] == '-' ? 1 : 0, "0");
        s = buf;
    }
    double v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return false;
    out = v;
    return true;
}

bool parse_integer(std::string_view s, int& out) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    if (s.empty() || (s[0] == '-' && s.size() == 1)) return false;
    for (std::size_t i = (s[0] == '-') ? 1 : 0; i < s.size(); ++i)
        if (!is_digit(s[i])) return false;
    int v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return false;
    out = v;
    return true;
}

std::string spell_linuxcnc(double model, double mm_per_unit) {
    require_finite(model);
    if (model == 0) return "0";
    const double v = model / mm_per_unit;
    char buf[64];
    for (int decimals = 6; decimals <= 17; ++decimals) {
        std::snprintf(buf, sizeof buf, "%+.*f", decimals, v);
        if (read_back(buf, mm_per_unit) == model) return buf;
    }
    std::string s = spell_shortest(model, mm_per_unit);
    return s[0] == '-' ? s : "+" + s;
}

std::string spell_shortest(double model, double mm_per_unit) {
    require_finite(model);
    if (model == 0) return "0";
    const double v = model / mm_per_unit;
    std::string s = shortest(v);
    if (read_back(s, mm_per_unit) == model) return s;
    // Dividing by the unit may have lost the last bit: look for a neighbour that reads back.
    double up = v, down = v;
    for (int i = 0; i < 4; ++i) {
        up = std::nextafter(up, std::numeric_limits<double>::infinity());
        down = std::nextafter(down, -std::numeric_limits<double>::infinity());
        for (double c : {up, down}) {
            std::string t = shortest(c);
            if (read_back(t, mm_per_unit) == model) return t;
        }
    }
    return s;
}

std::string trim(std::string_view s) {
    std::size_t b = 0, e = s.size();
    while (b < e && ascii_space(s[b])) ++b;
    while (e > b && ascii_space(s[e - 1])) --e;
    return std::string(s.substr(b, e - b));
}

std::string to_lower(std::string_view s) {
    std::string r;
    r.reserve(s.size());
    for (char c : s) r += ascii_lower(c);
    return r;
}

}  // namespace toolcomp::tables
