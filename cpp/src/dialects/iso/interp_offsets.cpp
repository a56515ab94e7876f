// Work offsets: G54..G59.3, G10 L2/L20, G92 family, G28/G30 (LinuxCNC convert_setup,
// convert_axis_offsets, convert_home). The machine never moves when an offset changes: the
// program coordinates of the current point change instead.
#include <cmath>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::iso {

namespace {
constexpr char kAxisLetter[6] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
}

Vec6 Interp::to_machine(const Vec6& prog) const {
    Vec6 p = prog + g92_;
    const double r = rotation_[st_.coord_system - 1] * kPi / 180;
    if (r != 0) {
        const double c = std::cos(r), s = std::sin(r), x = p[0], y = p[1];
        p[0] = c * x - s * y;
        p[1] = s * x + c * y;
    }
    return p + g5x_[st_.coord_system - 1] + tlo_;
}

Vec6 Interp::from_machine(const Vec6& machine) const {
    Vec6 p = machine - g5x_[st_.coord_system - 1] - tlo_;
    const double r = rotation_[st_.coord_system - 1] * kPi / 180;
    if (r != 0) {
        const double c = std::cos(r), s = std::sin(r), x = p[0], y = p[1];
        p[0] = c * x + s * y;
        p[1] = -s * x + c * y;
    }
    return p - g92_;
}

void Interp::set_coord_system(int n) { change_offset(st_.coord_system, n); }

void Interp::g10(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    if (!bw.has('L')) fail(code::g10_bad_l, "Line with G10 does not have L0, L1, L10, L11, L2, or L20", col);
    int l = int_value(bw['L'].value);
    if ((l == 1 || l == 10 || l == 11) && profile_.g10_tool_table) return g10_tool(bw, l);
    if (l == 0 && profile_.g10_tool_table) {  // reload the tool table: the run's table is the file's
        if (tool_ != 0)
            fail(code::g10_tool_words, "G10 L0 not allowed with loaded tool <" + std::to_string(tool_) + ">", col);
        return;
    }
    if (l == 0 || l == 1 || l == 10 || l == 11)
        fail(code::unsupported_g10, "G10 L" + std::to_string(l) + " (tool table edit) is not supported by toolcomp", col);
    if (l != 2 && l != 20) fail(code::g10_bad_l, "Line with G10 does not have L0, L1, L10, L11, L2, or L20", col);
    const std::string which = l == 2 ? "G10 L2" : "G10 L20";
    // LinuxCNC refuses a P more than 0.0001 above the integer it rounds to (below is let be)
    // or one that rounds out of 0-9, then takes the system (int)(P + 0.0001): P1.9999 is G55,
    // P1.5 G54.
    int p = -1;
    if (bw.has('P')) {
        const double pv = bw['P'].value;
        if (profile_.integer_word_slack) {
            const double rounded = std::round(pv);
            if ((pv + 0.0001) - rounded > 0.0002) fail(code::g10_p_not_integer, "P value not an integer with G10", col);
            p = rounded < 0 || rounded > 9 ? -1 : int_value_truncated(pv + 0.0001);
        } else {
            p = int_value_truncated(pv);
        }
    }
    if (p < 0 || p > 9) fail(code::g10_bad_p, "P value out of range (0-9) with " + which, col);
    if (profile_.fanuc_g10) {
        // Fanuc's G10 L20 sets the additional systems G54.1 P1-P48 and L2 P0 the external
        // offset that shifts every system: neither is LinuxCNC's, neither is run here.
        if (l == 20)
            fail(code::unsupported_g10, "G10 L20 (the additional work coordinate systems G54.1) is not supported by toolcomp",
                 col);
        if (p == 0) fail(code::unsupported_g10, "G10 L2 P0 (the external work offset) is not supported by toolcomp", col);
        if (p > 6) fail(code::g10_bad_p, "P value out of range (1-6) with G10 L2", col);
        if (bw.has('R')) fail(code::unused_word, "R word with no code that uses it (G10 L2 sets no rotation here)",
                              bw['R'].column);
    }
    if (l == 2 && (bw.has('I') || bw.has('J'))) fail(code::g10_ij, "I J words not allowed with G10 L2", col);
    if (l == 20 && bw.has('R')) fail(code::g10_l20_r, "R not allowed in G10 L20", bw['R'].column);
    int n = p == 0 ? st_.coord_system : p;
    Vec6 value = g5x_[n - 1];
    double rotation = rotation_[n - 1];
    if (l == 2) {  // the offset itself (LinuxCNC: absolute even in G91; Fanuc adds it in G91)
        const bool add = st_.incremental && profile_.fanuc_g10;
        for (int i = 0; i < 6; ++i)
            if (bw.has(kAxisLetter[i])) value[i] = (add ? value[i] : 0) + axis_value(bw, i);
        if (bw.has('R')) rotation = bw['R'].value;
    } else {
        // L20: the origin that gives the current point the programmed coordinates in system
        // n (the machine point is m = rotate_n(t + G92) + origin_n + TLO). An axis not given
        // keeps the current point's coordinate in system n; in a rotated system X and Y
        // both move the origin's X and Y (LinuxCNC).
        const Vec6 m = to_machine(pos_) - tlo_;
        const double r = rotation * kPi / 180, c = std::cos(r), sn = std::sin(r);
        Vec6 t = m - value;  // the current point in system n
        const double tx = t[0], ty = t[1];
        t[0] = c * tx + sn * ty;
        t[1] = -sn * tx + c * ty;
        t -= g92_;
        for (int i = 0; i < 6; ++i)
            if (bw.has(kAxisLetter[i])) t[i] = axis_value(bw, i);
        Vec6 rt = t + g92_;
        const double x = rt[0], y = rt[1];
        rt[0] = c * x - sn * y;
        rt[1] = sn * x + c * y;
        const Vec6 full = m - rt;
        const bool plane_given = bw.has('X') || bw.has('Y');
        for (int i = 0; i < 6; ++i)
            if (bw.has(kAxisLetter[i]) || (i < 2 && r != 0 && plane_given)) value[i] = full[i];
    }
    if (n == st_.coord_system) {
        Vec6 m = to_machine(pos_);
        g5x_[n - 1] = value;
        rotation_[n - 1] = rotation;
        pos_ = from_machine(m);
    } else {
        g5x_[n - 1] = value;
        rotation_[n - 1] = rotation;
    }
}

void Interp::g92(const BlockWords& bw, int code) {
    switch (code) {
        case G92: {
            Vec6 value = g92_;
            for (int i = 0; i < 6; ++i)
                if (bw.has(kAxisLetter[i])) value[i] = pos_[i] + g92_[i] - axis_value(bw, i);
            change_offset(g92_, value);
            g92_saved_ = g92_;
            g92_on_ = true;
            break;
        }
        case G52: {  // G52: a local offset of the work coordinate system, G92's storage (LinuxCNC)
            Vec6 value = g92_;
            for (int i = 0; i < 6; ++i)
                if (bw.has(kAxisLetter[i])) value[i] = axis_value(bw, i);
            change_offset(g92_, value);
            g92_saved_ = g92_;
            g92_on_ = true;
            break;
        }
        case G92_1: change_offset(g92_, Vec6::Zero()); g92_saved_.setZero(); g92_on_ = false; break;
        case G92_2: change_offset(g92_, Vec6::Zero()); g92_on_ = false; break;
        case G92_3: change_offset(g92_, g92_saved_); g92_on_ = true; break;
        default: break;
    }
}

// G50 in G-code system A (Fanuc T series, Haas lathe): X/Z set the coordinate system as
// G92 does in the other systems; S is the highest spindle speed of constant surface speed
// (G96), kept until the next G50 S. U and W would shift it: refused.
void Interp::g50(const BlockWords& bw) {
    const int col = bw.g_column[g_nonmodal];
    if (bw.has('U') || bw.has('W'))
        fail(code::unsupported_word, "G50 with U or W (a shift of the coordinate system) is not supported by toolcomp",
             bw[bw.has('U') ? 'U' : 'W'].column);
    if (!bw.has('S') && !bw.has_axis()) fail(code::g92_no_axes, "G50 needs X/Z (the coordinate system) or S (the spindle clamp)", col);
    if (bw.has('S')) {
        if (bw['S'].value < 0) fail(code::bad_word, "G50 S: the spindle speed clamp cannot be negative", bw['S'].column);
        spindle_clamp_ = bw['S'].value;
    }
    if (bw.has_axis()) g92(bw, 920);
}

void Interp::home(const BlockWords& bw, int code) {
    Vec6& stored = (code == G28 || code == G28_1) ? g28_ : g30_;
    if (code == G28_1 || code == G30_1) {  // G28.1 / G30.1: remember where the machine is
        if (comp_on())
            fail(code::comp_set_home, "Cannot set reference point with cutter compensation in effect",
                 bw.g_column[g_nonmodal]);
        stored = to_machine(pos_);
        return;
    }
    // Through the intermediate point (axis words as usual) to the stored machine position;
    // only the named axes go home, all of them when none is named. On lathes U and W name X
    // and Z (G28 U0 W0: home from where the tool is).
    Vec6 mid = find_end(bw);
    straight(MotionKind::rapid, mid, std::nan(""));
    Vec6 target = mid;
    Vec6 home_prog = from_machine(stored);
    bool any = bw.has_axis();
    const bool uw = profile_.incremental_uw;
    for (int i = 0; i < 6; ++i)
        if (!any || bw.has(kAxisLetter[i]) || (uw && ((i == 0 && bw.has('U')) || (i == 2 && bw.has('W')))))
            target[i] = home_prog[i];
    straight(MotionKind::rapid, target, std::nan(""));
}

}  // namespace toolcomp::iso
