// The machine a program runs on (control/machine.hpp): the tool change position and the
// travel limits, in machine coordinates. Its origins are placed at start (interp.cpp).
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp::iso {

// M6 on a machine with a tool change position: the axes it names go there at rapid first
// (Haas mill: Z to machine zero), the others stay. (A lathe's machine X is a diameter, as the
// control shows it; the interpreter keeps radii.)
void Interp::to_tool_change_position(int column) {
    const Machine& mc = *opts_.machine;
    Vec6 m = to_machine(pos_);
    bool any = false;
    for (int i = 0; i < 3; ++i)
        if (const auto& v = mc.tool_change[static_cast<std::size_t>(i)]) {
            m[i] = *v / machine_scale(i);
            any = true;
        }
    if (!any) return;
    if (comp_on()) fail(code::comp_tool_change, "Cannot change tools with cutter radius compensation on", column);
    const Vec6 end = from_machine(m);
    if (end != pos_) straight(MotionKind::rapid, end, std::nan(""));
}

// A builder M code that runs a subprogram, after the rest of its block: LinuxCNC as
// o<program> call (a remap to an O-word sub), Fanuc as M98 P<number>.
// LinuxCNC's REMAP: an o-call of the code's sub with the argspec's words as its locals
// (interp_remap.cc): present words by their lower-case name, or as #1, #2, ... with '@'.
void Interp::remap_call(const MachineCode& c, const BlockWords& bw, const std::string& code_name, int column) {
    Statement s;
    s.kind = Stmt::o_call;
    s.column = column;
    std::string name = c.program;  // LinuxCNC folds a sub's name to lower case, as o<MySub> call
    for (char& ch : name) ch = ascii_lower(ch);
    s.label = "<" + name + ">";
    std::string missing, unmet;
    std::vector<std::pair<std::string, double>> named;
    std::vector<double> positional;
    const bool at = c.argspec.find('@') != std::string::npos;
    for (char ch : c.argspec) {
        if (ch == '>' || ch == '^') {
            const double v = ch == '>' ? (st_.feed_mode == G93 ? feed_ : feed_ / scale()) : spindles_[0].speed;
            if (v <= 0) unmet += ch == '>' ? "F>0," : "S>0,";
            else named.emplace_back(ch == '>' ? "f" : "s", v);
            continue;
        }
        if (ch == '@') continue;
        const char u = static_cast<char>(ch >= 'a' ? ch - 32 : ch);
        const bool present = (bw.machine_words & letter_bit(u)) != 0;
        const double v = present ? bw.letter[static_cast<std::size_t>(letter_index(u))].value : 0.0;
        if (!present && ch == u) missing += missing.empty() ? std::string(1, u) : "," + std::string(1, u);
        if (at) positional.push_back(v);
        else if (present) named.emplace_back(std::string(1, ascii_lower(u)), v);
    }
    if (!missing.empty() || !unmet.empty())
        fail(code::remap_words, "user-defined " + code_name + ":" + (missing.empty() ? "" : " missing: " + missing) + unmet,
             column);
    call_sub(s);
    for (std::size_t i = 0; i < positional.size() && i < 30; ++i) params_.set(static_cast<int>(i) + 1, positional[i]);
    for (const auto& [n, v] : named) params_.set_named(n, v);
}

void Interp::machine_subprogram(const BlockWords& bw) {
    const MachineCode& c = *bw.machine_call;
    const int column = bw.machine_call_column;
    if (prog_.dialect == Dialect::linuxcnc) return remap_call(c, bw, "M" + std::to_string(bw.machine_call_number), column);
    const std::string n = c.program[0] == 'O' || c.program[0] == 'o' ? c.program.substr(1) : c.program;
    WordSlot p;
    p.value = std::stod(n);
    p.column = column;
    p.set = true;
    call_program(Frame::m98, p, WordSlot{}, column);
}

// A remapped G code as the block's motion: its sub now, the block's stop when it returns. It
// does not stay the motion mode (the sub's last motion does).
bool Interp::remapped_motion(const BlockWords& bw) {
    const int col = bw.g_column[g_motion];
    st_.motion = prev_motion_;
    const int g = bw.g[g_motion];
    remap_call(*bw.machine_g, bw, "G" + std::to_string(g / 10) + (g % 10 ? "." + std::to_string(g % 10) : ""), col);
    if (bw.m[m_stop] >= 0) {  // M0/M1/M2/M30 of the block come after the motion
        auto rest = std::make_shared<BlockWords>(bw);
        rest->g.fill(-1);
        rest->g_groups = 0;
        rest->letters = 0;
        rest->machine_g = nullptr;
        rest->machine_call = nullptr;
        rest->m.fill(-1);
        rest->m[m_stop] = bw.m[m_stop];
        rest->m_count = 1;
        frames_.back().resume = rest;
        frames_.back().resume_motion = -1;
        return false;  // the block's stop waits for the sub
    }
    return true;
}

void Interp::check_travel(const Motion& m) {
    const auto msg = travel_->beyond(m, rotation_[st_.coord_system - 1] * kPi / 180, [this](const Vec3& p) {
        Vec6 q = pos_;
        q.head<3>() = p;
        const Vec6 machine = to_machine(q);
        return Vec3(machine[0] * machine_scale(0), machine[1] * machine_scale(1), machine[2] * machine_scale(2));
    });
    if (!msg) return;
    if (travel_->stops()) fail(code::travel_limit, *msg);
    travel_->warn(*msg, {line_, 0, file_name()}, diags_);
}

}  // namespace toolcomp::iso
