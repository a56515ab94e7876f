// Tool selection and change (T, M6, M61) and tool length compensation (G43, G43.1, G43.2,
// G44, G49), LinuxCNC convert_tool_select / convert_tool_change / convert_tool_length_offset.
#include <cmath>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

namespace {
constexpr char kAxisLetter[6] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
}

Vec6 Interp::tool_offset_of(int tool, int column) const {
    Vec6 v = Vec6::Zero();
    if (tool == 0) return v;
    const Tool* t = tools_ ? tools_->find(tool) : nullptr;
    if (!t) {
        if (!tools_) return v;  // no table at all: reported once by select_tool/length_comp
        fail(code::tool_not_found, "Requested tool " + std::to_string(tool) + " not found in the tool table", column);
    }
    const CuttingEdge& e = t->edge();
    Eigen::Vector3d len = e.effective_length() / scale();  // the table is in mm
    switch (profile_.length_axes) {
        case LengthAxes::all:
            v << len.x(), len.y(), len.z(), e.rotary[0], e.rotary[1], e.rotary[2];
            break;
        case LengthAxes::z_only:
            v[2] = len.z();
            break;
        case LengthAxes::plane_normal:
            v[axes(st_.plane).c] = len.z();
            break;
    }
    return v;
}

// Lathes with T offsets: geometry of one offset plus (wear_sign times) wear of another.
Interp::OffsetValues Interp::offset_values() const {
    OffsetValues v;
    if (!tools_) return v;
    const Tool* g = geometry_offset_ ? tools_->find(geometry_offset_) : nullptr;
    const Tool* w = wear_offset_ ? tools_->find(wear_offset_) : nullptr;
    const double ws = profile_.wear_sign, sc = scale();
    Eigen::Vector3d len = Eigen::Vector3d::Zero();
    if (g) {
        len += g->edge().length;
        v.radius += g->edge().radius;
        v.orientation = g->edge().orientation;
    }
    if (w) {
        len += ws * w->edge().length_wear;
        v.radius += ws * w->edge().radius_wear;
    }
    v.length << len.x() / sc, len.y() / sc, len.z() / sc, 0, 0, 0;
    v.radius /= sc;
    return v;
}

void Interp::select_tool(const BlockWords& bw) {
    int t = int_value(bw['T'].value);
    if (profile_.t_offsets) {
        // Lathe turret: the turret indexes and the offsets apply at once. The T word is
        // <tool><offset> with the profile's format (geometry and wear numbers).
        const int f = profile_.t_format;
        const int digits = f == 0 ? 2 : (f - 1) % 3 + 1;
        const int div = digits == 1 ? 10 : digits == 2 ? 100 : 1000;
        const int tool = t / div, wear = t % div, geometry = (f >= 4) ? tool : wear;
        for (int n : {geometry, wear})
            if (n != 0 && tools_ && !tools_->find(n))
                fail(code::offset_not_found, "Offset " + std::to_string(n) + " not found in the offset table",
                     bw['T'].column);
        if (radius_.side != 0 && tool != tool_ && profile_.kind != MachineKind::lathe)
            fail(code::comp_tool_change, "Cannot change tools with cutter radius compensation on", bw['T'].column);
        selected_ = tool_ = tool;
        geometry_offset_ = geometry;
        wear_offset_ = wear;
        change_offset(tlo_, offset_values().length);
        if (radius_.side != 0) set_radius_from_offset();
        return;
    }
    if (t != 0 && tools_ && !tools_->find(t))
        fail(code::tool_not_found, "Requested tool " + std::to_string(t) + " not found in the tool table", bw['T'].column);
    if (t != 0 && !tools_)
        diags_.push_back({code::no_tool_table, Severity::warning,
                          "No tool table given: tool " + std::to_string(t) + " has no offsets and no radius",
                          {line_, bw['T'].column}});
    selected_ = t;
}

void Interp::change_tool(const BlockWords& bw, int mcode) {
    if (mcode == M6) {  // M6: the prepared tool goes into the spindle; no length offset yet
        if (selected_ >= 0) tool_ = selected_;
        if (profile_.tool_change_stops_spindle)
            for (Spindle& s : spindles_) s.turning = 0;
        return;
    }
    // M61 Q: tell the control which tool is in the spindle, without a change.
    // LinuxCNC takes Q to the nearest integer (halves up); Fanuc as written.
    const double q = bw.has('Q') ? bw['Q'].value : -1;
    const bool lcnc = profile_.integer_word_slack;
    if (!bw.has('Q') || (lcnc ? std::floor(q + 0.5) < 0 : q < 0 || std::fabs(q - std::round(q)) > 1e-9))
        fail(code::m61_q, "Need non-negative Q-word to specify tool number with M61", bw.m_column[m_tool_change]);
    int t = lcnc ? int_value_truncated(std::floor(q + 0.5)) : int_value(q);
    if (t != 0 && tools_ && !tools_->find(t))
        fail(code::tool_not_found, "Requested tool " + std::to_string(t) + " not found in the tool table",
             bw['Q'].column);
    tool_ = t;
}

void Interp::length_comp(const BlockWords& bw, int code) {
    const int col = bw.g_column[g_length_comp];
    st_.length_mode = code;
    auto h_tool = [&]() {
        double h = bw['H'].value;
        if (!whole_word(h, profile_.integer_word_slack)) fail(code::non_integer_value, "Non integer value for integer", bw['H'].column);
        int t = int_value(h);
        if (t < 0) fail(code::tool_not_found, "Requested tool " + std::to_string(t) + " not found in the tool table", bw['H'].column);
        return t;
    };
    switch (code) {
        case G49:
            change_offset(tlo_, Vec6::Zero());
            break;
        case G43:
        case G44: {
            int t = 0;
            if (profile_.modal_offset_numbers) {  // Fanuc: the H number is modal, H0 no offset
                if (bw.has('H')) last_h_ = h_tool();
                t = last_h_;
            } else {
                t = bw.has('H') ? h_tool() : spindle_tool();
                if (t == 0 && bw.has('H')) t = spindle_tool();  // H0: the tool in the spindle
            }
            Vec6 v = tool_offset_of(t, bw.has('H') ? bw['H'].column : col);
            change_offset(tlo_, code == G44 ? Vec6(-v) : v);
            break;
        }
        case G43_1: {  // dynamic: the named components are replaced
            Vec6 v = tlo_;
            for (int i = 0; i < 6; ++i)
                if (bw.has(kAxisLetter[i])) v[i] = axis_value(bw, i);  // G7: an X word is a diameter
            change_offset(tlo_, v);
            break;
        }
        case G43_2: {  // additive
            bool axes = bw.has_axis();
            if (bw.has('H') && axes) fail(code::g43_2_both, "G43.2: Can not have both H and axis words", col);
            if (!bw.has('H') && !axes) fail(code::g43_2_none, "G43.2: No axes specified and H word missing", col);
            Vec6 add = Vec6::Zero();
            if (bw.has('H')) {
                add = tool_offset_of(h_tool(), bw['H'].column);
            } else {
                for (int i = 0; i < 6; ++i)
                    if (bw.has(kAxisLetter[i])) add[i] = axis_value(bw, i);
            }
            change_offset(tlo_, tlo_ + add);
            break;
        }
        default:
            break;
    }
}

}  // namespace toolcomp::iso
