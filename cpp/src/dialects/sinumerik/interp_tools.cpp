// Tools on a Sinumerik: T selects (and changes at once on a lathe), M6 changes the selected
// tool on a mill, the change activates D1 (MD20270 CUTTING_EDGE_DEFAULT = 1), D<n> selects
// an edge of the active tool, D0 deselects every offset. Edge data come from $TC_DP (the
// run's tool data and the program's own assignments) or else from the ToolTable (through
// edge_from_common). The length vector follows the plane (spec §3.2) and, with a toolholder
// (TCARR=m), its kinematics (spec §3.6).
#include <cctype>

#include "interp.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/program/int_value.hpp"
#include "toolcomp/program/text.hpp"
#include "toolcomp/tools/format_sinumerik.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::sinumerik {

void Interp::select_tool(const BlockData& b) {
    const Value& tv = b['T'];
    int t = 0;
    if (!b.tool_name.empty()) {
        const Tool* found = nullptr;
        if (tools_)
            for (const Tool& x : tools_->tools())
                if (to_upper_ascii(x.name) == to_upper_ascii(b.tool_name)) found = &x;
        if (!found) fail(code::alarm_17190, "17190 Illegal T number: no tool named \"" + b.tool_name + "\"", b.tool_name_column);
        t = found->number;
    } else {
        if (tv.v != std::floor(tv.v) || !(tv.v >= 0 && tv.v <= 32000)) fail(code::alarm_17190, "17190 Illegal T number", tv.column);
        t = int_value(tv.v);
        bool known = t == 0 || (tools_ && tools_->contains(t));
        auto it = edges_.lower_bound({t, 0});
        known |= it != edges_.end() && it->first.first == t;
        if (!known) fail(code::alarm_17190, "17190 Illegal T number: T" + std::to_string(t) + " is not in the tool data", tv.column);
    }
    selected_ = t;
    if (profile_.kind == MachineKind::lathe) change_tool();
}

// The axes the machine names for a tool change go there at rapid with the old tool (its
// position is the axes', the spindle's: the tool tip stays its offset below).
void Interp::to_tool_change_position() {
    const Machine* mc = opts_.machine;
    if (!mc) return;
    Vec3 end = pos_;
    for (int i = 0; i < 3; ++i)
        if (const auto& v = mc->tool_change[static_cast<std::size_t>(i)]) {
            const double axis = i == 0 && mc->kind == MachineKind::lathe ? *v / 2 : *v;
            end[i] = axis - tool_offset_[i] - work_origin_[i];
        }
    if (end == pos_) return;
    if (st_.side != 0) fail(code::alarm_10750, "10750 Tool change with active TRC");
    Motion m = motion_(MotionKind::rapid, end);
    m.radius = RadiusRequest{};
    pos_ = end;
    ++moves_;
    sink_.push(m);
}

void Interp::change_tool() {
    to_tool_change_position();
    tool_ = selected_;
    const int d_before = d_;
    d_ = 0;
    active_.reset();
    // The edge the new tool takes: MD20270 $MC_CUTTING_EDGE_DEFAULT (n, 0 none, -1 the D
    // number before the change: "T1 D1" then "M6" selects D1 of T1 either way).
    const int d = profile_.cutting_edge_default < 0 ? d_before : profile_.cutting_edge_default;
    if (tool_ != 0 && d > 0) {
        auto it = edges_.lower_bound({tool_, 0});
        const bool has_d = edges_.count({tool_, d}) || (tools_ && tools_->contains(tool_) && tools_->at(tool_).has_edge(d));
        if (has_d || (d == 1 && it != edges_.end() && it->first.first == tool_)) select_edge(d, 0);
    }
    update_tool_offset();
}

void Interp::select_edge(int d, int column) {
    if (d == 0) {
        d_ = 0;
        active_.reset();
        update_tool_offset();
        return;
    }
    if (tool_ == 0) {  // no tool in the spindle yet (T1 D1 before M6): no offset; the number is kept
        d_ = d;
        active_.reset();
        update_tool_offset();
        return;
    }
    if (auto it = edges_.find({tool_, d}); it != edges_.end()) {
        active_ = it->second;
    } else if (auto e = table_edge(tool_, d)) {
        active_ = *e;
    } else {
        fail(code::alarm_17180, "17180 Illegal D number: T" + std::to_string(tool_) + " has no cutting edge D" + std::to_string(d), column);
    }
    d_ = d;
    update_tool_offset();
}

std::optional<SinumerikEdge> Interp::table_edge(int t, int d) const {
    if (!tools_ || !tools_->contains(t) || !tools_->at(t).has_edge(d)) return std::nullopt;
    if (const SinumerikEdge* src = sinumerik_source_edge(*tools_, t, d)) return *src;  // a $TC_DP file
    return edge_from_common(tools_->at(t).edge(d));
}

const SinumerikEdge* Interp::edge() const { return active_ ? &*active_ : nullptr; }

double Interp::radius_now() const {
    return active_ ? active_->radius(opts_.lengths.wear_sign(), st_.offn) : 0.0;
}

void Interp::update_tool_offset() {
    Vec3 l = active_ ? tool_length_vector(*active_, st_.plane, opts_.lengths) : Vec3::Zero();
    zero_shift_ = Vec3::Zero();
    tool_axis_ = Vec3(0, 0, 1);
    if (tcarr_ != 0) {
        auto it = holders_.find(tcarr_);
        if (it == holders_.end()) fail(code::alarm_14153, "14153 Toolholder " + std::to_string(tcarr_) + " has no data ($TC_CARR)");
        try {
            check_kinematic_type(it->second.kind);
        } catch (const Error& e) {
            fail(e.code(), e.what());
        }
        const Toolholder& h = it->second;
        l = resulting_tool_length(h, l);
        zero_shift_ = table_zero_offset(h);
        // The tool's direction (tip towards spindle), Z at zero angles: the head's rotations.
        if (h.kind == 'T') tool_axis_ = rotate_about_axis(rotate_about_axis(Vec3(0, 0, 1), h.v2, h.angle2()), h.v1, h.angle1());
        if (h.kind == 'M') tool_axis_ = rotate_about_axis(Vec3(0, 0, 1), h.v1, h.angle1());
    }
    tool_offset_ = l;
}

}  // namespace toolcomp::sinumerik
