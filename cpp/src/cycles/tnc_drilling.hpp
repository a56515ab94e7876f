#pragma once
// The Heidenhain TNC's drilling cycles as moves along the tool axis (and, for 208 BORE
// MILLING, a helix about the hole's centre). Dialect-free: the interpreter reads the cycle's
// definition into its Q parameters (or the old cycles' numbered lines) and puts the moves.
//
// Along the tool axis, for a depth Q201 < 0 (the TNC's normal case; a positive depth is
// refused by the interpreter): the surface S (Q203, shifted), the set-up clearance S + Q200,
// the bottom S + Q201, the 2nd set-up clearance S + Q204. A 2xx cycle starts with a rapid to
// S + Q200 and ends at S + max(Q200, Q204). Feeds are returned in mm/min, +inf for FMAX.
#include <cstdint>
#include <map>
#include <vector>

namespace toolcomp::cycles::tnc {

using QValues = std::map<int, double>;  // Q number -> value (a MAX / FMAX feed: +inf)

struct AxialMove {
    double to;    // tool-axis coordinate, program units
    double feed;  // mm/min; +inf: rapid
};

// Where the cycle runs and what it needs from the machine's state.
struct Setting {
    double surface = 0;    // S: Q203 (or the old cycles' start minus the set-up clearance), shifted
    double from = 0;       // where the tool stands along the axis (the old cycles start there)
    double feed_unit = 1;  // mm/min per program feed unit (2.54 in INCH programs)
    double unit = 1;       // mm per program unit
    double speed = 0;      // spindle speed, rev/min (tapping)
    std::size_t max_moves = SIZE_MAX;  // beyond: MoveLimit (turning_roughing.hpp)
};

// The Q parameters a cycle's definition must give (the ones the TNC writes that have no
// default), in the order the TNC writes them.
const std::vector<int>& required_q(int cycle);
bool is_drilling(int cycle);  // 200, 201, 203, 205, 207

// 200 DRILLING, 201 REAMING, 203 UNIVERSAL DRILLING, 205 UNIVERSAL PECKING, 207 RIGID
// TAPPING. Throws CycleError (cycle_bad_value) for values the TNC refuses.
std::vector<AxialMove> drilling(int cycle, const QValues& q, const Setting& s);

// The old cycles, defined by numbered lines (1.1 SET UP, 1.2 DEPTH, 1.3 PECKG, 1.4 DWELL,
// 1.5 F; 17.1 SET UP, 17.2 DEPTH, 17.3 PITCH), from the tool's position and back to it.
std::vector<AxialMove> pecking_1(const QValues& lines, const Setting& s);
std::vector<AxialMove> tapping_17(const QValues& lines, const Setting& s);

// 208 BORE MILLING: the helix about the centre, in the working plane (u, v) from the centre,
// and along the axis. The tool-centre path: radius Q335/2 - tool radius.
struct BoreMilling {
    double radius = 0;    // of the tool centre's helix; 0: a plunge straight down
    int dir = 1;          // +1 counter-clockwise (DR+, climb with M3), -1 clockwise
    double top = 0;       // the helix starts at the set-up clearance
    double bottom = 0;
    double turns = 0;     // helix revolutions from top to bottom (not a whole number in general)
    double feed = 0;      // mm/min
    double end = 0;       // the axis height the cycle ends at
};
BoreMilling bore_milling(const QValues& q, const Setting& s, double tool_radius);

}  // namespace toolcomp::cycles::tnc
