#pragma once
// The Sinumerik 840D's drilling cycles CYCLE81-CYCLE89 (and CYCLE840) as moves along the
// tool axis (CYCLE86: with its lift-off in the plane). Dialect-free: the interpreter evaluates
// the call's arguments (program units; an omitted one is 0), runs the moves from the hole's
// centre and restores nothing else (the cycles are SAVE subprograms: the caller's G functions
// and feed stay).
//
// The parameters every cycle starts with (RTP, RFP, SDIS, DP, DPR) and their rules, as the
// 840D's cycles apply them: SDIS and DPR lose their sign; a DPR that is not 0 wins over DP
// (DP = RFP - sgn(RTP - RFP) DPR, and RTP = RFP is then alarm 61101); RFP = DP makes no move;
// a retraction plane on the side of the depth is 61101. The safety plane is RFP + SDIS
// towards the retraction side. Dwells take no place in the path and are not returned.
#include <cstdint>
#include <string>
#include <vector>

namespace toolcomp::cycles::siemens {

enum class Feed : std::uint8_t {
    rapid,       // G0
    programmed,  // G1 at `feed`, in the caller's feed type (G94: mm/min, G95: mm/rev)
    per_minute,  // G1 at `feed` mm/min whatever the feed type (tapping: pitch x speed)
};

struct Step {
    double to;        // tool-axis coordinate, program units
    Feed how;
    double feed = 0;  // mm/min or mm/rev (see Feed); 0 with Feed::rapid
    double a = 0;     // offset from the hole's centre in the plane, program units (CYCLE86)
    double b = 0;
};

// What the cycle needs from the caller's state.
struct Setting {
    double feed = 0;  // the caller's F, mm/min or mm/rev
    double unit = 1;  // mm per program unit (25.4 in a G70/G700 program)
    double feed_unit = 1;  // mm per unit of a programmed feed (25.4 under G700 only)
    double from = 0;  // where the tool stands on the drilling axis, program units
    double speed = 0; // the spindle's speed, rev/min (CYCLE840)
    std::size_t max_moves = SIZE_MAX;  // beyond: MoveLimit (turning_roughing.hpp)
};

bool is_drilling_cycle(const std::string& name);  // CYCLE81 ... CYCLE89, CYCLE840
std::size_t parameter_count(const std::string& name);  // with the sl extensions (GMODE ...)

// The axis the cycle drills along: 0 the applicate of the plane, 1 its abscissa, 2 its
// ordinate (CYCLE83 / CYCLE84 / CYCLE840 _AXN; the others drill along the applicate).
int drilling_axis(const std::string& name, const std::vector<double>& args);

// The cycle's moves from the hole's centre. Throws CycleError for values the 840D refuses
// (its alarm number and text) and for what toolcomp does not model (unsupported_word).
std::vector<Step> drilling(const std::string& name, const std::vector<double>& args, const Setting& s);

}  // namespace toolcomp::cycles::siemens
