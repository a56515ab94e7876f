// Machines: a control's profile plus the builder's configuration (control/machine.hpp).
#include "toolcomp/control/machine.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace toolcomp {

Machine plain_machine(Dialect control, MachineKind kind) {
    Machine m;
    m.name = std::string(dialect_name(control)) + (kind == MachineKind::lathe ? "-lathe" : "");
    m.control = control;
    m.kind = kind;
    m.profile = profile_for(control, kind);
    return m;
}

namespace {
[[noreturn]] void bad(const std::string& field, const std::string& why) {
    throw std::invalid_argument("Machine." + field + ": " + why);
}
void finite(const std::string& field, double v) {
    if (!std::isfinite(v)) bad(field, "must be a finite number (got " + std::to_string(v) + ")");
}
const char* kAxis[3] = {"x", "y", "z"};
// LinuxCNC's REMAP argspec: letters but O, '@', '>', '^'.
void check_argspec(const std::string& field, const std::string& code, const std::string& argspec) {
    for (char c : argspec)
        if (!(((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')) && c != 'O' && c != 'o') && c != '@' && c != '>' && c != '^')
            bad(field, code + " argspec: '" + std::string(1, c) + "' is not an argspec character (letters but O, '@', '>', '^')");
}
}  // namespace

void check_machine(const Machine& m) {
    if (m.profile.kind != m.kind) bad("profile", "is a profile of another kind of machine (mill / lathe)");
    if (m.spindles < 1 || m.spindles > Machine::kMaxSpindles) bad("spindles", "must be 1 to 8");
    for (const auto& [number, code] : m.m_codes) {
        if (number < 0 || number > 99999) bad("m_codes", "M" + std::to_string(number) + " is no M code number (0 to 99999)");
        if (std::find(m.profile.fixed_m_codes.begin(), m.profile.fixed_m_codes.end(), number) !=
            m.profile.fixed_m_codes.end())
            bad("m_codes", "M" + std::to_string(number) + " is fixed by the control (" +
                               std::string(dialect_name(m.control)) + "); a machine cannot declare it");
        for (char c : code.words)
            if (c < 'A' || c > 'Z' || c == 'G' || c == 'M' || c == 'N' || c == 'X' || c == 'Y' || c == 'Z')
                bad("m_codes", "M" + std::to_string(number) + " words: '" + std::string(1, c) +
                                   "' is not a letter an M code may read (A-Z but G, M, N, X, Y, Z)");
        if (code.action == MCodeAction::subprogram) {
            const std::string where = "M" + std::to_string(number) + " runs a subprogram: ";
            if (m.control != Dialect::linuxcnc && m.control != Dialect::fanuc)
                bad("m_codes", where + "toolcomp runs them on LinuxCNC and Fanuc machines");
            if (code.program.empty()) bad("m_codes", where + "its program is missing");
            if (m.control == Dialect::fanuc) {
                const std::string n = code.program[0] == 'O' || code.program[0] == 'o' ? code.program.substr(1) : code.program;
                if (n.empty() || n.size() > 8 || n.find_first_not_of("0123456789") != std::string::npos)
                    bad("m_codes", where + "a Fanuc program is an O number (O9020), not '" + code.program + "'");
            } else if (code.program.find_first_of("/\\<> ") != std::string::npos || code.program.find("..") != std::string::npos) {
                bad("m_codes", where + "'" + code.program + "' is no subroutine name");
            }
            if (m.control == Dialect::linuxcnc && number >= 100 && number <= 199)
                bad("m_codes", where + "LinuxCNC runs M100-M199 as user programs, never remapped (declare what they do "
                                       "for the path: nothing)");
        }
        if (!code.argspec.empty() && (code.action != MCodeAction::subprogram || m.control != Dialect::linuxcnc))
            bad("m_codes", "M" + std::to_string(number) + " argspec: LinuxCNC's REMAP argspec is for subprogram codes");
        check_argspec("m_codes", "M" + std::to_string(number), code.argspec);
        // LinuxCNC reads M codes up to M199 in programs and remaps M200-M999.
        const int highest = m.control == Dialect::linuxcnc ? 999 : m.profile.max_m_code;
        if (number > highest)
            bad("m_codes", "M" + std::to_string(number) + " is beyond the M codes " + std::string(dialect_name(m.control)) +
                               " reads (up to M" + std::to_string(highest) + ")");
    }
    for (const auto& [code10, code] : m.g_codes) {
        const std::string where = "G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
        if (m.control != Dialect::linuxcnc) bad("g_codes", where + ": remapped G codes are LinuxCNC's");
        if (code10 < 0 || code10 > 9999) bad("g_codes", where + " is no G code number");
        if (code.action != MCodeAction::subprogram || code.program.empty())
            bad("g_codes", where + " runs a subprogram: its program is missing");
        if (code.program.find_first_of("/\\<> ") != std::string::npos || code.program.find("..") != std::string::npos)
            bad("g_codes", where + ": '" + code.program + "' is no subroutine name");
        check_argspec("g_codes", where, code.argspec);
    }
    for (const auto& datum : m.machine_data) {
        const std::string& name = datum.first;
        const double value = datum.second;
        if (m.control != Dialect::sinumerik) bad("machine_data", name + ": machine data are the Sinumerik's");
        static constexpr std::string_view kPrefixes[] = {"$MN_", "$MC_", "$MA_", "$SN_", "$SC_", "$SA_"};
        // an index after the name: "[3]", "[X]", "[1,Z]" (whole numbers or axis names)
        const std::size_t open = name.find('[');
        const std::string base = name.substr(0, open);
        const bool index_ok = open == std::string::npos ||
                              (name.back() == ']' && name.size() > open + 2 &&
                               name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789,-", open + 1) == name.size() - 1);
        if (std::none_of(std::begin(kPrefixes), std::end(kPrefixes), [&base](std::string_view p) { return base.rfind(p, 0) == 0; }) ||
            base.size() < 5 || base.find_first_not_of("$ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos || !index_ok)
            bad("machine_data", "'" + name + "' is no machine or setting data name ($MN_, $MC_, $MA_, $SN_, $SC_, $SA_ and upper "
                                             "case, an index as [3], [X] or [1,Z])");
        if (!std::isfinite(value)) bad("machine_data", name + " must be a finite number");
    }
    for (const auto& [number, code] : m.cycles) {
        const std::string where = "CYCL DEF " + std::to_string(number);
        if (m.control != Dialect::heidenhain) bad("cycles", where + ": builder cycles are the Heidenhain's");
        if (number < 1 || number > 9999) bad("cycles", where + " is no cycle number");
        if (code.action != MCodeAction::nothing)
            bad("cycles", where + ": a builder cycle is declared with the action nothing (it does not move the tool)");
        static constexpr int kRun[] = {1, 7, 8, 9, 10, 11, 17, 19, 26, 32, 200, 201, 203, 205, 207, 208, 220, 221, 247};
        if (std::find(std::begin(kRun), std::end(kRun), number) != std::end(kRun))
            bad("cycles", where + " is a cycle of the TNC itself");
    }
    for (int i = 0; i < 3; ++i) {
        const std::string a = kAxis[i];
        finite("work_origin." + a, m.work_origin[i]);
        finite("g28." + a, m.g28[i]);
        finite("g30." + a, m.g30[i]);
        finite("start." + a, m.start[i]);
        finite("m92." + a, m.m92[i]);
        if (m.tool_change[i]) finite("tool_change." + a, *m.tool_change[i]);
        const AxisTravel& t = m.travel[i];
        if (std::isnan(t.min) || std::isnan(t.max)) bad("travel." + a, "bounds must be numbers");
        if (t.min > t.max) bad("travel." + a, "min " + std::to_string(t.min) + " is above max " + std::to_string(t.max));
        for (const auto* r : {&m.rapid_rate, &m.max_feed})
            if (!std::isfinite((*r)[i]) || (*r)[i] < 0)
                bad(std::string(r == &m.rapid_rate ? "rapid_rate." : "max_feed.") + a, "must be a finite number >= 0");
    }
    if (!std::isfinite(m.tool_change_time) || m.tool_change_time < 0)
        bad("tool_change_time", "must be a finite number >= 0 (seconds)");
    check_profile(m.profile);
}

}  // namespace toolcomp
