// G10 L1, L10, L11: a program setting a tool's offsets in the tool table (LinuxCNC
// convert_setup_tool). L1 writes the words; L10 the offsets that make the present point read
// the words in the active coordinate system once G43 takes them (G5x and G92 cancel out),
// L11 the same in G59.3 without G92 (a fixture). The run edits its own copy of the table,
// made at the first edit; the caller's table is never changed, and the copy is the run's
// output (Result.tools). What a later T, G43 or G41/G42 reads is the copy; an offset or
// radius already in effect stays until it is taken again, as on LinuxCNC.
#include <cmath>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

namespace {

// (x, y) turned by `degrees` about the origin, as LinuxCNC's rotate() turns it.
Vec2 rotated(const Vec2& p, double degrees) {
    const double t = degrees * kPi / 180, c = std::cos(t), s = std::sin(t);
    return {p[0] * c - p[1] * s, p[0] * s + p[1] * c};
}

}  // namespace

void Interp::g10_tool(const BlockWords& bw, int l) {
    const int col = bw.g_column[g_nonmodal];
    const int number = bw.has('P') ? int_value(bw['P'].value) : -1;
    if (!tools_ || !tools_->find(number))
        fail(code::tool_not_found, "Requested tool " + std::to_string(number) + " not found in the tool table", col);
    bool any = false;
    for (char c : {'X', 'Y', 'Z', 'A', 'B', 'C', 'R', 'Q', 'I', 'J'}) any = any || bw.has(c);
    if (!any) fail(code::g10_tool_words, "G10 L1 without offsets has no effect", col);
    int q = -1;
    if (bw.has('Q') && bw['Q'].value != -1.0) {
        if (!d_word_whole(bw['Q'].value, true)) fail(code::g10_tool_words, "Q number in G10 is not an integer", col);
        q = int_value(bw['Q'].value);
        if (q > 9) fail(code::g10_tool_words, "Invalid tool orientation", col);
    }
    if (!edited_tools_) {
        edited_tools_ = *tools_;
        tools_ = &*edited_tools_;
    }
    CuttingEdge& e = edited_tools_->find(number)->edge();
    const double mm = scale();  // the table is in mm
    auto word = [&](int i) { return axis_value(bw, i); };  // G7: X is a diameter
    const char* axes = "XYZABC";
    Vec6 to = Vec6::Zero();  // L1: the words themselves; L10 / L11: the point minus the words
    if (l != 1) {
        const int k = l == 11 ? 9 : st_.coord_system;
        const double phi = rotation_[static_cast<std::size_t>(k - 1)];
        Vec6 v = to_machine(pos_) - g5x_[static_cast<std::size_t>(k - 1)];
        v.head<2>() = rotated(v.head<2>(), -phi);
        if (g92_on_) {  // L11: a fixture's offset ignores G92 (LinuxCNC takes it off and adds it back)
            v -= g92_saved_;
            if (l == 11) v += g92_saved_;
        }
        // X and Y turn with the system's rotation; one of them alone keeps the old offset's
        // part along the other (rotated) axis.
        if (bw.has('X') || bw.has('Y')) {
            Vec2 t(bw.has('X') ? v[0] - word(0) : 0.0, bw.has('Y') ? v[1] - word(1) : 0.0);
            Vec2 keep = Vec2::Zero();
            if (!bw.has('X') || !bw.has('Y')) {
                keep = rotated(e.length.head<2>() / mm, -phi);
                keep[bw.has('X') ? 0 : 1] = 0;
                keep = rotated(keep, phi);
            }
            t = rotated(t, phi);
            for (int i = 0; i < 2; ++i) e.length[i] = (t[i] + keep[i]) * mm;
        }
        for (int i = 2; i < 6; ++i) to[i] = v[i] - (bw.has(axes[i]) ? word(i) : 0.0);
    } else {
        for (int i = 0; i < 6; ++i) to[i] = bw.has(axes[i]) ? word(i) : 0.0;
    }
    for (int i = l == 1 ? 0 : 2; i < 6; ++i) {
        if (!bw.has(axes[i])) continue;
        if (i < 3) e.length[i] = to[i] * mm;
        else e.rotary[static_cast<std::size_t>(i - 3)] = to[i];
    }
    if (bw.has('R')) e.radius = bw['R'].value * mm;
    if (bw.has('I')) e.front_angle = bw['I'].value;
    if (bw.has('J')) e.back_angle = bw['J'].value;
    if (q >= 0) e.orientation = q;
}

}  // namespace toolcomp::iso
