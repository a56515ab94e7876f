// Work offsets: G54..G59.3, G10 L2/L20, G92 family, G28/G30 (LinuxCNC convert_setup,
// convert_axis_offsets, convert_home). The machine never moves when an offset changes: the
// program coordinates of the current point change instead.
#include <cmath>

#include "interp.hpp"

namespace toolcomp::iso {

namespace {
constexpr char kAxisLetter[6] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
}

void Interp::change_offset(Vec6& offset, const Vec6& value) {
    pos_ -= value - offset;
    offset = value;
}

void Interp::set_coord_system(int n) {
    if (n == st_.coord_system) return;
    Vec6 old = g5x_[st_.coord_system - 1];
    st_.coord_system = n;
    pos_ -= g5x_[n - 1] - old;
}

void Interp::g10(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    if (!bw.has('L')) fail("g10_bad_l", "Line with G10 does not have L0, L1, L10, L11, L2, or L20", col);
    int l = static_cast<int>(std::lround(bw['L'].value));
    if (l == 0 || l == 1 || l == 10 || l == 11)
        fail("unsupported_g10", "G10 L" + std::to_string(l) + " (tool table edit) is not supported by toolcomp", col);
    if (l != 2 && l != 20) fail("g10_bad_l", "Line with G10 does not have L0, L1, L10, L11, L2, or L20", col);
    const std::string which = l == 2 ? "G10 L2" : "G10 L20";
    int p = bw.has('P') ? static_cast<int>(bw['P'].value) : -1;  // the control truncates P
    if (!bw.has('P') || p < 0 || p > 9) fail("g10_bad_p", "P value out of range (0-9) with " + which, col);
    if (l == 2 && (bw.has('I') || bw.has('J'))) fail("g10_ij", "I J words not allowed with G10 L2", col);
    if (bw.has('R')) {
        if (l == 20) fail("g10_l20_r", "R not allowed in G10 L20", bw['R'].column);
        if (bw['R'].value != 0)
            fail("unsupported_rotation", "Coordinate system rotation (G10 L2 R) is not supported by toolcomp",
                 bw['R'].column);
    }
    int n = p == 0 ? st_.coord_system : p;
    Vec6 value = g5x_[n - 1];
    for (int i = 0; i < 6; ++i) {
        if (!bw.has(kAxisLetter[i])) continue;
        double v = axis_value(bw, i);
        // L2: the offset itself (absolute even in G91). L20: the offset that gives the
        // current point the coordinate v in system n.
        value[i] = l == 2 ? v : pos_[i] + g5x_[st_.coord_system - 1][i] - v;
    }
    if (n == st_.coord_system)
        change_offset(g5x_[n - 1], value);
    else
        g5x_[n - 1] = value;
}

void Interp::g92(const BlockWords& bw, int code) {
    switch (code) {
        case 920: {
            Vec6 value = g92_;
            for (int i = 0; i < 6; ++i)
                if (bw.has(kAxisLetter[i])) value[i] = pos_[i] + g92_[i] - axis_value(bw, i);
            change_offset(g92_, value);
            g92_saved_ = g92_;
            break;
        }
        case 921: change_offset(g92_, Vec6::Zero()); g92_saved_.setZero(); break;
        case 922: change_offset(g92_, Vec6::Zero()); break;
        case 923: change_offset(g92_, g92_saved_); break;
        default: break;
    }
}

void Interp::home(const BlockWords& bw, int code) {
    Vec6& stored = (code == 280 || code == 281) ? g28_ : g30_;
    if (code == 281 || code == 301) {  // G28.1 / G30.1: remember where the machine is
        stored = pos_ + machine_offset();
        return;
    }
    // Through the intermediate point (axis words as usual) to the stored machine position;
    // only the named axes go home, all of them when none is named.
    Vec6 mid = find_end(bw);
    straight(MotionKind::rapid, mid, std::nan(""));
    Vec6 target = mid;
    Vec6 home_prog = stored - machine_offset();
    bool any = bw.has_axis();
    for (int i = 0; i < 6; ++i)
        if (!any || bw.has(kAxisLetter[i])) target[i] = home_prog[i];
    straight(MotionKind::rapid, target, std::nan(""));
}

}  // namespace toolcomp::iso
