#pragma once
// Sinumerik tool data file ("$TC_DPn[t,d]=value" lines, the initialisation-file form of
// sinumerik_edge.hpp) as a tool table of the common model; suffix .ini, format "sinumerik".
//
// Reading: every (t, d) becomes edge d of tool t. A milling-like tool (type outside 400..599)
// gives length (x, y, z) = (L3, L2, L1), a turning/grinding tool (x, y, z) = (L1, L3, L2) and
// its cutting-edge position DP2 as the tip orientation: the vectors the control uses in G17
// and G18 respectively. Geometry (DP3..5) plus adapter (DP21..23) is the length, wear DP12..14
// plus the sum and setup offsets SCP/ECP12..14 the length wear; radius DP6, its wear DP15 +
// SCP15 + ECP15, corner radius DP7 and its wear DP16. Lengths are converted from the file
// unit to mm. Errors are those of parse_tc_dp.
//
// Writing keeps the file: lines of unchanged tools (and comments, blank lines, M17/M30) stay
// byte for byte; a changed tool's lines are replaced, where its first line was, by its edges
// in write_tc_dp's form, starting from the data read so that the values the common model
// does not carry (type, adapter split, SCP/ECP, DP8..11, DP17..25) are kept; a removed tool's
// lines disappear; a new tool is appended (type 120, or 500 with a tip orientation).
#include "toolcomp/tools/sinumerik_edge.hpp"
#include "toolcomp/tools/tool_table.hpp"

namespace toolcomp {

ToolTable read_sinumerik_table(std::string_view text, LengthUnit units);
std::string write_sinumerik_table(const ToolTable& table);

// The $TC_DP data of edge (t, d) as read, when `table` came from a tool data file and tool t
// is unchanged since; nullptr otherwise (the interpreter then uses edge_from_common).
const sinumerik::SinumerikEdge* sinumerik_source_edge(const ToolTable& table, int t, int d);

}  // namespace toolcomp
