#pragma once
// A Path written out as text: a G-code program of its segments (path_gcode.cpp) and CSV rows
// (path_csv.cpp). Millions of segments a second: what users of large programs wait for after
// a run is these, not the run.
#include <cstddef>
#include <string>

#include "toolcomp/path.hpp"

namespace toolcomp {

// The program a control without cutter or nose radius compensation runs to move along a
// compensated path: G40 throughout, G0/G1 lines, G2/G3 arcs with incremental centres (I J K,
// the arc's plane selected by G17/G18/G19 before it), helices as arcs with the third axis,
// G21 G90 G94. Coordinates are the path's program coordinates plus its tool length offsets
// (`tool_length`), so the program needs no tool table. A word whose value, written with
// `digits` decimals, is that of the segment's start is left out (X always stays); F and the
// rotary axes are modal. `comments`: "(line N)" before the blocks of each source line.
struct GcodeStyle {
    enum class Target { linuxcnc, fanuc, grbl };  // the control the program is written for
    Target target = Target::linuxcnc;
    int digits = 6;  // 0..30
    bool comments = true;
    bool tool_length = true;
};
// linuxcnc writes G91.1 in the header and an arc of several turns as one block with P;
// fanuc frames the program in % and ends it with M30; fanuc and grbl write the turns of an
// arc as full circles before the rest (the third axis shared out by angle).
// Throws std::invalid_argument for a path that jumps (a start more than 1e-9 mm from the end
// before it: a work offset changed, or without `tool_length` a tool length offset) and for
// `digits` out of range.
std::string gcode_text(const Path& path, const GcodeStyle& style);

// CSV rows (RFC 4180 line ends "\r\n") of the segments [begin, end), numbered from
// `first_index` on, appended to `out`: index, kind, line, tool, start, end, center (empty for
// lines and rapids), feed (empty where it is NaN: rapids, G96 at the axis without D), side,
// generated, tool_offset, a b c. Numbers with 6 decimals (mm, mm/min, degrees).
void csv_rows(const Path& path, std::size_t begin, std::size_t end, std::size_t first_index, std::string& out);
// The header row of csv_rows().
const char* csv_header();

}  // namespace toolcomp
