// FN 18: SYSREAD Qn = ID<group> NR<number> [IDX<index>]: the control's data a part program
// reads, from the interpreter's state (TNC group and number, as the TNC's manuals list them).
// A group toolcomp does not keep is refused by its numbers, never read as 0.
#include <cctype>
#include <cmath>
#include <string>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::heidenhain {

namespace {

// The statement's words after "SYSREAD": the target Q number and ID, NR, IDX (a number or
// a Q parameter each).
struct SysreadWords {
    int target = -1;
    std::string id, nr, idx;  // as written (digits, or Qn)
};

SysreadWords read_words(std::string_view s) {
    SysreadWords w;
    std::size_t i = s.find("SYSREAD");
    if (i == std::string_view::npos) throw std::invalid_argument("SYSREAD expected");
    i += 7;
    auto skip = [&] {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    };
    auto word = [&](std::string_view letters) {  // the letters, then a value word
        skip();
        for (char c : letters) {
            if (i >= s.size() || ascii_upper(s[i]) != c) return std::string();
            ++i;
        }
        skip();
        std::string v;
        if (i < s.size() && ascii_upper(s[i]) == 'Q') v.push_back('Q'), ++i;
        while (i < s.size() && (ascii_digit(s[i]) || s[i] == '.')) v.push_back(s[i++]);
        if (v.empty() || v == "Q") throw std::invalid_argument(std::string(letters) + " needs a number");
        return v;
    };
    skip();
    if (i >= s.size() || ascii_upper(s[i]) != 'Q' || i + 1 >= s.size() || !ascii_digit(s[i + 1]))
        throw std::invalid_argument("the target Q parameter expected (QL / QR are not supported by toolcomp)");
    ++i;
    w.target = 0;
    while (i < s.size() && ascii_digit(s[i])) w.target = w.target * 10 + (s[i++] - '0');
    skip();
    if (i >= s.size() || s[i] != '=') throw std::invalid_argument("'=' expected");
    ++i;
    w.id = word("ID");
    w.nr = word("NR");
    if (w.id.empty() || w.nr.empty()) throw std::invalid_argument("ID and NR expected");
    w.idx = word("IDX");
    skip();
    if (i < s.size() && s[i] != ';') throw std::invalid_argument("unexpected text after SYSREAD");
    return w;
}

}  // namespace

void Interp::sysread(const Token& statement) {
    SysreadWords w;
    try {
        w = read_words(statement.text);
    } catch (const std::invalid_argument& e) {
        fail(code::q_syntax, std::string("FN 18: SYSREAD: ") + e.what(), statement.column);
    }
    auto value = [&](const std::string& v) {
        if (v.empty()) return 0.0;
        if (v[0] == 'Q') return q_value(std::stoi(v.substr(1)), statement.column);
        return std::stod(v);
    };
    const double id = value(w.id), nr = value(w.nr), idx = value(w.idx);
    if (id != std::floor(id) || nr != std::floor(nr) || idx != std::floor(idx) || std::fabs(id) > 1e6 ||
        std::fabs(nr) > 1e6 || std::fabs(idx) > 1e6)
        fail(code::q_syntax, "FN 18: SYSREAD: ID, NR and IDX are whole numbers", statement.column);
    check_q(w.target, statement.column);
    q_[w.target] = system_datum(static_cast<int>(id), static_cast<int>(nr), static_cast<int>(idx), statement.column);
}

// The groups programs read: the units, the tool (its number, axis, table data, TOOL CALL
// deltas, its active radius and length), the feed, the transformations (cycles 7, 8, 10, 11,
// 26), the travel limits of the machine, the current position in the active system (ID270)
// and in the machine's (ID240: the spindle's, as an M91 block programs it, so that L Z+Q1 M91
// after FN 18 ... ID240 NR1 IDX3 stays where it is). Lengths in program units.
double Interp::system_datum(int id, int nr, int idx, int column) const {
    const int axis = axes(working_plane_.value_or(plane_)).c;  // 0 X, 1 Y, 2 Z
    auto refused = [&]() -> double {
        fail(code::unsupported_parameter,
             "FN 18: SYSREAD ID" + std::to_string(id) + " NR" + std::to_string(nr) +
                 (idx ? " IDX" + std::to_string(idx) : std::string()) + " is not supported by toolcomp",
             column);
    };
    auto axis_index = [&]() {  // IDX 1-3: X, Y, Z
        if (idx < 1 || idx > 3) refused();
        return idx - 1;
    };
    switch (id) {
        case 10:
            if (nr == 1) return prog_.inch ? 1 : 0;
            break;
        case 20:
            if (nr == 1) return tool_;
            if (nr == 3) return axis;
            if (nr == 9) return feed_ / (prog_.inch ? 2.54 : 1.0);
            break;
        case 50: {  // the tool table's data of tool IDX
            const Tool* t = tools_ ? tools_->find(idx) : nullptr;
            if (!t) {
                if (auto d = defs_.find(idx); d != defs_.end() && nr >= 1 && nr <= 6)
                    return nr == 1 ? d->second.length : nr == 2 ? d->second.radius : nr == 3 ? d->second.r2 : 0.0;
                fail(code::tool_not_found, "FN 18: SYSREAD ID50: tool " + std::to_string(idx) + " is not in the tool table",
                     column);
            }
            const CuttingEdge& e = t->edge();
            switch (nr) {
                case 1: return e.length.z() / unit_;
                case 2: return e.radius / unit_;
                case 3: return e.corner_radius / unit_;
                case 4: return e.length_wear.z() / unit_;
                case 5: return e.radius_wear / unit_;
                case 6: return e.corner_radius_wear / unit_;
                default: break;
            }
            break;
        }
        case 60:  // the TOOL CALL
            if (nr == 1) return tool_;
            if (nr == 2) return axis;
            if (nr == 4) return call_dl_;
            if (nr == 5) return call_dr_;
            if (nr == 7) return call_dr2_;
            break;
        case 200:  // the active tool, oversizes included
            if (nr == 1 && idx == 0) return radius_;
            if (nr == 2 && idx == 0) return tlo_[axis];
            break;
        case 210:
            if (nr == 2) return transforms_.rotation;  // rotation (cycle 10)
            if (nr == 3) {                             // mirrored axes: bits 0-2 X, Y, Z
                int bits = 0;
                for (int i = 0; i < 3; ++i) bits |= transforms_.mirror[static_cast<std::size_t>(i)] ? 1 << i : 0;
                return bits;
            }
            if (nr == 4) return transforms_.scale * transforms_.axis_scale[axis_index()];  // scaling of the axis
            break;
        case 220:
            if (nr == 2) return transforms_.shift[axis_index()];  // the datum shift (cycle 7)
            break;
        case 230:  // software limits of the machine (machine frame)
            if ((nr == 2 || nr == 3) && machine_) {
                const AxisTravel& tr = machine_->travel[static_cast<std::size_t>(axis_index())];
                const double v = nr == 2 ? tr.min : tr.max;
                if (std::isfinite(v)) return v / unit_;
            }
            if (nr == 2 || nr == 3)
                fail(code::travel_limit, "FN 18: SYSREAD ID230 reads the machine's travel: give the machine (a machine file with [travel])",
                     column);
            break;
        case 240:  // the nominal position in the machine (REF) system
            if (nr == 1) return frame().point(pos_)[axis_index()] + work_origin_[axis_index()] + tlo_[axis_index()];
            break;
        case 270:  // the current position in the active coordinate system
            if (nr == 1) return pos_[axis_index()];
            break;
        default:
            break;
    }
    return refused();
}

}  // namespace toolcomp::heidenhain
