// The machine a Klartext program runs on (control/machine.hpp): where program zero (the
// preset) lies in machine coordinates, the machine datums of M91 and M92, and the tool
// change position. Positions in the machine file are millimetres; the interpreter's are
// program units.
#include <cmath>

#include "codes.hpp"
#include "interp.hpp"
#include "toolcomp/program/codes.hpp"

namespace toolcomp::heidenhain {

void Interp::set_machine(const Machine* m) {
    machine_ = m;
    if (!m) return;
    for (int i = 0; i < 3; ++i) work_origin_[i] = m->work_origin[static_cast<std::size_t>(i)] / unit_;
    pos_ = -work_origin_;  // at the machine's zero, no tool yet
}

void Interp::set_start(const Vec3& machine) { pos_ = machine / unit_ - work_origin_; }

// TNC: "coordinates in a positioning block with M91 are referenced to the machine datum
// [with M92 to the additional machine datum]; radius compensation remains the same, the
// tool length is not compensated" and M91/M92 act in their own block only. An axis given
// incrementally moves by its value as in any block. Without a machine, the machine's zero is
// program zero.
void Interp::machine_datum_end(Tokens t, Vec3& end) const {
    int datum = 0;
    for (std::size_t i = 1; i < t.size(); ++i)
        if (t[i].is("M") && t[i].has_value && (t[i].value == static_cast<double>(M91) || t[i].value == static_cast<double>(M92))) {
            if (datum) fail(code::bad_word, "M91 and M92 in one block", t[i].column);
            datum = static_cast<int>(t[i].value);
        }
    if (!datum) return;
    static constexpr std::string_view names[3] = {"X", "Y", "Z"};
    Vec3 at = frame().point(end);  // from the preset: machine datums are not transformed
    for (std::size_t i = 1; i < t.size(); ++i)
        for (int a = 0; a < 3; ++a)
            if (t[i].is(names[a]) && t[i].has_value) {
                const double from = datum == M92 && machine_ ? machine_->m92[static_cast<std::size_t>(a)] / unit_ : 0.0;
                at[a] = t[i].value + from - work_origin_[a] - tlo_[a];
            }
    end = frame().to_program(at);
}

// M140 MB n / MB MAX: before the rest of its block, the tool retracts along the tool axis, away
// from the workpiece, at rapid: by n, or to the end of the machine's travel (its software
// limit switch, from the machine file's [travel]: machine coordinates of the spindle).
void Interp::retract(Tokens t) {
    const Token* mb = find(t, "MB");
    bool m140 = false;
    const bool builder = machine_ && machine_->m_code(140);  // the machine's own M140 instead
    for (const Token& k : t) m140 = m140 || (k.is("M") && k.has_value && k.value == static_cast<double>(M140) && !builder);
    if (!mb && !m140) return;
    if (!mb) fail(code::bad_word, "M140 needs MB (a distance or MAX)", t[0].column);
    if (!m140) fail(code::bad_word, "MB without M140", mb->column);
    if (!axis_called_) fail(code::tool_call, "M140 before any TOOL CALL: no tool axis to retract along", mb->column);
    if (side_ != 0) fail(code::comp_plane, "M140 with RL/RR: not supported by toolcomp", mb->column);
    const int c = axes(plane_).c;
    Vec3 end = frame().point(pos_);  // from the preset: the retraction is the machine's
    if (mb->text == "MAX") {
        const double max = machine_ ? machine_->travel[static_cast<std::size_t>(c)].max : INFINITY;
        if (!std::isfinite(max))
            fail(code::travel_limit,
                 "M140 MB MAX retracts to the end of the machine's travel: give the machine (a machine file with the " +
                     std::string(1, "XYZ"[c]) + " travel in [travel])",
                 mb->column);
        end[c] = std::max(end[c], max / unit_ - work_origin_[c] - tlo_[c]);
    } else {
        if (!mb->has_value || mb->value < 0) fail(code::bad_word, "M140 MB needs a distance >= 0 or MAX", mb->column);
        end[c] += mb->value;
    }
    end = frame().to_program(end);
    if (end == pos_) return;
    Motion m = motion_to(MotionKind::rapid, end);
    put(m);
    pos_ = end;
}

// TOOL CALL of a tool on a machine with a tool change position: the axes it names go there
// at rapid first, with the tool in the spindle (the position is the spindle's).
void Interp::to_tool_change_position() {
    if (!machine_) return;
    Vec3 end = frame().point(pos_);  // from the preset
    for (int i = 0; i < 3; ++i)
        if (const auto& v = machine_->tool_change[static_cast<std::size_t>(i)])
            end[i] = *v / unit_ - work_origin_[i] - tlo_[i];
    end = frame().to_program(end);
    if (end == pos_) return;
    if (side_ != 0) fail(code::comp_tool_change, "TOOL CALL with radius compensation RL/RR active: cancel it with R0 first");
    settle_pending();
    if (approach_) throw ProgramError(code::approach_without_contour, "APPR needs a contour element after it", {approach_->line, 0, {}});
    Motion m = motion_to(MotionKind::rapid, end);
    m.radius.side = 0;
    put(m);
    pos_ = end;
}

}  // namespace toolcomp::heidenhain
