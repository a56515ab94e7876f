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
void Interp::machine_subprogram(const MachineCode& c, int column) {
    if (prog_.dialect == Dialect::linuxcnc) {
        Statement s;
        s.kind = Stmt::o_call;
        s.column = column;
        std::string name = c.program;  // LinuxCNC folds a sub's name to lower case, as o<MySub> call
        for (char& ch : name) ch = ascii_lower(ch);
        s.label = "<" + name + ">";
        call_sub(s);
        return;
    }
    const std::string n = c.program[0] == 'O' || c.program[0] == 'o' ? c.program.substr(1) : c.program;
    WordSlot p;
    p.value = std::stod(n);
    p.column = column;
    p.set = true;
    call_program(Frame::m98, p, WordSlot{}, column);
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
