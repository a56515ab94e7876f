#pragma once
// LinuxCNC tool table (.tbl): one tool per line,
//   T<n> P<pocket> X Y Z A B C U V W D<diameter> I<front angle> J<back angle> Q<orientation> ;comment
// words in any order and case, any subset; blank and ';' comment lines are kept.
// Lengths (X Y Z U V W D) are in the table's unit; D is the diameter (radius = D/2).
// Canonical spelling of a written tool (LinuxCNC's own writer order):
//   T1 P1 D+10.000000 X+0.500000 Z+25.000000 I+95.000000 J+155.000000 Q2 ;comment
// (T and P always, other words only when non-zero; numbers "%+f", more digits when six
// decimals would not give the value back.)
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

ToolTable read_linuxcnc_table(std::string_view text, LengthUnit units);
std::string write_linuxcnc_table(const ToolTable& table);

}  // namespace toolcomp
