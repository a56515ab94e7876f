// G40, G41/G42 [D], G41.1/G42.1 D [L]: the cutter radius compensation request, with
// LinuxCNC's checks (convert_cutter_compensation_on/off). The offset itself is computed by
// the radius compensation stage after the Motion stream.
#include <cmath>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

void Interp::radius_comp(const BlockWords& bw, int code) {
    const int col = bw.g_column[g_radius_comp];
    if (code == G40) {
        Vec3 dir = Vec3::Zero();
        if (profile_.radius.exit_direction_words) {
            const char* offs = "IJK";
            for (int i = 0; i < 3; ++i)
                if (bw.has(offs[i])) dir[i] = bw[offs[i]].value;
        }
        if (radius_.side != 0) out().control({ControlKind::radius_off, line_, dir, file_});
        if (radius_.side != 0 && radius_.radius > 0 && comp_moved_ && profile_.radius.exit_must_be_straight)
            arc_not_allowed_ = true;
        comp_moved_ = false;
        radius_ = {};
        return;
    }
    const bool dynamic = code == G41_1 || code == G42_1;
    const std::string name = code == G41 ? "G41" : code == G42 ? "G42" : code == G41_1 ? "G41.1" : "G42.1";
    if (st_.plane == Plane::yz && !profile_.radius.yz_plane) fail(code::comp_plane, profile_.radius.messages.plane, col);
    if (comp_on() && !profile_.radius.side_change) fail(code::comp_already_on, profile_.radius.messages.already_on, col);

    double radius = 0;
    int orientation = 0;
    if (dynamic) {
        if (!bw.has('D')) fail(code::comp_no_d, name + " with no D word", col);
        radius = bw['D'].value / 2;  // program units
        if (bw.has('L')) {
            if (st_.plane != Plane::zx) fail(code::comp_l_not_g18, name + " with L word, but plane is not G18", bw['L'].column);
            orientation = int_value(bw['L'].value);
        }
    } else if (profile_.t_offsets) {
        if (bw.has('D'))
            fail(code::comp_d_on_lathe, "D word is not used here: the T word's offset gives the nose radius", bw['D'].column);
        radius_.side = static_cast<std::int8_t>(code == G41 ? 1 : -1);
        radius_.checks = checks_;
        set_radius_from_offset();
        return;
    } else {
        // The D number: modal on Fanuc (D0 at the start, no radius), else the spindle's tool
        // when the block has none.
        int tool = profile_.modal_offset_numbers ? last_d_ : spindle_tool();
        if (bw.has('D')) {
            double d = bw['D'].value;
            if (!d_word_whole(d, profile_.integer_word_slack))
                fail(code::comp_d_not_integer, name + " requires D word to be a whole number", bw['D'].column);
            if (d < -0.5) fail(code::comp_negative_d, "Negative d word tool radius index used", bw['D'].column);
            tool = int_value(d);
            if (profile_.modal_offset_numbers) last_d_ = tool;
        }
        if (tool != 0 && tools_) {
            const Tool* t = tools_->find(tool);
            if (!t)
                fail(code::tool_not_found, "Requested tool " + std::to_string(tool) + " not found in the tool table",
                     bw.has('D') ? bw['D'].column : col);
            radius = t->edge().effective_radius() / scale();  // the table is in mm
            orientation = t->edge().orientation;
        }
        if (orientation != 0 && orientation != 9 && st_.plane != Plane::zx)
            fail(code::comp_lathe_tool_plane, name + " with lathe tool, but plane is not G18", col);
    }
    int side = (code == G41 || code == G41_1) ? 1 : -1;
    if (radius < 0) {  // a negative radius cuts on the other side
        side = -side;
        radius = -radius;
    }
    radius_ = {static_cast<std::int8_t>(side), radius, static_cast<std::int8_t>(orientation), checks_};
}

// Lathes with T offsets: the nose radius and tip of the active offset (geometry + wear).
// Fanuc: a D word without G41/G42 is the D number the next G41/G42 takes (G43 H1 D1 at a
// tool change). Under compensation it would change the offset from the next block on, which
// toolcomp does not model: refused.
void Interp::modal_d_number(const BlockWords& bw) {
    const WordSlot d = bw['D'];
    if (!d_word_whole(d.value, profile_.integer_word_slack))
        fail(code::comp_d_not_integer, "The D word must be a whole number", d.column);
    if (d.value < -0.5) fail(code::comp_negative_d, "Negative d word tool radius index used", d.column);
    if (comp_on())
        fail(code::unsupported_word, "A D word changing the offset while cutter compensation is on is not supported by toolcomp",
             d.column);
    last_d_ = int_value(d.value);
}

void Interp::set_radius_from_offset() {
    const OffsetValues v = offset_values();
    radius_.radius = v.radius;
    radius_.orientation = static_cast<std::int8_t>(v.orientation);
}

}  // namespace toolcomp::iso
