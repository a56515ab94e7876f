// Reading and writing "$TC_DPn[t,d]=value" initialisation lines (spec §3.1).
#include <sstream>

#include "number_text.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"
#include "toolcomp/tools/sinumerik_edge.hpp"

namespace toolcomp::sinumerik {

namespace {

// A cursor over one line; `col` is 0-based, errors report col + 1.
struct Cursor {
    std::string_view s;
    std::size_t col = 0;
    int line = 0;

    void blanks() {
        while (col < s.size() && (s[col] == ' ' || s[col] == '\t')) ++col;
    }
    bool at_end() {
        blanks();
        return col >= s.size();
    }
    [[noreturn]] void fail(const std::string& code, const std::string& msg, std::size_t at) const {
        throw ToolTableError(code, "line " + std::to_string(line) + ": " + msg,
                             SourcePos{line, static_cast<int>(at) + 1});
    }
    [[noreturn]] void bad(const std::string& expected) const {
        fail(code::sinumerik_bad_line, "expected " + expected + " in a $TC_DPn[t,d]=value line", col);
    }
    bool word(std::string_view w) {  // case-insensitive keyword
        blanks();
        if (s.size() - col < w.size()) return false;
        for (std::size_t i = 0; i < w.size(); ++i)
            if (ascii_upper(s[col + i]) != w[i]) return false;
        col += w.size();
        return true;
    }
    void expect(char c, const char* what) {
        blanks();
        if (col >= s.size() || s[col] != c) bad(what);
        ++col;
    }
    int integer(const char* what, std::size_t& start) {
        blanks();
        start = col;
        while (col < s.size() && ascii_digit(s[col])) ++col;
        int v = 0;
        if (col == start || !tables::parse_integer(s.substr(start, col - start), v)) {
            col = start;
            bad(what);
        }
        return v;
    }
};

std::string_view strip_comment(std::string_view l) {
    auto p = l.find(';');
    return p == std::string_view::npos ? l : l.substr(0, p);
}

bool is_end_word(std::string_view t) {
    std::string u = tables::to_lower(tables::trim(t));
    return u == "m17" || u == "m30" || u == "m02" || u == "m2";
}

}  // namespace

SinumerikEdgeMap parse_tc_dp(std::string_view text, int max_t, int max_d) {
    text = skip_bom(text);
    SinumerikEdgeMap out;
    int line_no = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        std::string_view raw = text.substr(pos, nl - pos);
        pos = nl + 1;
        ++line_no;
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        Cursor c{strip_comment(raw), 0, line_no};
        if (c.at_end()) continue;
        // Optional block number N<digits>.
        if ((c.s[c.col] == 'N' || c.s[c.col] == 'n') && c.col + 1 < c.s.size() &&
            ascii_digit(c.s[c.col + 1])) {
            ++c.col;
            while (c.col < c.s.size() && ascii_digit(c.s[c.col])) ++c.col;
            if (c.at_end()) continue;
        }
        if (is_end_word(c.s.substr(c.col))) continue;
        if (!c.word("$TC_")) c.bad("$TC_DP, $TC_ECP or $TC_SCP");
        int which = 0;  // 0 DP, 1 ECP, 2 SCP
        if (c.word("DP")) which = 0;
        else if (c.word("ECP")) which = 1;
        else if (c.word("SCP")) which = 2;
        else c.bad("DP, ECP or SCP after $TC_");
        std::size_t at_n = 0, at_t = 0, at_d = 0;
        const int n = c.integer("a parameter number", at_n);
        c.expect('[', "'['");
        const int t = c.integer("a tool number", at_t);
        c.expect(',', "','");
        const int d = c.integer("an edge number", at_d);
        c.expect(']', "']'");
        c.expect('=', "'='");
        c.blanks();
        const std::size_t at_v = c.col;
        double v = 0;
        if (!tables::parse_decimal(tables::trim(c.s.substr(at_v)), v)) {
            c.col = at_v;
            c.bad("a decimal value after '='");
        }
        if (n < 1 || n > 25) c.fail(code::sinumerik_bad_dp, "parameter number " + std::to_string(n) + " is outside 1..25", at_n);
        if (t < 1 || t > max_t)
            c.fail(code::sinumerik_bad_tool, "tool number " + std::to_string(t) + " is outside 1.." + std::to_string(max_t), at_t);
        if (d < 1 || d > max_d)
            c.fail(code::sinumerik_bad_edge, "edge number " + std::to_string(d) + " is outside 1.." + std::to_string(max_d), at_d);
        SinumerikEdge& e = out[{t, d}];
        auto& arr = which == 0 ? e.dp : which == 1 ? e.ecp : e.scp;
        arr[static_cast<std::size_t>(n - 1)] = v;
        if (nl == text.size()) break;
    }
    return out;
}

std::string write_tc_dp(const SinumerikEdgeMap& edges) {
    std::ostringstream os;
    const char* names[3] = {"DP", "ECP", "SCP"};
    for (const auto& [key, e] : edges) {
        const std::array<double, 25>* arrays[3] = {&e.dp, &e.ecp, &e.scp};
        for (int w = 0; w < 3; ++w) {
            for (std::size_t i = 0; i < 25; ++i) {
                const double v = (*arrays[w])[i];
                if (v == 0 && !(w == 0 && i == 0)) continue;
                os << "$TC_" << names[w] << (i + 1) << '[' << key.first << ',' << key.second
                   << "]=" << tables::spell_shortest(v, 1.0) << '\n';
            }
        }
    }
    return os.str();
}

}  // namespace toolcomp::sinumerik
