// G10 L1: a program setting a tool's offsets in the tool table (LinuxCNC convert_setup_tool,
// L1 only). The run edits its own copy of the table, made at the first G10 L1; the caller's
// table is never changed, and the copy is the run's output (Result.tools). What a later T,
// G43 or G41/G42 reads is the copy; an offset or radius already in effect stays until it is
// taken again, as on LinuxCNC.
#include <cmath>

#include "interp.hpp"
#include "whole_numbers.hpp"
#include "toolcomp/program/codes.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp::iso {

void Interp::g10_tool(const BlockWords& bw) {
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
    const char* axes = "XYZ";
    for (int i = 0; i < 3; ++i)
        if (bw.has(axes[i])) e.length[i] = bw[axes[i]].value * mm;
    const char* rotary = "ABC";
    for (int i = 0; i < 3; ++i)
        if (bw.has(rotary[i])) e.rotary[static_cast<std::size_t>(i)] = bw[rotary[i]].value;
    if (bw.has('R')) e.radius = bw['R'].value * mm;
    if (bw.has('I')) e.front_angle = bw['I'].value;
    if (bw.has('J')) e.back_angle = bw['J'].value;
    if (q >= 0) e.orientation = q;
}

}  // namespace toolcomp::iso
